#include <gtest/gtest.h>

#include <cmath>

#include "core/character/posed_character.h"
#include "core/mesh/plane_section.h"
#include "core/skin_test_util.h"
#include "core/skinning/skin_metrics.h"
#include "core/util/thread_pool.h"

namespace mq {
namespace {

std::vector<float> posedPositions(const Character& c, const PoseEdits& edits, ThreadPool* pool = nullptr) {
  PosedCharacter posed;
  posed.evaluate(c, -1, 0.0f, &edits, pool);
  return posed.meshes()[0].positions;
}

Character dqsTube(int rings, int around) {
  Character c = tubeCharacter(rings, around, false);
  c.skinning = SkinningMethod::Dqs;
  return c;
}

TEST(DualQuaternionSkinning, RestPoseReproducesRestMesh) {
  const Character c = dqsTube(41, 24);
  const std::vector<float> p = posedPositions(c, {});
  for (size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p[i], c.meshes[0].positions[i], 1e-6f);
}

TEST(DualQuaternionSkinning, OneInfluenceIsTheBoneTransform) {
  Character lbs = tubeCharacter(21, 12, true);
  Character dqs = lbs;
  dqs.skinning = SkinningMethod::Dqs;
  PoseEdits edits;
  edits.rotations[0] = glm::angleAxis(glm::radians(-35.0f), glm::normalize(glm::vec3(0, 1, 1)));
  edits.rotations[1] = glm::angleAxis(glm::radians(70.0f), glm::normalize(glm::vec3(1, 0, 1)));
  const std::vector<float> a = posedPositions(lbs, edits), b = posedPositions(dqs, edits);
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 2e-6f);
}

TEST(DualQuaternionSkinning, TwistKeepsTheSectionWhereLinearBlendCollapses) {
  // A 180-degree twist of the child about the axis: LBS folds the joint ring
  // onto the axis (cos^2(90 deg) = 0), DQS turns it rigidly.
  Character dqs = dqsTube(201, 48);  // rings 1 cm apart: the twist turns 4.5 degrees a ring
  Character lbs = dqs;
  lbs.skinning = SkinningMethod::Lbs;
  PoseEdits edits;
  edits.rotations[1] = glm::angleAxis(glm::radians(179.0f), glm::vec3(0, 1, 0));
  const MetricBody body(dqs);
  const std::vector<float>& rest = dqs.meshes[0].positions;
  const auto tris = dqs.meshes[0].triangles;
  const glm::dvec3 joint(0, 1, 0), axis(0, 1, 0);
  const double lbsLeast = minimumSectionRatio(rest, posedPositions(lbs, edits), tris, joint, axis, -0.3, 0.3, 0.01);
  const double dqsLeast = minimumSectionRatio(rest, posedPositions(dqs, edits), tris, joint, axis, -0.3, 0.3, 0.01);
  EXPECT_LT(lbsLeast, 0.01);
  EXPECT_GT(dqsLeast, 0.97);
}

TEST(DualQuaternionSkinning, NormalsStayUnitAndAgreeWithRecomputedNormals) {
  // As for LBS: the blended rotation is the normal's, which the bent
  // surface's own normal follows closely outside the sharpest blend.
  const Character c = dqsTube(81, 48);
  PoseEdits edits;
  edits.rotations[1] = glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 0, 1));
  PosedCharacter posed;
  posed.evaluate(c, -1, 0.0f, &edits, nullptr);
  std::vector<float> recomputed;
  computeVertexNormals(posed.meshes()[0].positions, c.meshes[0].triangles, recomputed);
  const auto& n = posed.meshes()[0].normals;
  for (size_t v = 48; v + 48 < c.meshes[0].vertexCount(); ++v) {  // skip the open ends
    const glm::vec3 a(n[3 * v], n[3 * v + 1], n[3 * v + 2]);
    const glm::vec3 b(recomputed[3 * v], recomputed[3 * v + 1], recomputed[3 * v + 2]);
    EXPECT_NEAR(glm::length(a), 1.0f, 1e-5f);
    EXPECT_GT(glm::dot(a, b), 0.9f) << "vertex " << v;
  }
}

TEST(DualQuaternionSkinning, AntipodalQuaternionsBlendTheShortWay) {
  // The child turned by 350 degrees is the same as -10: a vertex half on each
  // bone must move by 5 degrees, not 175.
  const Character c = dqsTube(41, 24);
  PoseEdits edits;
  edits.rotations[1] = glm::angleAxis(glm::radians(350.0f), glm::vec3(0, 1, 0));
  const std::vector<float> p = posedPositions(c, edits);
  const size_t v = 20 * 24;  // the joint ring, phi = 0: (0.2, 1, 0)
  ASSERT_NEAR(c.meshes[0].positions[3 * v + 1], 1.0f, 1e-6f);
  const float angle = std::atan2(-p[3 * v + 2], p[3 * v]);
  EXPECT_NEAR(glm::degrees(angle), -5.0f, 0.01f);
  EXPECT_NEAR(std::hypot(p[3 * v], p[3 * v + 2]), 0.2f, 1e-5f);
}

TEST(DualQuaternionSkinning, StretchedBindMatricesStillReproduceTheMesh) {
  // Bind matrices with a uniform scale and a non-uniform one (centimetre
  // exports, squashed bones): the rest pose still gives the rest mesh, and a
  // pose matches LBS where one bone alone drives a vertex.
  Character lbs = tubeCharacter(21, 12, true);
  for (int b = 0; b < 2; ++b) {
    Bone& bone = lbs.skeleton.bone(b);
    bone.rest.scale = b == 0 ? glm::vec3(0.01f) : glm::vec3(1.0f, 2.0f, 0.5f);
  }
  lbs.meshes[0].skin.inverseBind = lbs.skeleton.inverseBindMatrices();
  Character dqs = lbs;
  dqs.skinning = SkinningMethod::Dqs;
  const std::vector<float> restLbs = posedPositions(lbs, {}), restDqs = posedPositions(dqs, {});
  for (size_t i = 0; i < restLbs.size(); ++i) EXPECT_NEAR(restDqs[i], lbs.meshes[0].positions[i], 1e-5f);
  PoseEdits edits;
  edits.rotations[1] = glm::angleAxis(glm::radians(40.0f), glm::vec3(1, 0, 0));
  const std::vector<float> a = posedPositions(lbs, edits), b = posedPositions(dqs, edits);
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-5f);
}

TEST(DualQuaternionSkinning, ThreadedEqualsSingleThreaded) {
  const Character c = dqsTube(401, 64);
  PoseEdits edits;
  edits.rotations[1] = glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 0, 1));
  expectThreadedEqualsSingleThreaded(c, edits);
}

}  // namespace
}  // namespace mq
