#include <gtest/gtest.h>

#include <cmath>

#include "core/animation/clip.h"
#include "core/animation/track.h"
#include "core/math/transform.h"

namespace mq {
namespace {

Track vec3Track(Interpolation mode, std::vector<float> times, std::vector<float> values) {
  Track t;
  t.interpolation = mode;
  t.components = 3;
  t.times = std::move(times);
  t.values = std::move(values);
  return t;
}

TEST(Track, StepHoldsPreviousKey) {
  const Track t = vec3Track(Interpolation::Step, {0, 1}, {0, 0, 0, 2, 4, 6});
  float out[3];
  t.sample(0.99f, out);
  EXPECT_FLOAT_EQ(out[0], 0.0f);
  t.sample(1.0f, out);
  EXPECT_FLOAT_EQ(out[2], 6.0f);
}

TEST(Track, LinearInterpolatesAndClampsOutsideKeys) {
  const Track t = vec3Track(Interpolation::Linear, {1, 3}, {0, 0, 0, 2, 4, 6});
  float out[3];
  t.sample(2.0f, out);
  EXPECT_FLOAT_EQ(out[0], 1.0f);
  EXPECT_FLOAT_EQ(out[1], 2.0f);
  EXPECT_FLOAT_EQ(out[2], 3.0f);
  t.sample(-5.0f, out);
  EXPECT_FLOAT_EQ(out[1], 0.0f);
  t.sample(9.0f, out);
  EXPECT_FLOAT_EQ(out[1], 4.0f);
}

TEST(Track, CubicSplineMatchesHandComputedHermite) {
  // One component; keys at t=0 (v=0, out-tangent 1) and t=2 (v=1, in-tangent 0).
  Track t;
  t.interpolation = Interpolation::CubicSpline;
  t.components = 1;
  t.times = {0, 2};
  t.values = {/*in*/ 0, /*v*/ 0, /*out*/ 1, /*in*/ 0, /*v*/ 1, /*out*/ 0};
  float out;
  t.sample(1.0f, &out);
  // s = 0.5: h00=0.5 h10=0.125 h01=0.5 h11=-0.125; m0 = dt*1 = 2, m1 = 0
  EXPECT_NEAR(out, 0.125f * 2.0f + 0.5f * 1.0f, 1e-6f);
}

TEST(Track, BezierPassesThroughEndsAndUsesHandles) {
  Track t;
  t.interpolation = Interpolation::Bezier;
  t.components = 1;
  t.times = {0, 1};
  t.values = {0, 0, 1, 3, 2, 0};  // P0=0, P1=1, P2=3, P3=2
  float out;
  t.sample(0.5f, &out);
  EXPECT_NEAR(out, 0.125f * 0 + 0.375f * 1 + 0.375f * 3 + 0.125f * 2, 1e-6f);
  t.sample(1.0f, &out);
  EXPECT_FLOAT_EQ(out, 2.0f);
}

TEST(Track, LinearRotationIsShortestPathSlerp) {
  Track t;
  t.components = 4;
  t.isRotation = true;
  t.times = {0, 1};
  const float h = std::sqrt(0.5f);
  // identity and 90 degrees about Y, the second with flipped sign (same rotation)
  t.values = {0, 0, 0, 1, 0, -h, 0, -h};
  float q[4];
  t.sample(0.5f, q);
  const glm::quat r(q[3], q[0], q[1], q[2]);
  const glm::vec3 x = r * glm::vec3(1, 0, 0);
  // 45 degrees about +Y maps x to (cos45, 0, -sin45)
  EXPECT_NEAR(x.x, h, 1e-5f);
  EXPECT_NEAR(x.z, -h, 1e-5f);
  EXPECT_NEAR(glm::length(r), 1.0f, 1e-6f);
}

TEST(Track, ValidateRejectsBadSizes) {
  const Track t = vec3Track(Interpolation::Linear, {0, 1}, {0, 0, 0});
  EXPECT_THROW(t.validate(), std::invalid_argument);
}

TEST(Clip, LoopWrapsTime) {
  Clip clip;
  BoneChannel c;
  c.bone = 0;
  c.translation = vec3Track(Interpolation::Linear, {1, 3}, {0, 0, 0, 2, 0, 0});
  clip.boneChannels.push_back(c);
  clip.wrap = WrapMode::Loop;
  EXPECT_FLOAT_EQ(clip.wrapTime(4.0f), 2.0f);
  EXPECT_FLOAT_EQ(clip.wrapTime(0.5f), 2.5f);
  clip.wrap = WrapMode::Clamp;
  EXPECT_FLOAT_EQ(clip.wrapTime(4.0f), 3.0f);
}

TEST(Transform, EulerRoundTrip) {
  const glm::vec3 angles(20.0f, -35.0f, 60.0f);
  const glm::vec3 back = eulerDegreesFromQuat(quatFromEulerDegrees(angles));
  EXPECT_NEAR(back.x, angles.x, 1e-3f);
  EXPECT_NEAR(back.y, angles.y, 1e-3f);
  EXPECT_NEAR(back.z, angles.z, 1e-3f);
}

TEST(Transform, TrsMatrixRoundTrip) {
  Trs trs;
  trs.translation = {1, 2, 3};
  trs.rotation = glm::normalize(glm::quat(0.9f, 0.1f, 0.3f, -0.2f));
  trs.scale = {2, 2, 2};
  const Trs back = Trs::fromMatrix(trs.matrix());
  EXPECT_NEAR(glm::length(back.translation - trs.translation), 0.0f, 1e-5f);
  EXPECT_NEAR(std::abs(glm::dot(back.rotation, trs.rotation)), 1.0f, 1e-5f);
  EXPECT_NEAR(back.scale.y, 2.0f, 1e-5f);
}

}  // namespace
}  // namespace mq
