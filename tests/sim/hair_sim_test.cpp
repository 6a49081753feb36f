// Strand dynamics: length kept, settling under gravity, collisions with the
// head during a shake, stability at 60 steps per second, children following
// guides, determinism, proxies fitted to a skinned character.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "core/character/character.h"
#include "core/character/default_mannequin.h"
#include "core/hair/character_groom.h"
#include "core/hair/hairstyle.h"
#include "sim/hair/child_follow.h"
#include "sim/hair/hair_bake.h"
#include "sim/hair/hair_colliders.h"
#include "sim/hair/hair_simulator.h"
#include "strand_test_util.h"

namespace mq {
namespace {

using test::addStraightStrand;
using test::pointOf;

constexpr float kDt = 1.0f / 60.0f;

// Strands rooted on the upper half of a sphere at the origin, sticking out
// along the normal a little, then sideways: gravity drops them on the head.
Strands strandsOnSphere(int count, int points, float radius, float length, unsigned seed) {
  Strands strands;
  strands.pointsPerStrand = points;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  while (int(strands.strandCount()) < count) {
    glm::vec3 n(uniform(rng), uniform(rng), uniform(rng));
    if (glm::length(n) > 1.0f || glm::length(n) < 0.1f) continue;
    n = glm::normalize(n);
    if (n.y < 0.2f) continue;
    addStraightStrand(strands, n * radius, n, length);
  }
  return strands;
}

float strandLength(const std::vector<float>& points, size_t s, int n) {
  float length = 0.0f;
  for (int i = 1; i < n; ++i) length += glm::length(pointOf(points, s * n + i) - pointOf(points, s * n + i - 1));
  return length;
}

float maxSegmentError(const HairSimulator& sim) {
  const int n = sim.pointsPerStrand();
  float worst = 0.0f;
  for (size_t s = 0; s < sim.strandCount(); ++s)
    for (int i = 1; i < n; ++i) {
      const size_t k = s * n + i;
      const float rest = glm::length(pointOf(sim.rest().points, k) - pointOf(sim.rest().points, k - 1));
      const float now = glm::length(pointOf(sim.positions(), k) - pointOf(sim.positions(), k - 1));
      worst = std::max(worst, std::abs(now - rest) / rest);
    }
  return worst;
}

TEST(HairSim, HangingStrandSettlesWithLengthKept) {
  Strands strands;
  strands.pointsPerStrand = 20;
  const float length = 0.3f;
  addStraightStrand(strands, {0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, length);  // horizontal
  HairSimParams params;
  params.bendStiffness = 0.0f;
  params.globalStiffness = 0.0f;
  HairSimulator sim(params);
  sim.setRest(strands);
  float worstLength = 0.0f;
  std::vector<float> before;
  for (int step = 0; step < 600; ++step) {
    if (step == 599) before = sim.positions();
    sim.step(kDt, glm::mat4(1.0f));
    worstLength = std::max(worstLength, maxSegmentError(sim));
  }
  EXPECT_LT(worstLength, 0.01f);
  EXPECT_NEAR(strandLength(sim.positions(), 0, 20), length, 0.01f * length);
  // At rest: hanging straight down below the root, still (the FTL velocity
  // keeps a constant term at equilibrium, so compare positions).
  const glm::vec3 tip = pointOf(sim.positions(), 19);
  EXPECT_NEAR(tip.x, 0.0f, 0.01f);
  EXPECT_NEAR(tip.y, 1.0f - length, 0.01f);
  float fastest = 0.0f;
  for (size_t i = 0; i < 20; ++i)
    fastest = std::max(fastest, glm::length(pointOf(sim.positions(), i) - pointOf(before, i)) / kDt);
  EXPECT_LT(fastest, 1e-3f);
}

TEST(HairSim, StiffStrandHoldsItsShapeBetterThanLimpOne) {
  Strands strands;
  strands.pointsPerStrand = 16;
  addStraightStrand(strands, {0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.2f);
  auto tipDrop = [&](float bend) {
    HairSimParams params;
    params.bendStiffness = bend;
    params.globalStiffness = 0.0f;
    HairSimulator sim(params);
    sim.setRest(strands);
    for (int step = 0; step < 300; ++step) sim.step(kDt, glm::mat4(1.0f));
    return -pointOf(sim.positions(), 15).y;
  };
  const float limp = tipDrop(0.0f), stiff = tipDrop(0.9f);
  EXPECT_GT(limp, 0.19f);
  EXPECT_LT(stiff, 0.5f * limp);
  EXPECT_GT(stiff, 0.0f);  // gravity still bends it a little
}

// The head: a sphere on bone 0, which the test moves back and forth fast.
struct ShakenHead {
  float radius = 0.1f;
  HairColliders proxy;
  ShakenHead() { proxy.addSphere(0, glm::vec3(0.0f), radius); }
  static glm::mat4 transformAt(float t) {
    const float swing = std::sin(2.0f * float(M_PI) * 3.0f * t);  // 3 Hz
    glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(0.08f * swing, 1.6f, 0.0f));
    return glm::rotate(m, 0.6f * swing, glm::vec3(0.0f, 1.0f, 0.3f));
  }
};

TEST(HairSim, NoParticleInsideTheHeadAfterAShake) {
  ShakenHead head;
  const Strands strands = strandsOnSphere(200, 24, head.radius + 0.001f, 0.25f, 7);
  HairSimulator sim;
  sim.setRest(strands);
  float deepest = 0.0f;
  for (int step = 0; step < 180; ++step) {
    const glm::mat4 worldFromHead = ShakenHead::transformAt(step * kDt);
    const PosedHairColliders body = head.proxy.posed({worldFromHead});
    sim.step(kDt, worldFromHead, &body);
    const glm::vec3 center(worldFromHead[3]);
    for (size_t k = 0; k < sim.positions().size() / 3; ++k)
      deepest = std::max(deepest, head.radius - glm::length(pointOf(sim.positions(), k) - center));
  }
  // Roots sit 1 mm above the surface; nothing goes deeper than rounding.
  EXPECT_LT(deepest, 1e-4f);
  EXPECT_LT(maxSegmentError(sim), 0.02f);
}

TEST(HairSim, StableForManyStepsAtSixtyHertz) {
  ShakenHead head;
  const Strands strands = strandsOnSphere(64, 32, head.radius + 0.001f, 0.4f, 11);
  HairSimulator sim;
  sim.setRest(strands);
  for (int step = 0; step < 3600; ++step) {
    const glm::mat4 worldFromHead = ShakenHead::transformAt(step * kDt);
    const PosedHairColliders body = head.proxy.posed({worldFromHead}, 0.002f);
    sim.step(kDt, worldFromHead, &body);
  }
  const glm::vec3 center(ShakenHead::transformAt(3599 * kDt)[3]);
  for (size_t k = 0; k < sim.positions().size() / 3; ++k) {
    const glm::vec3 p = pointOf(sim.positions(), k);
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    ASSERT_LT(glm::length(p - center), head.radius + 0.45f);  // never further than the strand reaches
  }
  EXPECT_LT(maxSegmentError(sim), 0.02f);
}

TEST(HairSim, SameInputsGiveTheSameBytes) {
  ShakenHead head;
  const Strands strands = strandsOnSphere(300, 16, head.radius + 0.001f, 0.2f, 3);
  auto run = [&] {
    HairSimulator sim;
    sim.setRest(strands);
    for (int step = 0; step < 60; ++step) {
      const glm::mat4 m = ShakenHead::transformAt(step * kDt);
      const PosedHairColliders body = head.proxy.posed({m});
      sim.step(kDt, m, &body);
    }
    return sim.positions();
  };
  EXPECT_EQ(run(), run());
}

TEST(HairSim, ChildrenFollowTheirGuides) {
  const Strands guides = strandsOnSphere(10, 16, 0.1f, 0.2f, 5);
  // Each child: its guide shifted sideways by 5 mm.
  Strands children;
  children.pointsPerStrand = 16;
  const glm::vec3 offset(0.005f, 0.0f, 0.003f);
  for (size_t g = 0; g < guides.strandCount(); ++g)
    for (int copy = 0; copy < 3; ++copy) {
      for (int i = 0; i < 16; ++i) {
        const glm::vec3 p = pointOf(guides.points, g * 16 + i) + float(copy + 1) * offset;
        children.points.insert(children.points.end(), {p.x, p.y, p.z});
      }
      children.guideOf.push_back(int(g));
    }
  HairSimulator sim;
  sim.setRest(guides);
  const glm::mat4 moved =
      glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, 0.2f, 0.0f)), 1.2f, glm::vec3(0.0f, 1.0f, 0.0f));
  for (int step = 0; step < 90; ++step) sim.step(kDt, moved);
  std::vector<float> childNow;
  followGuides(children, sim, childNow);
  ASSERT_EQ(childNow.size(), children.points.size());
  float guideMotion = 0.0f;
  for (size_t c = 0; c < children.strandCount(); ++c) {
    const size_t g = size_t(children.guideOf[c]);
    // The root rides the scalp rigidly.
    const glm::vec3 expectedRoot = glm::vec3(moved * glm::vec4(pointOf(children.points, c * 16), 1.0f));
    EXPECT_LT(glm::length(pointOf(childNow, c * 16) - expectedRoot), 1e-5f);
    for (int i = 0; i < 16; ++i) {
      // Every point keeps its distance from the guide point and moved with it.
      const float restGap = glm::length(pointOf(children.points, c * 16 + i) - pointOf(guides.points, g * 16 + i));
      const float gapNow = glm::length(pointOf(childNow, c * 16 + i) - pointOf(sim.positions(), g * 16 + i));
      EXPECT_NEAR(gapNow, restGap, 1e-5f);
    }
    guideMotion =
        std::max(guideMotion, glm::length(pointOf(sim.positions(), g * 16 + 15) -
                                          glm::vec3(moved * glm::vec4(pointOf(guides.points, g * 16 + 15), 1.0f))));
  }
  EXPECT_GT(guideMotion, 0.01f);  // the guides really moved away from the rigid rest shape

  // Frames rebuilt from the positions alone (baked playback) match the simulator's.
  const std::vector<glm::quat> rebuilt = guideFrames(guides, sim.positions(), glm::quat_cast(glm::mat3(moved)));
  ASSERT_EQ(rebuilt.size(), sim.frames().size());
  for (size_t k = 0; k < rebuilt.size(); ++k) EXPECT_GT(std::abs(glm::dot(rebuilt[k], sim.frames()[k])), 0.9999f) << k;
}

TEST(HairSim, GroomedStrandsPoseGuidesFirstThenChildren) {
  // One array as the groom lays it out: guides first, then children.
  Strands all = strandsOnSphere(6, 12, 0.1f, 0.15f, 9);
  all.guideOf.assign(6, -1);
  for (int c = 0; c < 12; ++c) {
    const int g = c % 6;
    for (int i = 0; i < 12; ++i) {
      const glm::vec3 p = pointOf(all.points, g * 12 + i) + glm::vec3(0.0f, 0.0f, 0.004f);
      all.points.insert(all.points.end(), {p.x, p.y, p.z});
    }
    all.guideOf.push_back(g);
  }
  HairSimulator sim;
  sim.setRest(leadingStrands(all, 6));
  ASSERT_EQ(sim.strandCount(), 6u);
  for (int step = 0; step < 30; ++step) sim.step(kDt, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 0.1f)));
  std::vector<float> now;
  poseGroomedStrands(all, sim, now);
  ASSERT_EQ(now.size(), all.points.size());
  for (size_t k = 0; k < 6 * 12; ++k) EXPECT_EQ(pointOf(now, k), pointOf(sim.positions(), k));
  for (int c = 0; c < 12; ++c)
    for (int i = 0; i < 12; ++i) {
      const glm::vec3 child = pointOf(now, (6 + c) * 12 + i), guide = pointOf(sim.positions(), (c % 6) * 12 + i);
      EXPECT_NEAR(glm::length(child - guide), 0.004f, 1e-5f);
    }
}

// A head ellipsoid (turned, not axis-aligned) and two capsules, posed with a
// turn and a margin, as the children's body query sees them.
PosedHairColliders turnedHeadAndShoulders() {
  HairColliders colliders;
  colliders.addEllipsoid(0, glm::vec3(0.0f, 0.02f, 0.0f), glm::vec3(0.08f, 0.11f, 0.095f),
                         glm::angleAxis(0.3f, glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f))));
  colliders.addCapsule(0, glm::vec3(0.0f, -0.2f, -0.01f), glm::vec3(0.0f, -0.08f, 0.0f), 0.05f);
  colliders.addCapsule(-1, glm::vec3(-0.18f, -0.25f, 0.0f), glm::vec3(0.18f, -0.25f, 0.0f), 0.07f);
  const glm::mat4 head =
      glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.01f, 0.0f, 0.02f)), 0.5f, glm::vec3(0.0f, 1.0f, 0.0f));
  return colliders.posed({head}, 0.002f);
}

TEST(HairColliders, ClearanceNeverOverstatesTheDistanceToAProxy) {
  const PosedHairColliders body = turnedHeadAndShoulders();
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> box(-0.3f, 0.3f), unit(-1.0f, 1.0f);
  int outside = 0, inside = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const glm::vec3 p(box(rng), box(rng) - 0.05f, box(rng) * 0.5f);
    const float clearance = body.clearance(p);
    if (body.contains(p)) {
      EXPECT_EQ(clearance, 0.0f);
      ++inside;
      continue;
    }
    if (clearance <= 0.0f) continue;
    ++outside;
    // Points just inside the clearance ball, in any direction, are outside
    // every proxy: the body query would not move them.
    for (int k = 0; k < 8; ++k) {
      glm::vec3 direction(unit(rng), unit(rng), unit(rng));
      if (glm::length(direction) < 1e-3f) continue;
      glm::vec3 q = p + 0.999f * clearance * glm::normalize(direction);
      const glm::vec3 before = q;
      glm::vec3 normal;
      EXPECT_FALSE(body.pushOut(q, normal)) << trial;
      EXPECT_EQ(q, before);
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 2000);
  // Beside a capsule and nothing else, the bound is the exact distance.
  const glm::vec3 besideShoulder(0.0f, -0.25f, 0.2f);
  EXPECT_NEAR(body.clearance(besideShoulder), 0.2f - 0.072f, 1e-5f);
}

TEST(HairSim, ChildrenOutOfTheBodyAsIfEveryPointWereQueried) {
  // Guides draped over the head; children up to 5 cm from them, so some of
  // their points are inside the body and most are far from it.
  const PosedHairColliders body = turnedHeadAndShoulders();
  const Strands guides = strandsOnSphere(40, 16, 0.12f, 0.3f, 21);
  Strands children;
  children.pointsPerStrand = 16;
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (size_t c = 0; c < 800; ++c) {
    const size_t g = c % guides.strandCount();
    const glm::vec3 offset = 0.03f * glm::vec3(unit(rng), unit(rng), unit(rng));
    for (int i = 0; i < 16; ++i) {
      const glm::vec3 p = pointOf(guides.points, g * 16 + i) + (i == 0 ? glm::vec3(0.0f) : offset);
      children.points.insert(children.points.end(), {p.x, p.y, p.z});
    }
    children.guideOf.push_back(int(g));
  }
  HairSimulator sim;
  sim.setRest(guides);
  for (int step = 0; step < 60; ++step) sim.step(kDt, glm::mat4(1.0f), &body);

  std::vector<float> followed, reference;
  followGuides(children, sim, followed, &body);
  followGuides(children, sim, reference);
  int moved = 0;
  for (size_t k = 0; k < reference.size() / 3; ++k) {
    if (k % 16 == 0) continue;  // roots stay on the scalp
    glm::vec3 p = pointOf(reference, k), normal;
    if (body.pushOut(p, normal)) ++moved;
    ASSERT_EQ(pointOf(followed, k), p) << "child point " << k;
  }
  EXPECT_GT(moved, 50);
}

// A skinned character: a sphere weighted to "head" above a cylinder weighted
// to "neck"; the colliders built from the fitted body proxy match them and
// follow their bones.
Character sphereOnCylinder() {
  Character c;
  c.skeleton.addBone({"neck", -1, Trs{glm::vec3(0.0f, 1.4f, 0.0f)}, glm::mat4(1.0f)});
  c.skeleton.addBone({"head", 0, Trs{glm::vec3(0.0f, 0.2f, 0.0f)}, glm::mat4(1.0f)});
  Mesh mesh;
  std::vector<int> bones;
  for (int i = 0; i < 400; ++i) {  // sphere r=0.1 at y=1.7 (Fibonacci points)
    const float y = 1.0f - 2.0f * (float(i) + 0.5f) / 400.0f, r = std::sqrt(1.0f - y * y);
    const float phi = float(i) * 2.39996f;
    mesh.positions.insert(mesh.positions.end(), {0.1f * r * std::cos(phi), 1.7f + 0.1f * y, 0.1f * r * std::sin(phi)});
    bones.push_back(1);
  }
  for (int i = 0; i < 200; ++i) {  // cylinder r=0.05 from y=1.4 to 1.6
    const float phi = float(i % 20) * 2.0f * float(M_PI) / 20.0f, y = 1.4f + 0.2f * float(i / 20) / 9.0f;
    mesh.positions.insert(mesh.positions.end(), {0.05f * std::cos(phi), y, 0.05f * std::sin(phi)});
    bones.push_back(0);
  }
  mesh.normals.assign(mesh.positions.size(), 0.0f);
  mesh.skin.influencesPerVertex = 1;
  for (int b : bones) {
    mesh.skin.joints.push_back(uint16_t(b));
    mesh.skin.weights.push_back(1.0f);
  }
  mesh.skin.jointBones = {0, 1};
  mesh.skin.inverseBind = c.skeleton.inverseBindMatrices();
  c.meshes.push_back(std::move(mesh));
  return c;
}

TEST(HairSim, ProxiesFitASkinnedCharacter) {
  const Character character = sphereOnCylinder();
  const HairRig rig = HairRig::fromCharacter(character);
  ASSERT_EQ(rig.headBone, 1);
  ASSERT_EQ(rig.body.ellipsoids.size(), 1u);
  ASSERT_EQ(rig.body.capsules.size(), 1u);
  EXPECT_EQ(rig.body.ellipsoids[0].bone, 1);
  EXPECT_EQ(rig.body.capsules[0].bone, 0);
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(rig.body.ellipsoids[0].radii[axis], 0.1f, 0.006f);
  EXPECT_NEAR(rig.body.capsules[0].radius, 0.05f, 0.004f);
  // Posed: the head proxy follows the head bone.
  Pose pose = character.skeleton.restPose();
  pose[0].rotation = glm::angleAxis(0.5f, glm::vec3(1.0f, 0.0f, 0.0f));
  const auto worldFromBone = character.skeleton.worldTransforms(pose);
  const PosedHairColliders body = rig.body.posed(worldFromBone);
  const glm::vec3 headCenter = glm::vec3(worldFromBone[1] * glm::vec4(0.0f, 0.1f, 0.0f, 1.0f));
  EXPECT_TRUE(body.contains(headCenter, 0.05f));
  EXPECT_FALSE(body.contains(glm::vec3(0.0f, 1.7f, 0.0f), 0.0f));  // where the head was at rest
  glm::vec3 p = headCenter + glm::vec3(0.02f, 0.0f, 0.0f), normal;
  ASSERT_TRUE(body.pushOut(p, normal));
  EXPECT_NEAR(glm::length(p - headCenter), 0.1f, 0.007f);
}

// Each built-in hairstyle's guides on the default mannequin, the head
// shaken hard (+-40 degrees at 3 Hz about two axes): no particle ends inside
// the head or body colliders, lengths hold, everything stays finite.
void shakeTheDefaultMannequinsHead(const std::string& style) {
  SCOPED_TRACE(style);
  const Character character = makeDefaultMannequin();
  const std::unique_ptr<HairGroom> groom = makeCharacterGroom(character, ScalpRegion{});
  groom->grow(builtinHairStyle(style), 3000);
  const Strands guides = leadingStrands(groom->strands(), groom->guideCount());
  ASSERT_GT(guides.strandCount(), 100u);
  const HairRig rig = HairRig::fromProxy(character, groom->proxy());
  ASSERT_GE(rig.headBone, 0);
  ASSERT_FALSE(rig.body.ellipsoids.empty());
  HairSimulator sim;
  sim.setRest(guides);
  std::vector<glm::mat4> worldFromBone;
  size_t inside = 0;
  float worstSegment = 0.0f;
  for (int step = 0; step < 120; ++step) {
    Pose pose = character.skeleton.restPose();
    const float swing = std::sin(2.0f * float(M_PI) * 3.0f * float(step) * kDt);
    pose[rig.headBone].rotation =
        pose[rig.headBone].rotation * glm::angleAxis(0.7f * swing, glm::normalize(glm::vec3(0.3f, 1.0f, 0.4f)));
    character.skeleton.worldTransforms(pose, worldFromBone);
    const PosedHairColliders body = rig.body.posed(worldFromBone, sim.params().collisionMargin);
    sim.step(kDt, rig.posedFromRest(worldFromBone), &body);
    worstSegment = std::max(worstSegment, maxSegmentError(sim));
    if (step % 10 != 9) continue;
    const PosedHairColliders bare = rig.body.posed(worldFromBone);
    for (size_t s = 0; s < sim.strandCount(); ++s)
      for (int i = 1; i < sim.pointsPerStrand(); ++i)
        if (bare.contains(pointOf(sim.positions(), s * sim.pointsPerStrand() + i), 1e-4f)) ++inside;
  }
  EXPECT_EQ(inside, 0u);
  for (float x : sim.positions()) ASSERT_TRUE(std::isfinite(x));
  // Every segment keeps its length within 1% at every step, even where it
  // lies in the crease between two colliders (shoulder and chest) or its
  // groomed shape dives into the head (curls): there it slides along the
  // surfaces rather than being pushed off them shortened or stretched (up to
  // 38% before).
  EXPECT_LT(worstSegment, 0.01f);
}

TEST(HairSim, DefaultMannequinGuidesStayOutOfTheBodyWhenTheHeadShakes) {
  for (const std::string& style : builtinHairStyleNames()) shakeTheDefaultMannequinsHead(style);
}

TEST(HairSim, BakeReportsProgressAndStopsWhenCancelled) {
  const Character character = sphereOnCylinder();
  Strands strands = strandsOnSphere(20, 8, 0.101f, 0.15f, 1);
  for (size_t k = 0; k < strands.points.size() / 3; ++k) strands.points[3 * k + 1] += 1.7f;
  int lastDone = 0, total = 0;
  HairBakeCallbacks callbacks;
  callbacks.progress = [&](int done, int all) {
    lastDone = done;
    total = all;
  };
  HairBakeSettings settings;
  settings.settleSeconds = 0.1f;
  const HairBake full = bakeHair(character, -1, strands, HairSimParams{}, settings, callbacks);
  EXPECT_FALSE(full.cancelled);
  EXPECT_EQ(full.frameCount(), 61);
  EXPECT_EQ(lastDone, 61);
  EXPECT_EQ(total, 61);
  lastDone = 0;
  callbacks.cancelled = [&] { return lastDone >= 10; };
  const HairBake part = bakeHair(character, -1, strands, HairSimParams{}, settings, callbacks);
  EXPECT_TRUE(part.cancelled);
  EXPECT_EQ(part.frameCount(), 10);
  EXPECT_EQ(part.frames[9], full.frames[9]);  // deterministic
}

}  // namespace
}  // namespace mq
