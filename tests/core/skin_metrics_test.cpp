#include <gtest/gtest.h>

#include <cmath>

#include "core/character/posed_character.h"
#include "core/mesh/plane_section.h"
#include "core/skin_test_util.h"
#include "core/skinning/skin_metrics.h"

namespace mq {
namespace {

// An axis-aligned box [0, sx] x [0, sy] x [0, sz], outward-facing triangles.
void boxMesh(float sx, float sy, float sz, std::vector<float>& positions, std::vector<uint32_t>& triangles) {
  positions.clear();
  for (int i = 0; i < 8; ++i)
    positions.insert(positions.end(), {i & 1 ? sx : 0.0f, i & 2 ? sy : 0.0f, i & 4 ? sz : 0.0f});
  triangles = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
               2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
}

TEST(PlaneSection, BoxCutIsOneLoopOfTheBoxSection) {
  std::vector<float> p;
  std::vector<uint32_t> t;
  boxMesh(2.0f, 3.0f, 1.0f, p, t);
  const PlaneChart chart({1.0, 1.5, 0.4}, {0, 0, 1});
  const auto loops = sectionLoops(p, t, chart);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_NEAR(polygonArea(loops[0]), 6.0, 1e-9);
  ASSERT_NE(loopAround(loops, {0, 0}), nullptr);
  EXPECT_EQ(loopAround(loops, {5, 0}), nullptr);
  // From the centre, along the chart's u axis, the box wall is 1 or 1.5 away.
  const double exit = rayExitDistance(loops[0], {0, 0}, {1, 0});
  EXPECT_TRUE(std::abs(exit - 1.0) < 1e-9 || std::abs(exit - 1.5) < 1e-9) << exit;
  EXPECT_NEAR(polygonArea(clipToHalfPlane(loops[0], {0, 0}, {0, 1})), 3.0, 1e-9);
}

TEST(PlaneSection, PlaneThroughVerticesStillClosesTheLoop) {
  std::vector<float> p;
  std::vector<uint32_t> t;
  boxMesh(1.0f, 1.0f, 1.0f, p, t);
  // The diagonal plane x + y = 1 holds four of the cube's corners.
  const auto loops = sectionLoops(p, t, PlaneChart({0.5, 0.5, 0.5}, {1, 1, 0}));
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_NEAR(polygonArea(loops[0]), std::sqrt(2.0), 1e-9);
}

TEST(PlaneSection, NoLoopWhenThePlaneMissesTheMesh) {
  std::vector<float> p;
  std::vector<uint32_t> t;
  boxMesh(1.0f, 1.0f, 1.0f, p, t);
  EXPECT_TRUE(sectionLoops(p, t, PlaneChart({0, 0, 2}, {0, 0, 1})).empty());
}

struct Bend {
  double thickness, halfArea, localVolume;
};

// The tube bent by `degrees` about +Z at its joint (0, 1, 0).
Bend bendTube(SkinningMethod method, float degrees) {
  Character c = tubeCharacter(41, 48, false);
  c.skinning = method;
  PoseEdits edits;
  edits.rotations[1] = glm::angleAxis(glm::radians(degrees), glm::vec3(0, 0, 1));
  PosedCharacter posed;
  posed.evaluate(c, -1, 0.0f, &edits, nullptr);
  const auto& tris = c.meshes[0].triangles;
  const OuterSection s = outerSection(c.meshes[0].positions, posed.meshes()[0].positions, tris, tubeBend(degrees));
  const double v =
      localVolumeRatio(c.meshes[0].positions, posed.meshes()[0].positions, tris, {0, 1, 0}, {0, 1, 0}, 0.3);
  return {s.thickness, s.halfArea, v};
}

TEST(SkinMetrics, LinearBlendOuterSectionIsCosineOfHalfTheBend) {
  // The joint ring (weights 1/2, 1/2) maps by (I + R)/2: onto the bisecting
  // plane, scaled by cos(theta/2) across the bend.
  for (float degrees : {60.0f, 90.0f, 120.0f}) {
    const Bend b = bendTube(SkinningMethod::Lbs, degrees);
    const double expected = std::cos(glm::radians(degrees) / 2.0);
    EXPECT_NEAR(b.thickness, expected, 1e-4) << degrees;
    EXPECT_NEAR(b.halfArea, expected, 1e-3) << degrees;
    EXPECT_LT(b.localVolume, 0.95) << degrees;
  }
}

TEST(SkinMetrics, DualQuaternionBendKeepsTheOuterSection) {
  for (float degrees : {60.0f, 90.0f, 120.0f}) {
    const Bend b = bendTube(SkinningMethod::Dqs, degrees);
    EXPECT_NEAR(b.thickness, 1.0, 1e-4) << degrees;
    EXPECT_NEAR(b.halfArea, 1.0, 2e-3) << degrees;
    EXPECT_GT(b.localVolume, 0.95) << degrees;
  }
}

TEST(SkinMetrics, RigidMotionChangesNothing) {
  Character c = tubeCharacter(41, 24, false);
  PoseEdits edits;
  edits.rotations[0] = glm::angleAxis(glm::radians(50.0f), glm::normalize(glm::vec3(1, 2, 3)));
  PosedCharacter posed;
  posed.evaluate(c, -1, 0.0f, &edits, nullptr);
  const glm::dvec3 joint(posed.worldFromBone()[1][3]);
  const auto& tris = c.meshes[0].triangles;
  EXPECT_NEAR(localVolumeRatio(c.meshes[0].positions, posed.meshes()[0].positions, tris, {0, 1, 0}, joint, 0.3), 1.0,
              1e-5);
}

TEST(SkinMetrics, WeldMergesBitEqualPositionsAcrossMeshes) {
  // Two halves of a box's faces in two meshes sharing corner positions.
  Character c;
  c.skeleton = twoBoneChain();
  std::vector<float> p;
  std::vector<uint32_t> t;
  boxMesh(1, 1, 1, p, t);
  Mesh a, b;
  a.positions = b.positions = p;
  a.triangles.assign(t.begin(), t.begin() + 18);
  b.triangles.assign(t.begin() + 18, t.end());
  c.meshes = {a, b};
  const MetricBody body(c);
  EXPECT_EQ(body.vertexCount(), 8u);
  EXPECT_EQ(body.triangles().size(), t.size());
  EXPECT_EQ(intersectingPairs(p, body.triangles()), 0u);
}

}  // namespace
}  // namespace mq
