// Points carried by a deforming point set (core/geometry/rigid_carry.h).
#include <gtest/gtest.h>

#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/geometry/nearest_points.h"
#include "core/geometry/rigid_carry.h"

namespace mq {
namespace {

// A cylinder of points along x from x0 to x1 (an "arm"), radius r.
void addCylinder(std::vector<float>& out, float x0, float x1, float r) {
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j < 16; ++j) {
      const float a = 2.0f * float(M_PI) * j / 16.0f;
      out.insert(out.end(), {x0 + (x1 - x0) * i / 20.0f, r * std::cos(a), r * std::sin(a)});
    }
}

std::vector<float> transformed(const std::vector<float>& points, const glm::quat& q, glm::vec3 t, float fromX = -1e9f) {
  std::vector<float> out = points;
  for (size_t i = 0; i < points.size() / 3; ++i) {
    const glm::vec3 p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
    if (p.x < fromX) continue;
    const glm::vec3 m = q * p + t;
    out[3 * i] = m.x, out[3 * i + 1] = m.y, out[3 * i + 2] = m.z;
  }
  return out;
}

TEST(RigidCarry, RigidMotionOfTheSetMovesThePointsRigidly) {
  std::vector<float> body;
  addCylinder(body, 0.0f, 0.6f, 0.05f);
  std::vector<float> sleeve;
  addCylinder(sleeve, 0.05f, 0.55f, 0.07f);
  const glm::quat q = glm::angleAxis(1.2f, glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f)));
  const glm::vec3 t(0.1f, -0.2f, 0.3f);
  const std::vector<float> carried = RigidCarry(sleeve, body).carry(transformed(body, q, t));
  const std::vector<float> expected = transformed(sleeve, q, t);
  for (size_t i = 0; i < carried.size(); ++i) EXPECT_NEAR(carried[i], expected[i], 1e-4f);
}

TEST(RigidCarry, SleeveTurnsWithTheForearmWhereATranslationWouldShearIt) {
  std::vector<float> body;
  addCylinder(body, 0.0f, 0.6f, 0.05f);
  std::vector<float> sleeve;
  addCylinder(sleeve, 0.4f, 0.55f, 0.07f);  // around the "forearm" only
  // The forearm (x > 0.3) turns 90 degrees about z at the elbow.
  const glm::quat bend = glm::angleAxis(float(M_PI) / 2.0f, glm::vec3(0, 0, 1));
  const glm::vec3 elbow(0.3f, 0.0f, 0.0f);
  const std::vector<float> bent = transformed(body, bend, elbow - bend * elbow, 0.3f);
  const std::vector<float> carried = RigidCarry(sleeve, body).carry(bent);
  const std::vector<float> expected = transformed(sleeve, bend, elbow - bend * elbow);
  float worst = 0.0f;
  for (size_t i = 0; i < carried.size() / 3; ++i)
    worst = std::max(worst, glm::distance(glm::vec3(carried[3 * i], carried[3 * i + 1], carried[3 * i + 2]),
                                          glm::vec3(expected[3 * i], expected[3 * i + 1], expected[3 * i + 2])));
  EXPECT_LT(worst, 0.01f);
}

TEST(RigidCarry, UnchangedOrMismatchedSetLeavesThePoints) {
  std::vector<float> body;
  addCylinder(body, 0.0f, 0.6f, 0.05f);
  const std::vector<float> points = {0.1f, 0.2f, 0.0f, 0.3f, 0.0f, 0.1f};
  const RigidCarry carry(points, body);
  EXPECT_EQ(carry.carry(body), points);
  EXPECT_EQ(carry.carry({1.0f, 2.0f, 3.0f}), points);
  EXPECT_EQ(RigidCarry(points, {}).carry({}), points);
}

TEST(RigidCarry, NearestPointsAreTheKNearestInOrder) {
  std::vector<float> set;
  for (int i = 0; i < 100; ++i) set.insert(set.end(), {0.01f * i, 0.0f, 0.0f});
  const std::vector<uint32_t> near = nearestPoints({0.503f, 0.0f, 0.0f}, set, 3);
  ASSERT_EQ(near.size(), 3u);
  EXPECT_EQ(near[0], 50u);
  EXPECT_EQ(near[1], 51u);
  EXPECT_EQ(near[2], 49u);
  EXPECT_EQ(nearestPoints({0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, 8).size(), 1u);
}

}  // namespace
}  // namespace mq
