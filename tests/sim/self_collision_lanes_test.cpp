// The self-collision's four-lane computations against the scalar ones they
// stand in for, which define its candidates: the edge-edge distance test
// (the search drops the pairs it rejects), also where the float arithmetic
// is delicate (parallel and point segments, reach at the distance), its
// cheaper screen (never dropping a pair the scalar test keeps), the
// flat patches' alignment bound and the vertex-triangle screen, bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "sim/cloth/collision/segment_reach.h"
#include "sim/cloth/collision/self_collision.h"
#include "sim/cloth/collision/triangle_reach.h"

namespace mq::cloth {
namespace {

#ifdef MQ_SEGMENT_REACH_SSE
struct SegmentPair {
  glm::vec3 p0, p1, q0, q1;
  float reach;
};

Vec3x4 lanes(const SegmentPair (&pairs)[4], glm::vec3 SegmentPair::*point) {
  Vec3x4 v;
  float x[4], y[4], z[4];
  for (int k = 0; k < 4; ++k) x[k] = (pairs[k].*point).x, y[k] = (pairs[k].*point).y, z[k] = (pairs[k].*point).z;
  v.x = _mm_loadu_ps(x), v.y = _mm_loadu_ps(y), v.z = _mm_loadu_ps(z);
  return v;
}

unsigned fourLaneAnswer(const SegmentPair (&pairs)[4]) {
  float reach[4];
  for (int k = 0; k < 4; ++k) reach[k] = pairs[k].reach;
  return segmentsWithinReach(lanes(pairs, &SegmentPair::p0), lanes(pairs, &SegmentPair::p1),
                             lanes(pairs, &SegmentPair::q0), lanes(pairs, &SegmentPair::q1), _mm_loadu_ps(reach));
}

// Cloth-like segments (1.5 cm) near each other, some of them special: q
// parallel to p, p or q a point, q through p; the reach near the pair's distance.
SegmentPair randomPair(std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), fraction(0.0f, 1.0f);
  auto direction = [&] { return glm::vec3(unit(rng), unit(rng), unit(rng)) * 0.015f; };
  SegmentPair s;
  s.p0 = glm::vec3(unit(rng), unit(rng), unit(rng)) * 0.3f;
  s.p1 = s.p0 + direction();
  s.q0 = s.p0 + direction();
  s.q1 = s.q0 + direction();
  switch (rng() % 6) {
    case 0:
      s.q1 = s.q0 + (s.p1 - s.p0) * (0.5f + fraction(rng));
      break;  // parallel
    case 1:
      s.p1 = s.p0;
      break;  // p a point
    case 2:
      s.q1 = s.q0;
      break;  // q a point
    case 3:
      s.q0 = glm::mix(s.p0, s.p1, fraction(rng)) - 0.5f * direction(), s.q1 = s.q0 + direction();
      break;
    default:
      break;
  }
  const glm::vec2 st = closestSegmentParameters(s.p0, s.p1, s.q0, s.q1);
  const float distance = glm::length(glm::mix(s.p0, s.p1, st.x) - glm::mix(s.q0, s.q1, st.y));
  // Half the pairs with the reach at the distance, to the last bit.
  s.reach = rng() % 2 ? distance : distance * (0.5f + fraction(rng)) + 0.004f * fraction(rng);
  return s;
}

TEST(SegmentReach, FourLanesGiveTheScalarAnswers) {
  std::mt19937 rng(2026);
  int within = 0, apart = 0;
  for (int round = 0; round < 20000; ++round) {
    SegmentPair pairs[4];
    unsigned expected = 0;
    for (int k = 0; k < 4; ++k) {
      pairs[k] = randomPair(rng);
      const bool scalar = segmentsWithinReach(pairs[k].p0, pairs[k].p1, pairs[k].q0, pairs[k].q1, pairs[k].reach);
      expected |= unsigned(scalar) << k;
      (scalar ? within : apart) += 1;
    }
    ASSERT_EQ(fourLaneAnswer(pairs), expected) << "round " << round;
  }
  EXPECT_GT(within, 10000);
  EXPECT_GT(apart, 10000);
}

TEST(SegmentReach, TheMidpointLineBoundRejectsOnlyPairsTheScalarTestRejects) {
  // The edge search's screen (segmentsApart) drops pairs before their exact
  // test: it must never drop one the scalar test keeps, also with the reach
  // at the distance to the last bit, and it must drop most pairs whose
  // distance is well beyond the reach. Its inputs as the search computes them.
  std::mt19937 rng(33);
  int kept = 0, dropped = 0, farDropped = 0, far = 0;
  for (int round = 0; round < 20000; ++round) {
    SegmentPair pairs[4];
    float reach[4];
    float mid[3][4], halfP[3][4], halfQ[3][4];
    for (int k = 0; k < 4; ++k) {
      pairs[k] = randomPair(rng);
      // A quarter of the lanes with a small reach: their segments are far apart.
      if (k == 3) pairs[k].reach *= 0.25f;
      reach[k] = pairs[k].reach;
      const glm::vec3 m = 0.5f * (pairs[k].p0 + pairs[k].p1) - 0.5f * (pairs[k].q0 + pairs[k].q1);
      const glm::vec3 hp = 0.5f * (pairs[k].p1 - pairs[k].p0), hq = 0.5f * (pairs[k].q1 - pairs[k].q0);
      for (int c = 0; c < 3; ++c) mid[c][k] = m[c], halfP[c][k] = hp[c], halfQ[c][k] = hq[c];
    }
    auto lanes3 = [](float(&v)[3][4]) { return Vec3x4{_mm_loadu_ps(v[0]), _mm_loadu_ps(v[1]), _mm_loadu_ps(v[2])}; };
    const unsigned apart = segmentsApart(lanes3(mid), lanes3(halfP), lanes3(halfQ), _mm_loadu_ps(reach));
    for (int k = 0; k < 4; ++k) {
      const bool within = segmentsWithinReach(pairs[k].p0, pairs[k].p1, pairs[k].q0, pairs[k].q1, pairs[k].reach);
      const bool drop = (apart >> k & 1u) != 0;
      ASSERT_FALSE(within && drop) << "round " << round << " lane " << k;
      (drop ? dropped : kept) += 1;
      if (k == 3 && !within) far += 1, farDropped += drop;
    }
  }
  EXPECT_GT(kept, 20000);
  EXPECT_GT(dropped, 10000);
  EXPECT_GT(farDropped, far / 2);
}
#endif

TEST(AabbTree, LeafQueriesTwoLevelsAtATimeFindEveryOverlappingBox) {
  // The vertex-triangle search walks the tree by grandchildren and tests a
  // leaf's four boxes at once: the same boxes as a test of them all, after
  // a build and after a refit (the grandchildren's boxes are copies).
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> position(0.0f, 1.0f), size(0.0f, 0.05f);
  auto randomBoxes = [&](size_t count) {
    std::vector<Box> boxes(count);
    for (Box& b : boxes) {
      b.min = {position(rng), position(rng), position(rng)};
      b.max = b.min + glm::vec3(size(rng), size(rng), size(rng));
    }
    return boxes;
  };
  AabbTree tree;
  const std::vector<Box> built = randomBoxes(3001);
  tree.build(built);
  for (const std::vector<Box>& boxes : {built, randomBoxes(3001)}) {
    tree.refit(boxes);
    for (int q = 0; q < 100; ++q) {
      const glm::vec3 at(position(rng), position(rng), position(rng));
      const Box probe{at, at + glm::vec3(0.1f * position(rng))};
      std::set<uint32_t> expected, found;
      for (uint32_t i = 0; i < boxes.size(); ++i)
        if (boxes[i].overlaps(probe)) expected.insert(i);
      tree.queryLeaves(
          probe,
          [&](int32_t leaf) {
            const uint32_t first = tree.nodeInfo(size_t(leaf)).first;
            for (unsigned mask = tree.leafOverlaps(leaf, probe); mask != 0; mask &= mask - 1)
              EXPECT_TRUE(found.insert(tree.primitive(first + uint32_t(__builtin_ctz(mask)))).second);
          },
          [](int32_t) { return false; });
      EXPECT_EQ(found, expected);
    }
  }
}

TEST(AabbTree, LeafQueriesFromSharedEntriesFindTheLeavesOfQueriesFromTheRoot) {
  // The vertex groups of a run start their walks where the run's walk
  // parts: each group's leaves are those of its walk from the root, with
  // the same nodes skipped, for any split.
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> position(0.0f, 1.0f), size(0.0f, 0.05f);
  std::vector<Box> boxes(3001);
  for (Box& b : boxes) {
    b.min = {position(rng), position(rng), position(rng)};
    b.max = b.min + glm::vec3(size(rng), size(rng), size(rng));
  }
  AabbTree tree;
  tree.build(boxes);
  std::vector<uint8_t> skipped(tree.nodeCount());
  for (uint8_t& s : skipped) s = rng() % 16 == 0;
  skipped[0] = 0;
  size_t leaves = 0;
  auto skip = [&](int32_t node) { return skipped[size_t(node)] != 0; };
  std::vector<AabbTree::Entry> entries;
  for (int run = 0; run < 200; ++run) {
    const glm::vec3 centre(position(rng), position(rng), position(rng));
    Box probes[6], around;
    for (Box& probe : probes) {
      const glm::vec3 at = centre + 0.1f * glm::vec3(position(rng), position(rng), position(rng));
      probe = {at, at + glm::vec3(0.05f * position(rng))};
      around.extend(probe);
    }
    tree.queryEntries(around, uint32_t(1 + rng() % 400), skip, entries);
    for (const Box& probe : probes) {
      std::vector<int32_t> fromRoot, fromEntries;
      tree.queryLeaves(
          probe, [&](int32_t leaf) { fromRoot.push_back(leaf); }, skip);
      tree.queryLeavesFrom(
          entries, probe, [&](int32_t leaf) { fromEntries.push_back(leaf); }, skip);
      std::sort(fromRoot.begin(), fromRoot.end());
      std::sort(fromEntries.begin(), fromEntries.end());
      ASSERT_EQ(fromEntries, fromRoot) << "run " << run;
      leaves += fromRoot.size();
    }
  }
  EXPECT_GT(leaves, 500u);
}

// Normals spread around an axis, some near the flat limit (45 degrees), in
// runs of every length up to 19 (the four-lane part and the rest).
TEST(FlatPatches, SmallestAlignmentFourAtATimeGivesTheScalarAnswer) {
  std::mt19937 rng(45);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int flat = 0, wide = 0;
  for (int round = 0; round < 20000; ++round) {
    const glm::vec3 axis = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + glm::vec3(0.0f, 0.01f, 0.0f));
    const size_t count = 1 + rng() % 19;
    std::vector<float> x(count), y(count), z(count);
    float expected = 1e30f;
    for (size_t k = 0; k < count; ++k) {
      const glm::vec3 n = glm::normalize(axis + (0.6f + 0.4f * unit(rng)) * glm::vec3(unit(rng), unit(rng), unit(rng)));
      x[k] = n.x, y[k] = n.y, z[k] = n.z;
      expected = std::min(expected, axis.x * n.x + axis.y * n.y + axis.z * n.z);
    }
    ASSERT_EQ(smallestAlignment(x.data(), y.data(), z.data(), count, axis), expected) << "round " << round;
    (expected >= 0.7071f ? flat : wide) += 1;
  }
  EXPECT_GT(flat, 2000);
  EXPECT_GT(wide, 2000);
}

// Cloth-like triangles (1.5 cm) with random moves, some of them collapsed to
// a point or to a segment; the vertices near them, half of them at the
// screen's bound to the last bits, some of them a corner, some in the
// triangle's flat patch.
TEST(TriangleScreen, FourLanesGiveTheScalarAnswers) {
  std::mt19937 rng(2027);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), fraction(0.0f, 1.0f);
  auto direction = [&](float length) { return glm::vec3(unit(rng), unit(rng), unit(rng)) * length; };
  const uint32_t places = 4096;
  const float thickness = 0.004f;
  TriangleColumns columns;
  columns.resize(places);
  std::vector<TriangleReach> reaches(places);
  std::vector<std::array<uint32_t, 3>> corners(places);
  std::vector<int32_t> flats(places);
  for (uint32_t k = 0; k < places; ++k) {
    glm::vec3 start[3], moves[3];
    start[0] = direction(0.3f);
    start[1] = start[0] + direction(0.015f);
    start[2] = rng() % 8 == 0 ? start[0] : start[0] + direction(0.015f);  // some collapsed
    if (rng() % 8 == 0) start[1] = glm::mix(start[0], start[2], fraction(rng));
    const glm::vec3 common = direction(0.01f);
    for (glm::vec3& m : moves) m = common + direction(rng() % 2 ? 0.002f : 0.0f);
    corners[k] = {uint32_t(3 * k), uint32_t(3 * k + 1), uint32_t(3 * k + 2)};
    flats[k] = rng() % 3 == 0 ? -1 : int32_t(rng() % 8);
    reaches[k] = triangleReach(start, moves);
    columns.set(k, corners[k], flats[k], reaches[k]);
  }
  int passed = 0, failed = 0, boundPassed = 0, boundFailed = 0;  // boundX: the lane placed at the bound
  for (int round = 0; round < 40000; ++round) {
    const uint32_t first = uint32_t(rng() % (places - 3)), near = first + uint32_t(rng() % 4);
    const TriangleReach& t = reaches[near];
    const uint32_t vertex = rng() % 16 == 0 ? corners[near][rng() % 3] : uint32_t(3 * places + rng() % 100);
    const int32_t flat = rng() % 4 == 0 ? flats[near] : int32_t(rng() % 8) - 1;
    const glm::vec3 move = t.meanMove + direction(0.003f);
    const float farthest = thickness + glm::length(move - t.meanMove) + t.spread;
    const glm::vec3 away = glm::normalize(direction(1.0f) + glm::vec3(0.0f, 0.0f, 1e-3f));
    const bool atBound = rng() % 2 == 0;
    glm::vec3 start = t.centre + away * (atBound ? t.radius + 1.0001f * farthest + 1e-6f : 0.05f * fraction(rng));
    for (int ulps = int(rng() % 5) - 2; ulps != 0; ulps += ulps > 0 ? -1 : 1)
      start.x = std::nextafter(start.x, ulps > 0 ? 1.0f : -1.0f);
    unsigned expected = 0;
    for (uint32_t k = 0; k < 4; ++k) {
      const bool scalar = columns.screen(first + k, vertex, flat, start, move, thickness);
      expected |= unsigned(scalar) << k;
      (scalar ? passed : failed) += 1;
      const bool screenedByIndex = vertex < 3 * places || (flat >= 0 && flat == flats[near]);
      if (atBound && first + k == near && !screenedByIndex) (scalar ? boundPassed : boundFailed) += 1;
    }
    ASSERT_EQ(columns.screenFour(first, vertex, flat, start, move, thickness), expected) << "round " << round;
  }
  EXPECT_GT(passed, 10000);
  EXPECT_GT(failed, 100000);
  EXPECT_GT(boundPassed, 1000);
  EXPECT_GT(boundFailed, 1000);
}

}  // namespace
}  // namespace mq::cloth
