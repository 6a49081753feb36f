// Oracle O24 (research brief §4): the inward ray-cast thickness of a sphere
// of radius R is its diameter 2R at every vertex, within 1 %.
#include <gtest/gtest.h>

#include "core/mesh/inward_thickness.h"
#include "core/mesh/triangle_ray_caster.h"
#include "icosphere_util.h"

namespace mq {
namespace {

TEST(InwardThickness, SphereIsItsDiameter) {
  for (float radius : {0.01f, 0.3f}) {
    const test::FlatMesh sphere = test::makeIcosphere(radius, 4, {0.1f, 0.9f, 0.0f});
    const std::vector<float> thickness = inwardThickness(sphere.positions, sphere.normals, sphere.triangles, -1.0f);
    for (float d : thickness) EXPECT_NEAR(d / (2.0f * radius), 1.0f, 0.01f);
  }
}

TEST(InwardThickness, TwoSpheresDoNotSeeEachOther) {
  // Rays go inward only: a second body beside the first changes nothing.
  test::FlatMesh a = test::makeIcosphere(0.05f, 3), b = test::makeIcosphere(0.2f, 3, {0.5f, 0.0f, 0.0f});
  const uint32_t offset = uint32_t(a.positions.size() / 3);
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
  for (uint32_t i : b.triangles) a.triangles.push_back(i + offset);
  const std::vector<float> thickness = inwardThickness(a.positions, a.normals, a.triangles, -1.0f);
  for (size_t v = 0; v < thickness.size(); ++v)
    EXPECT_NEAR(thickness[v], v < offset ? 0.1f : 0.4f, v < offset ? 0.001f : 0.004f);
}

TEST(InwardThickness, OpenMeshGivesTheMissingValue) {
  const std::vector<float> quad = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, up = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  for (float d : inwardThickness(quad, up, {0, 1, 2, 0, 2, 3}, 7.0f)) EXPECT_EQ(d, 7.0f);
}

TEST(TriangleRayCaster, NearestHitAndMisses) {
  // Two parallel unit squares at z = 1 and z = 3.
  const std::vector<float> p = {0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0, 0, 3, 1, 0, 3, 1, 1, 3, 0, 1, 3};
  const TriangleRayCaster caster(p, {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7});
  EXPECT_NEAR(caster.firstHit({0.3f, 0.6f, 0.0f}, {0, 0, 1}, 0.0f), 1.0f, 1e-6f);
  EXPECT_NEAR(caster.firstHit({0.3f, 0.6f, 0.0f}, {0, 0, 1}, 1.5f), 3.0f, 1e-6f);
  EXPECT_NEAR(caster.firstHit({0.3f, 0.6f, 4.0f}, {0, 0, -1}, 0.0f), 1.0f, 1e-6f);
  EXPECT_LT(caster.firstHit({2.0f, 0.5f, 0.0f}, {0, 0, 1}, 0.0f), 0.0f);
  EXPECT_LT(caster.firstHit({0.3f, 0.6f, 0.0f}, {0, 0, -1}, 0.0f), 0.0f);
}

}  // namespace
}  // namespace mq
