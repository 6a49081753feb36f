// The signed distance grid of a triangle mesh: exact near the surface,
// signed deep inside, positive beside an open border, and a push-out that
// lands at the margin.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/mesh/mesh_distance_field.h"
#include "icosphere_util.h"

namespace mq {
namespace {

constexpr float kRadius = 0.1f;

Aabb boxAround(float halfSide) { return {glm::vec3(-halfSide), glm::vec3(halfSide)}; }

TEST(MeshDistanceField, MatchesASpheresDistanceNearItsSurfaceAndKeepsTheSignDeepInside) {
  const test::FlatMesh sphere = test::makeIcosphere(kRadius, 4);
  const float cell = 0.004f, band = 0.016f;
  const MeshDistanceField field(sphere.positions, sphere.triangles, boxAround(0.15f), cell, band);
  // The faceted sphere lies within 0.2 mm of the round one at 4 subdivisions.
  for (const glm::vec3 direction : {glm::vec3(1, 0, 0), glm::normalize(glm::vec3(1, 2, -3)), glm::vec3(0, -1, 0)})
    for (const float r : {0.09f, 0.095f, 0.1f, 0.105f, 0.11f}) {
      EXPECT_NEAR(field.distance(r * direction), r - kRadius, 0.6e-3f) << r;
      if (std::abs(r - kRadius) > 0.002f) {
        EXPECT_GT(glm::dot(field.outward(r * direction), direction), 0.98f) << r;
      }
    }
  EXPECT_FLOAT_EQ(field.distance(glm::vec3(0.0f)), -band);       // the centre: past the band, inside
  EXPECT_FLOAT_EQ(field.distance(glm::vec3(0.14f)), band);       // a corner of the box: outside
  EXPECT_FLOAT_EQ(field.distance(glm::vec3(0.5f, 0, 0)), band);  // beyond the region
}

TEST(MeshDistanceField, PushOutLandsAtTheMarginAndLeavesOutsidePointsAlone) {
  const test::FlatMesh sphere = test::makeIcosphere(kRadius, 4);
  const MeshDistanceField field(sphere.positions, sphere.triangles, boxAround(0.15f), 0.004f, 0.016f);
  const float margin = 0.002f;
  for (const float r : {0.092f, 0.099f, 0.1005f}) {
    const glm::vec3 direction = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
    glm::vec3 p = r * direction, normal(0.0f);
    ASSERT_TRUE(field.pushOut(p, margin, &normal)) << r;
    EXPECT_GE(field.distance(p), margin - 1e-5f) << r;
    EXPECT_NEAR(glm::length(p), kRadius + margin, 0.7e-3f) << r;
    EXPECT_GT(glm::dot(normal, direction), 0.98f) << r;
  }
  glm::vec3 outside(0.0f, 0.11f, 0.0f);
  EXPECT_FALSE(field.pushOut(outside, margin));
  EXPECT_EQ(outside, glm::vec3(0.0f, 0.11f, 0.0f));
}

// A hemisphere open at its rim (a scan cut at the neck): points beside the
// rim, below the cut, are outside; points under the dome are inside.
TEST(MeshDistanceField, AnOpenBorderIsNotAWall) {
  const test::FlatMesh sphere = test::makeIcosphere(kRadius, 4);
  test::FlatMesh dome;
  dome.positions = sphere.positions;
  for (size_t t = 0; t < sphere.triangles.size(); t += 3) {
    bool upper = true;
    for (int k = 0; k < 3; ++k) upper = upper && sphere.positions[3 * sphere.triangles[t + k] + 1] > 0.0f;
    if (upper) dome.triangles.insert(dome.triangles.end(), &sphere.triangles[t], &sphere.triangles[t] + 3);
  }
  const MeshDistanceField field(dome.positions, dome.triangles, boxAround(0.15f), 0.004f, 0.016f);
  EXPECT_LT(field.distance({0.0f, 0.095f, 0.0f}), -0.004f);  // under the top of the dome
  EXPECT_GT(field.distance({0.0f, 0.11f, 0.0f}), 0.008f);    // above it
  // Below the rim, just outside and just inside the cut: both beside an open
  // border, so both outside.
  EXPECT_GT(field.distance({0.105f, -0.006f, 0.0f}), 0.0f);
  EXPECT_GT(field.distance({0.095f, -0.006f, 0.0f}), 0.0f);
}

// A mesh whose faces each have their own copies of their corners (as
// exporters write flat-shaded or UV-split meshes) is welded: its edges are
// no border. Seen from a concave side (a cube turned inside out: its inside
// is the world around it), points beside an edge have it as their closest
// point, and a border there would read as outside.
TEST(MeshDistanceField, EdgesSplitByTheExporterAreNoBorder) {
  test::FlatMesh cube;
  const float h = 0.05f;
  for (int axis = 0; axis < 3; ++axis)
    for (const float side : {-1.0f, 1.0f}) {
      const uint32_t first = uint32_t(cube.positions.size() / 3);
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (const glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        glm::vec3 p(0.0f);
        p[axis] = side * h;
        p[u] = corner.x * h;
        p[v] = corner.y * h;
        cube.positions.insert(cube.positions.end(), {p.x, p.y, p.z});
      }
      // Wound so that the normal points into the cube: turned inside out.
      const std::vector<uint32_t> quad =
          side > 0.0f ? std::vector<uint32_t>{0, 2, 1, 0, 3, 2} : std::vector<uint32_t>{0, 1, 2, 0, 2, 3};
      for (const uint32_t k : quad) cube.triangles.push_back(first + k);
    }
  const MeshDistanceField field(cube.positions, cube.triangles, boxAround(0.09f), 0.002f, 0.016f);
  EXPECT_GT(field.distance(glm::vec3(0.0f, 0.04f, 0.0f)), 0.008f);  // in the cube: outside the inverted surface
  for (const glm::vec3 p :
       {glm::vec3(0.056f, 0.056f, 0.0f), glm::vec3(0.0f, -0.056f, 0.056f), glm::vec3(-0.056f, 0.01f, -0.056f)})
    EXPECT_NEAR(field.distance(p), -0.006f * std::sqrt(2.0f), 0.5e-3f) << p.x << " " << p.y << " " << p.z;
}

}  // namespace
}  // namespace mq
