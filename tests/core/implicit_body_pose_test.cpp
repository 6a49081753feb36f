#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/character/default_mannequin.h"
#include "core/character/implicit_body.h"
#include "core/character/posed_character.h"
#include "core/skinning/skin_metrics.h"

namespace mq {
namespace {

// Two primitives on two bones: a capsule on bone 0 and a ball on bone 1.
ImplicitBody twoBoneBody() {
  ImplicitBody body;
  body.add(ImplicitPrimitive::roundCone({0, 0, 0}, {0, 0.3f, 0}, 0.05f, 0.04f, 0, 0.01f));
  body.add(ImplicitPrimitive::ellipsoid({0, 0.45f, 0}, {0.06f, 0.08f, 0.05f}, 1, 0.01f));
  body.setReferenceBlend(0.01f);
  return body;
}

TEST(ImplicitBodyPose, PrimitivesFollowTheirBones) {
  const ImplicitBody rest = twoBoneBody();
  const glm::mat4 turn = glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, -0.2f, 0.3f)) *
                         glm::rotate(glm::mat4(1.0f), 1.1f, glm::normalize(glm::vec3(1, 2, 3)));
  // Both bones moved alike: the field moves rigidly.
  const ImplicitBody moved = rest.posed({turn, turn});
  for (const glm::vec3 p : {glm::vec3(0.05f, 0.1f, 0.0f), glm::vec3(0.0f, 0.45f, 0.07f), glm::vec3(0.2f, 0.2f, 0.2f)})
    EXPECT_NEAR(moved.value(glm::vec3(turn * glm::vec4(p, 1.0f))), rest.value(p), 2e-6f);
  // Only bone 1 moved: the capsule stays where it was, the ball goes.
  const ImplicitBody bent = rest.posed({glm::mat4(1.0f), turn});
  EXPECT_NEAR(bent.value({0.05f, 0.1f, 0.0f}), rest.value({0.05f, 0.1f, 0.0f}), 2e-6f);
  EXPECT_GT(bent.value({0.0f, 0.45f, 0.0f}), 0.0f);
  EXPECT_LT(bent.value(glm::vec3(turn * glm::vec4(0.0f, 0.45f, 0.0f, 1.0f))), -0.04f);
}

TEST(ImplicitBodyPose, ScaleScalesTheField) {
  ImplicitBody body = twoBoneBody();
  const glm::vec3 p(0.07f, 0.2f, 0.01f);
  const float before = body.value(p);
  body.scale(2.0f);
  EXPECT_NEAR(body.value(2.0f * p), 2.0f * before, 1e-6f);
}

// M6 on a ball: a skin pushed out by 1 mm sits 1 mm outside the body.
TEST(ImplicitBodyDeviation, BallSkinPushedOutByOneMillimetre) {
  ImplicitBody body;
  body.add(ImplicitPrimitive::ellipsoid({0, 0, 0}, {0.1f, 0.1f, 0.1f}, 0, 0.01f));
  std::vector<float> rest, posed;
  for (int i = 0; i < 200; ++i) {
    const float z = -1.0f + 2.0f * (i + 0.5f) / 200.0f, a = 2.4f * float(i), r = std::sqrt(1.0f - z * z);
    const glm::vec3 n(r * std::cos(a), r * std::sin(a), z);
    const glm::vec3 onSkin = 0.1f * n, pushed = 0.101f * n;
    rest.insert(rest.end(), {onSkin.x, onSkin.y, onSkin.z});
    posed.insert(posed.end(), {pushed.x, pushed.y, pushed.z});
  }
  // Only the cap within 5 cm of the north pole counts.
  const BodyDeviation d = implicitBodyDeviation(body, rest, posed, {0, 0, 0.1}, 0.05);
  EXPECT_GT(d.vertices, 0u);
  EXPECT_LT(d.vertices, 100u);
  EXPECT_NEAR(d.mean, 0.001, 1e-5);
  EXPECT_NEAR(d.rms, 0.001, 1e-5);
  EXPECT_DOUBLE_EQ(d.beyond2mm, 0.0);
  EXPECT_EQ(implicitBodyDeviation(body, rest, posed, {0, 0, 5}, 0.05).vertices, 0u);
}

// The mannequin keeps its body: its rest skin lies on it (the brief: RMS
// 0.07 mm), and a scaled mannequin keeps that.
TEST(ImplicitBodyDeviation, MannequinRestSkinLiesOnItsBody) {
  Character mannequin = makeDefaultMannequin();
  const Mesh& mesh = mannequin.meshes[0];
  ASSERT_TRUE(mesh.implicitBody);
  const ImplicitBody field = mesh.implicitBody->posed({});
  // The upper body (the soles, cut flat by the ground, are off the field).
  const BodyDeviation upper = implicitBodyDeviation(field, mesh.positions, mesh.positions, {0.0, 1.2, 0.0}, 0.45);
  EXPECT_GT(upper.vertices, 5000u);
  EXPECT_LT(upper.rms, 0.0003);
  mannequin.scaleUniformly(0.5f);
  const Mesh& half = mannequin.meshes[0];
  const BodyDeviation scaled =
      implicitBodyDeviation(half.implicitBody->posed({}), half.positions, half.positions, {0.0, 0.6, 0.0}, 0.225);
  EXPECT_EQ(scaled.vertices, upper.vertices);
  EXPECT_NEAR(scaled.rms, 0.5 * upper.rms, 0.05 * upper.rms + 1e-7);
}

}  // namespace
}  // namespace mq
