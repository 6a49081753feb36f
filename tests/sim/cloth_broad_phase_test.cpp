// The acceleration pieces of the cloth solver against brute force: the BVH's
// pair traversal and nearest search, the elongation limiter's sparse
// Gauss-Seidel against a full sweep, self-collision candidates that do not
// depend on whether the trees were rebuilt or refitted, and that are those
// of a brute-force search.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "cloth_test_scenes.h"
#include "sim/cloth/cloth_topology.h"
#include "sim/cloth/collision/aabb_tree.h"
#include "sim/cloth/collision/self_collision.h"
#include "sim/cloth/constraints/stretch_limit.h"
#include "sim/cloth/forces/cloth_forces.h"

namespace mq::cloth {
namespace {

std::vector<Box> randomBoxes(size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> position(0.0f, 1.0f), size(0.0f, 0.08f);
  std::vector<Box> boxes(count);
  for (Box& b : boxes) {
    b.min = {position(rng), position(rng), position(rng)};
    b.max = b.min + glm::vec3(size(rng), size(rng), size(rng));
  }
  return boxes;
}

using PairSet = std::set<std::pair<uint32_t, uint32_t>>;

// Every overlapping pair (i < j), by testing them all.
PairSet overlappingPairs(const std::vector<Box>& boxes) {
  PairSet pairs;
  for (uint32_t i = 0; i < boxes.size(); ++i)
    for (uint32_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) pairs.insert({i, j});
  return pairs;
}

// The pairs the tree's self-traversal jobs report, and how many reports.
std::pair<PairSet, size_t> pairsFromJobs(const AabbTree& tree, const std::vector<AabbTree::PairJob>& jobs) {
  PairSet found;
  size_t visits = 0;
  for (const AabbTree::PairJob& job : jobs)
    tree.runJob(job, [&](uint32_t i, uint32_t j) {
      ++visits;
      found.insert(std::minmax(i, j));
    });
  return {found, visits};
}

TEST(AabbTree, PairJobsFindEveryOverlappingPairOnce) {
  const std::vector<Box> boxes = randomBoxes(1500, 7);
  AabbTree tree;
  tree.build(boxes);
  const PairSet expected = overlappingPairs(boxes);
  ASSERT_GT(expected.size(), 100u);
  const std::vector<AabbTree::PairJob> jobs = tree.pairJobs(64);
  EXPECT_GE(jobs.size(), 64u);
  const auto [found, visits] = pairsFromJobs(tree, jobs);
  EXPECT_EQ(visits, expected.size());  // no pair twice
  EXPECT_EQ(found, expected);
}

TEST(AabbTree, PairJobsAfterARefitFindTheNewBoxesPairs) {
  // The leaves' boxes are kept as columns too: a refit must renew them.
  const std::vector<Box> built = randomBoxes(1500, 7), moved = randomBoxes(1500, 8);
  AabbTree tree;
  tree.build(built);
  tree.refit(moved);
  const PairSet expected = overlappingPairs(moved);
  ASSERT_GT(expected.size(), 100u);
  const auto [found, visits] = pairsFromJobs(tree, tree.pairJobs(64));
  EXPECT_EQ(visits, expected.size());
  EXPECT_EQ(found, expected);
}

TEST(AabbTree, SkippedNodesLeaveOutExactlyTheirOwnPairs) {
  const std::vector<Box> boxes = randomBoxes(1500, 5);
  AabbTree tree;
  tree.build(boxes);
  // Skip the pairs within the root's left child, and queries into its right child.
  const AabbTree::NodeInfo root = tree.nodeInfo(0);
  ASSERT_GE(root.left, 0);
  const AabbTree::NodeInfo left = tree.nodeInfo(size_t(root.left)), right = tree.nodeInfo(size_t(root.right));
  std::vector<int> side(boxes.size(), 0);  // 1: under the left child, 2: under the right
  for (uint32_t k = left.first; k < left.first + left.count; ++k) side[tree.primitive(k)] = 1;
  for (uint32_t k = right.first; k < right.first + right.count; ++k) side[tree.primitive(k)] = 2;
  std::set<std::pair<uint32_t, uint32_t>> expected, found;
  for (uint32_t i = 0; i < boxes.size(); ++i)
    for (uint32_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j]) && !(side[i] == 1 && side[j] == 1)) expected.insert({i, j});
  auto skipLeft = [&](int32_t node) { return node == root.left; };
  for (const AabbTree::PairJob& job : tree.pairJobs(16, skipLeft))
    tree.runJob(
        job, [&](uint32_t i, uint32_t j) { found.insert(std::minmax(i, j)); }, skipLeft);
  EXPECT_EQ(found, expected);
  const Box probe{glm::vec3(0.3f), glm::vec3(0.7f)};
  std::set<uint32_t> expectedHits, hits;
  for (uint32_t i = 0; i < boxes.size(); ++i)
    if (boxes[i].overlaps(probe) && side[i] != 2) expectedHits.insert(i);
  tree.query(
      probe, [&](uint32_t i) { hits.insert(i); }, [&](int32_t node) { return node == root.right; });
  ASSERT_FALSE(expectedHits.empty());
  EXPECT_EQ(hits, expectedHits);
}

TEST(AabbTree, NearestSearchMatchesBruteForce) {
  const std::vector<Box> boxes = randomBoxes(2000, 11);
  AabbTree tree;
  tree.build(boxes);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> position(-0.1f, 1.1f);
  auto centre = [&](uint32_t i) { return 0.5f * (boxes[i].min + boxes[i].max); };
  for (int q = 0; q < 200; ++q) {
    const glm::vec3 p(position(rng), position(rng), position(rng));
    float bruteBest = 0.1f;
    int64_t bruteIndex = -1;
    for (uint32_t i = 0; i < boxes.size(); ++i) {
      const float d = glm::length(centre(i) - p);
      if (d < bruteBest) bruteBest = d, bruteIndex = i;
    }
    float best = 0.1f;
    int64_t index = -1;
    tree.nearest(p, best, [&](uint32_t i) {
      const float d = glm::length(centre(i) - p);  // a box's centre lies in it: its box is nearer
      if (d < best) best = d, index = i;
    });
    EXPECT_EQ(index, bruteIndex);
    EXPECT_EQ(best, bruteBest);
  }
}

// Symmetric Gauss-Seidel over every spring in every pass, as the limiter
// did before it tracked which springs need a check: a pass's worst spring
// (before its correction) decides whether the cloth is measured again.
int fullSweep(ClothState& s, const std::vector<Spring>& springs, size_t count, float maxStretch, int maxPasses) {
  const float target = maxStretch * (1.0f - 1e-3f);
  int passes = 0;
  float worst = maxStretchOf(s.x, springs, count);
  while (passes < maxPasses && worst > maxStretch) {
    float passWorst = 0.0f;
    for (size_t n = 0; n < count; ++n) {
      const Spring& sp = springs[passes % 2 == 0 ? n : count - 1 - n];
      const glm::vec3 d = s.x[sp.a] - s.x[sp.b];
      const float l = glm::length(d), limit = target * sp.rest, wa = s.invMass[sp.a], wb = s.invMass[sp.b];
      if (l <= limit || wa + wb == 0.0f) continue;
      passWorst = std::max(passWorst, l / sp.rest);
      const glm::vec3 correction = ((l - limit) / (l * (wa + wb))) * d;
      s.x[sp.a] -= wa * correction;
      s.x[sp.b] += wb * correction;
    }
    ++passes;
    worst = passWorst <= maxStretch ? maxStretchOf(s.x, springs, count) : passWorst;
  }
  return passes;
}

TEST(StretchLimiter, SparsePassesGiveTheFullSweepsResult) {
  // A sheet with a patch pulled 5 cm out of it and its centre heavy, as
  // cloth pinched by a body part.
  const ClothMesh mesh = test::horizontalSheetMesh(40, 0.6f, glm::vec3(0.0f));
  const ClothTopology topology = buildClothTopology(mesh);
  const Fabric fabric = fabricPreset("cotton");
  ClothSettings settings;
  ClothSimulator sim(mesh, topology, fabric, settings);
  ClothState pulled = sim.state();
  const glm::vec3 centre = pulled.x[20 * 40 + 20];
  for (size_t i = 0; i < pulled.size(); ++i) {
    const float d = glm::length(pulled.x[i] - centre);
    if (d < 0.06f) pulled.x[i].y += 0.05f * (1.0f - d / 0.06f);
    if (d < 0.02f) pulled.invMass[i] *= 0.05f;
  }
  const auto& springs = sim.forces().springs().springs();
  const size_t count = sim.forces().structuralCount();
  ASSERT_GT(maxStretchOf(pulled.x, springs, count), 1.3f);

  ClothState reference = pulled;
  const int referencePasses = fullSweep(reference, springs, count, 1.1f, 2000);
  StretchLimiter limiter(springs, count, pulled.size());
  ClothState sparse = pulled;
  const StretchLimitResult r = limiter.limitByPositions(sparse, 1.1f, 2000, 1.0f / 30.0f);
  EXPECT_LE(r.maxStretchAfter, 1.1f);
  EXPECT_NEAR(r.passes, referencePasses, 2);
  float worst = 0.0f;
  for (size_t i = 0; i < pulled.size(); ++i) worst = std::max(worst, glm::length(sparse.x[i] - reference.x[i]));
  EXPECT_LT(worst, 5e-5f) << "the sparse passes moved the cloth differently from the full sweep";
  // The limiter is reused: a second call on the same input gives the same state.
  ClothState again = pulled;
  limiter.limitByPositions(again, 1.1f, 2000, 1.0f / 30.0f);
  EXPECT_EQ(again.x, sparse.x);
}

TEST(StretchLimiter, AReusedLimiterGivesAFreshOnesResults) {
  // The limiter keeps each spring's stretch between calls and measures again
  // only at vertices that moved: as the contact rounds use it (a few vertices
  // moved between calls, heavy vertices changing, the budget running out), or
  // with the whole cloth moved, it must give exactly what a fresh one gives.
  const ClothMesh mesh = test::horizontalSheetMesh(40, 0.6f, glm::vec3(0.0f));
  const ClothTopology topology = buildClothTopology(mesh);
  ClothSettings settings;
  ClothSimulator sim(mesh, topology, fabricPreset("cotton"), settings);
  const auto& springs = sim.forces().springs().springs();
  const size_t count = sim.forces().structuralCount();
  ClothState reused = sim.state();
  const glm::vec3 centre = reused.x[20 * 40 + 20];
  for (size_t i = 0; i < reused.size(); ++i) {
    const float d = glm::length(reused.x[i] - centre);
    if (d < 0.06f) reused.x[i].y += 0.05f * (1.0f - d / 0.06f);
  }
  ClothState fresh = reused;
  StretchLimiter limiter(springs, count, reused.size());
  for (int call = 0; call < 12; ++call) {
    for (ClothState* s : {&reused, &fresh}) {
      if (call % 4 == 1)  // a few vertices put back out, some heavy
        for (size_t i = 20 * 40 + 15; i < 20 * 40 + 25; ++i) s->x[i].y += 0.01f, s->invMass[i] *= 0.5f;
      if (call == 6)  // the whole cloth moved
        for (size_t i = 0; i < s->size(); ++i) s->x[i] += glm::vec3(0.001f * float(i % 7), 0.002f * float(i % 5), 0.0f);
    }
    const int budget = call < 8 ? 3 : 2000;  // the early calls end with springs still over the limit
    const StretchLimitResult a = limiter.limitByPositions(reused, 1.1f, budget, 1.0f / 30.0f);
    const StretchLimitResult b = limitStretchByPositions(fresh, springs, count, 1.1f, budget, 1.0f / 30.0f);
    EXPECT_EQ(a.passes, b.passes) << "call " << call;
    EXPECT_EQ(a.maxStretchBefore, b.maxStretchBefore) << "call " << call;
    EXPECT_EQ(a.maxStretchAfter, b.maxStretchAfter) << "call " << call;
    EXPECT_EQ(a.maxStretchAfter, maxStretchOf(reused.x, springs, count)) << "call " << call;
    EXPECT_EQ(reused.x, fresh.x) << "call " << call;
    EXPECT_EQ(reused.v, fresh.v) << "call " << call;
  }
  EXPECT_LE(maxStretchOf(reused.x, springs, count), 1.1f);
}

TEST(SelfCollision, CandidatesDoNotDependOnTreeRefits) {
  // A sheet folded over itself, moved a little each step: one resolver
  // refits its trees between steps, a fresh one builds them; both must push
  // the same pairs apart the same way.
  ClothMesh mesh = test::horizontalSheetMesh(30, 0.4f, glm::vec3(0.0f));
  for (size_t i = 0; i < mesh.vertexCount(); ++i) {
    float& x = mesh.positions[3 * i];
    float& y = mesh.positions[3 * i + 1];
    if (x > 0.0f) y = 0.003f, x = -x;  // the right half folded onto the left, 3 mm above
  }
  const Fabric fabric = fabricPreset("cotton");
  ClothSettings settings;
  ClothSimulator sim(mesh, fabric, settings);
  SelfCollision reused(mesh.triangles, mesh.vertexCount());
  for (int step = 0; step < 20; ++step) {
    ClothState start = sim.state();
    for (size_t i = 0; i < start.size(); ++i)
      start.x[i] += glm::vec3(0.0f, 0.0005f * std::sin(0.3f * float(step + i)), 0.0f);
    ClothState moved = start;
    for (size_t i = 0; i < moved.size(); ++i)
      moved.x[i] += glm::vec3(0.001f * std::cos(0.7f * float(i + step)), -0.002f * float(i % 3), 0.0f);
    ClothState a = moved, b = moved;
    SelfCollision fresh(mesh.triangles, mesh.vertexCount());
    const int contactsA = reused.resolve(a, start.x, settings.selfThickness, 20);
    const int contactsB = fresh.resolve(b, start.x, settings.selfThickness, 20);
    EXPECT_GT(contactsA, 0);
    EXPECT_EQ(contactsA, contactsB) << "step " << step;
    EXPECT_EQ(a.x, b.x) << "step " << step;
    EXPECT_EQ(a.v, b.v) << "step " << step;
  }
}

TEST(SelfCollision, AFlatSheetHasNoCandidatesEvenWithAThicknessAboveItsEdges) {
  // 1.4 cm between vertices, 2 cm thickness: without the flat patch test its
  // neighbours beyond the one-ring would be candidates, pushed out of its plane.
  const ClothMesh mesh = test::horizontalSheetMesh(30, 0.4f, glm::vec3(0.0f));
  ClothSimulator sim(mesh, fabricPreset("cotton"), ClothSettings());
  const ClothState start = sim.state();
  ClothState moved = start;
  for (size_t i = 0; i < moved.size(); ++i)
    moved.x[i] += glm::vec3(0.002f * std::sin(float(i)), 0.0f, 0.002f * std::cos(0.7f * float(i)));
  ClothState resolved = moved;
  SelfCollision selfCollision(mesh.triangles, mesh.vertexCount());
  EXPECT_EQ(selfCollision.resolve(resolved, start.x, 0.02f, 20), 0);
  EXPECT_EQ(selfCollision.vertexTriangleCandidates(), 0u);
  EXPECT_EQ(selfCollision.edgeEdgeCandidates(), 0u);
  size_t pushed = 0;
  for (size_t i = 0; i < moved.size(); ++i) pushed += resolved.x[i] != moved.x[i];
  EXPECT_EQ(pushed, 0u);
}

TEST(SelfCollision, AConnectedFoldIsNotTakenForAFlatPatch) {
  // One sheet folded over itself at x = 0, its upper layer 3 mm above the
  // lower one (and facing down), then moved 6 mm down, through it: the layers
  // are one connected patch whose normals are opposite, so its pairs are
  // found and the upper layer ends above the lower one (away from the crease
  // column, whose vertical triangles the layers' vertices straddle).
  const int n = 30;
  ClothMesh mesh = test::horizontalSheetMesh(n, 0.4f, glm::vec3(0.0f));
  std::vector<bool> upper(mesh.vertexCount(), false);
  for (size_t i = 0; i < mesh.vertexCount(); ++i) {
    float& x = mesh.positions[3 * i];
    if (x > 0.0f) mesh.positions[3 * i + 1] = 0.003f, x = -x, upper[i] = true;
  }
  ClothSimulator sim(mesh, fabricPreset("cotton"), ClothSettings());
  const ClothState start = sim.state();
  ClothState s = start;
  for (size_t i = 0; i < s.size(); ++i)
    if (upper[i]) s.x[i].y -= 0.006f;
  SelfCollision selfCollision(mesh.triangles, mesh.vertexCount());
  EXPECT_GT(selfCollision.resolve(s, start.x, 0.004f, 20), 0);
  EXPECT_GT(selfCollision.vertexTriangleCandidates(), 0u);
  int checked = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    if (!upper[i] || start.x[i].x > -0.01f) continue;
    for (size_t j = 0; j < s.size(); ++j)  // the lower vertex under it
      if (!upper[j] && std::abs(start.x[j].x - start.x[i].x) < 1e-6f && std::abs(start.x[j].z - start.x[i].z) < 1e-6f) {
        EXPECT_GT(s.x[i].y, s.x[j].y) << "upper vertex " << i << " went through the lower layer";
        ++checked;
      }
  }
  EXPECT_EQ(checked, n * (n / 2 - 1));
}

TEST(SelfCollision, MotionBoundsLeaveOutNoCandidate) {
  // A crumpled sheet (heights alternating by 3 mm between neighbours) folded
  // over itself, its upper layer 5 mm above the lower one, turned rigidly in
  // the step, about an axis far away (it moves 11 cm as a whole, its moves
  // differ by up to 4 cm) and about the middle of its fold (up to 4 cm), with
  // a little noise: the searches that leave out the nodes out of reach by
  // their start and move boxes find the same pairs and push them the same way
  // as those that visit all the pairs whose boxes overlap.
  ClothMesh mesh = test::horizontalSheetMesh(20, 0.2f, glm::vec3(0.0f));
  const float spacing = 0.2f / 19.0f;
  for (size_t i = 0; i < mesh.vertexCount(); ++i) {
    float& x = mesh.positions[3 * i];
    const int column = int(std::lround((x + 0.1f) / spacing));
    const int row = int(std::lround((mesh.positions[3 * i + 2] + 0.1f) / spacing));
    mesh.positions[3 * i + 1] = (column + row) % 2 ? 0.0015f : -0.0015f;
    if (x > 0.0f) mesh.positions[3 * i + 1] += 0.005f, x = -x;
  }
  const ClothState start = ClothSimulator(mesh, fabricPreset("cotton"), ClothSettings()).state();
  for (const glm::vec3 axisPoint : {glm::vec3(0.5f, 0.0f, 0.0f), glm::vec3(0.0f)}) {
    const float angle = axisPoint.x > 0.0f ? 0.2f : 0.3f;
    ClothState moved = start;
    for (size_t i = 0; i < moved.size(); ++i) {
      const glm::vec3 r = start.x[i] - axisPoint;
      const glm::vec3 turned(std::cos(angle) * r.x + std::sin(angle) * r.z, r.y,
                             -std::sin(angle) * r.x + std::cos(angle) * r.z);
      moved.x[i] = axisPoint + turned +
                   0.001f * glm::vec3(std::sin(float(i)), std::cos(1.3f * float(i)), std::sin(0.7f * float(i)));
    }
    for (const float thickness : {0.004f, 0.008f}) {
      SelfCollision bounded(mesh.triangles, mesh.vertexCount()), unbounded(mesh.triangles, mesh.vertexCount());
      unbounded.setMotionBounds(false);
      ClothState a = moved, b = moved;
      const int contacts = bounded.resolve(a, start.x, thickness, 20);
      EXPECT_EQ(contacts, unbounded.resolve(b, start.x, thickness, 20));
      const std::string where = "angle " + std::to_string(angle) + ", thickness " + std::to_string(thickness);
      EXPECT_GT(bounded.vertexTriangleCandidates(), 0u) << where;
      EXPECT_GT(bounded.edgeEdgeCandidates(), 0u) << where;
      EXPECT_EQ(bounded.vertexTriangleCandidates(), unbounded.vertexTriangleCandidates()) << where;
      EXPECT_EQ(bounded.edgeEdgeCandidates(), unbounded.edgeEdgeCandidates()) << where;
      EXPECT_EQ(a.x, b.x) << where;
      EXPECT_EQ(a.v, b.v) << where;
    }
  }
}

// The candidates of resolve() from the thickness and a step from `start` to `end`.
struct Candidates {
  std::vector<std::array<uint32_t, 2>> vertexTriangle;
  std::vector<std::array<uint32_t, 4>> edgeEdge;
};
Candidates candidatesOf(const ClothMesh& mesh, const ClothState& start, const ClothState& end, float thickness,
                        bool exhaustive) {
  SelfCollision selfCollision(mesh.triangles, mesh.vertexCount());
  selfCollision.setExhaustive(exhaustive);
  ClothState s = end;
  selfCollision.resolve(s, start.x, thickness, 1);
  return {selfCollision.vertexTrianglePairs(), selfCollision.edgeEdgePairs()};
}

// The state turned by `angle` about the vertical axis through `axisPoint`.
ClothState turned(const ClothState& state, glm::vec3 axisPoint, float angle) {
  ClothState out = state;
  for (glm::vec3& p : out.x) {
    const glm::vec3 r = p - axisPoint;
    p = axisPoint +
        glm::vec3(std::cos(angle) * r.x + std::sin(angle) * r.z, r.y, -std::sin(angle) * r.x + std::cos(angle) * r.z);
  }
  return out;
}

TEST(SelfCollision, SearchesFindThePairsOfAnExhaustiveTest) {
  // A sheet dropped over a sphere, folding onto itself with self-collisions
  // on: at a few of its steps, as simulated and with the end of the step
  // swung (about an axis at its side, so its moves differ by centimetres),
  // the tree searches (vertex groups, pair traversal, flat patches and
  // motion bounds pruning whole nodes) find exactly the pairs of a test of
  // every vertex against every triangle and every edge against every edge.
  const ClothMesh mesh = test::horizontalSheetMesh(28, 0.6f, glm::vec3(0.0f, 0.25f, 0.0f));
  ClothSettings settings;
  settings.selfCollisions = true;
  ClothSimulator sim(mesh, fabricPreset("cotton"), settings);
  sim.addCollider(PrimitiveCollider::sphere({0.0f, 0.0f, 0.0f}, 0.15f));
  size_t vertexTriangle = 0, edgeEdge = 0, swungVertexTriangle = 0;
  for (int step = 1; step <= 60; ++step) {
    const ClothState start = sim.state();
    sim.step(1.0f / 60.0f);
    if (step % 12 != 0) continue;
    for (const bool swung : {false, true}) {
      const ClothState end = swung ? turned(sim.state(), glm::vec3(0.4f, 0.0f, 0.0f), 0.08f) : sim.state();
      for (const float thickness : {settings.selfThickness, 0.01f}) {
        const Candidates searched = candidatesOf(mesh, start, end, thickness, false);
        const Candidates reference = candidatesOf(mesh, start, end, thickness, true);
        const std::string where =
            "step " + std::to_string(step) + (swung ? " swung" : "") + ", thickness " + std::to_string(thickness);
        EXPECT_EQ(searched.vertexTriangle, reference.vertexTriangle) << where;
        EXPECT_EQ(searched.edgeEdge, reference.edgeEdge) << where;
        (swung ? swungVertexTriangle : vertexTriangle) += reference.vertexTriangle.size();
        edgeEdge += reference.edgeEdge.size();
      }
    }
  }
  EXPECT_GT(vertexTriangle, 50u);
  EXPECT_GT(swungVertexTriangle, 50u);
  EXPECT_GT(edgeEdge, 50u);
}

}  // namespace
}  // namespace mq::cloth
