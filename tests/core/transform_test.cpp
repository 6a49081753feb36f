// The pose maths of core/math/transform.h.
#include <gtest/gtest.h>

#include <cmath>

#include "core/math/transform.h"

namespace mq {
namespace {

// The edit computed for a world-axis turn rotates the bone's world frame by
// exactly that turn.
TEST(Transform, EditAfterWorldRotationTurnsTheWorldFrameAboutTheAxis) {
  const glm::quat edit = quatFromEulerDegrees({10, 20, 30});
  const glm::quat world = quatFromEulerDegrees({-30, 45, 5});
  const glm::vec3 axis = glm::normalize(glm::vec3(0.3f, 1.0f, -0.2f));
  const glm::quat after = editAfterWorldRotation(edit, world, axis, 0.7f);
  const glm::quat expectedWorld = glm::angleAxis(0.7f, axis) * world;
  const glm::quat gotWorld = world * glm::inverse(edit) * after;
  EXPECT_NEAR(std::abs(glm::dot(expectedWorld, gotWorld)), 1.0f, 1e-5f);
  // No turn: the edit stays.
  EXPECT_NEAR(std::abs(glm::dot(editAfterWorldRotation(edit, world, axis, 0.0f), edit)), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace mq
