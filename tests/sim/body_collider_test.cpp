// The body collider's inside/outside test near edges and vertices of a
// non-convex closed mesh: an L-shaped prism, whose notch has a reflex edge
// and saddle-like corners where a nearest triangle's own normal can point
// either way.
#include <gtest/gtest.h>

#include <random>

#include "sim/cloth/collision/body_collider.h"

namespace mq::cloth {
namespace {

constexpr float kUnit = 0.05f;  // m; the L is 2 x 2 units, 1 unit thick

// The L polygon in the xy plane, counter-clockwise, extruded along z from 0 to kUnit.
void lPrism(std::vector<float>& positions, std::vector<uint32_t>& triangles) {
  const float corners[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (float z : {0.0f, 1.0f})
    for (const auto& c : corners) positions.insert(positions.end(), {kUnit * c[0], kUnit * c[1], kUnit * z});
  // Caps: a fan from corner 0, which sees every other corner.
  for (uint32_t i = 1; i + 1 < 6; ++i) {
    triangles.insert(triangles.end(), {0, i + 1, i});          // bottom, facing -z
    triangles.insert(triangles.end(), {6, 6 + i, 6 + i + 1});  // top, facing +z
  }
  for (uint32_t i = 0; i < 6; ++i) {
    const uint32_t j = (i + 1) % 6;
    triangles.insert(triangles.end(), {i, j, 6 + j, i, 6 + j, 6 + i});
  }
}

bool insideL(const glm::vec3& p) {
  const glm::vec3 u = p / kUnit;
  if (u.z <= 0.0f || u.z >= 1.0f || u.x <= 0.0f || u.y <= 0.0f) return false;
  return (u.x < 2.0f && u.y < 1.0f) || (u.x < 1.0f && u.y < 2.0f);
}

TEST(BodyCollider, TellsInsideFromOutsideNearEdgesAndCornersOfANonConvexBody) {
  std::vector<float> positions;
  std::vector<uint32_t> triangles;
  lPrism(positions, triangles);
  BodyCollider body;
  body.setMesh(positions, triangles, 0.02f);
  // Points around the notch's corners and reflex edge, and the outer corners.
  std::mt19937 random(7);
  std::uniform_real_distribution<float> offset(-0.4f, 0.4f);
  const glm::vec3 spots[] = {{1, 1, 1}, {1, 1, 0}, {1, 1, 0.5f}, {2, 1, 1}, {1, 2, 1}, {0, 0, 1}, {2, 0, 0}};
  int checked = 0, wrong = 0;
  for (const glm::vec3& spot : spots)
    for (int k = 0; k < 4000; ++k) {
      const glm::vec3 p = kUnit * (spot + glm::vec3(offset(random), offset(random), offset(random)));
      BodyContact contact;
      if (!body.nearestContact(p, contact) || std::abs(contact.signedDistance) < 1e-5f) continue;
      ++checked;
      wrong += (contact.signedDistance < 0.0f) != insideL(p);
    }
  EXPECT_GT(checked, 20000);
  EXPECT_EQ(wrong, 0) << "of " << checked;
}

TEST(BodyCollider, PushesOutAlongTheShortestWayToTheSurface) {
  std::vector<float> positions;
  std::vector<uint32_t> triangles;
  lPrism(positions, triangles);
  BodyCollider body;
  body.setMesh(positions, triangles, 0.02f);
  // Just inside the reflex edge of the notch: out is diagonal, into the notch.
  const glm::vec3 p = kUnit * glm::vec3(0.95f, 0.95f, 0.5f);
  BodyContact contact;
  ASSERT_TRUE(body.nearestContact(p, contact));
  EXPECT_LT(contact.signedDistance, 0.0f);
  EXPECT_NEAR(contact.normal.x, std::sqrt(0.5f), 1e-3f);
  EXPECT_NEAR(contact.normal.y, std::sqrt(0.5f), 1e-3f);
  EXPECT_NEAR(contact.normal.z, 0.0f, 1e-3f);
}

}  // namespace
}  // namespace mq::cloth
