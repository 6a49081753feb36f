// Mean curvature per vertex: a sphere of radius R has H = 1/R everywhere.
#include <gtest/gtest.h>

#include "core/mesh/mean_curvature.h"
#include "icosphere_util.h"

namespace mq {
namespace {

TEST(MeanCurvature, SphereIsOneOverItsRadius) {
  for (float radius : {0.01f, 1.0f}) {
    const test::FlatMesh sphere = test::makeIcosphere(radius, 4, {0.3f, 1.2f, -0.1f});
    const std::vector<float> h = vertexMeanCurvature(sphere.positions, sphere.normals, sphere.triangles);
    ASSERT_EQ(h.size(), sphere.positions.size() / 3);
    for (float value : h) EXPECT_NEAR(value * radius, 1.0f, 0.01f);
  }
}

TEST(MeanCurvature, SmoothingRemovesASpikeAndKeepsTheSphere) {
  test::FlatMesh sphere = test::makeIcosphere(1.0f, 3);
  // One vertex pushed out: a spike of curvature at it and its ring.
  for (int c = 0; c < 3; ++c) sphere.positions[c] *= 1.05f;
  const std::vector<float> raw = vertexMeanCurvature(sphere.positions, sphere.normals, sphere.triangles);
  const std::vector<float> smooth = vertexMeanCurvature(sphere.positions, sphere.normals, sphere.triangles, 2);
  EXPECT_GT(raw[0], 2.0f);
  for (size_t v = 0; v < smooth.size(); ++v) EXPECT_NEAR(smooth[v], 1.0f, 0.2f) << v;
}

TEST(MeanCurvature, InwardNormalsGiveNegativeCurvature) {
  test::FlatMesh sphere = test::makeIcosphere(0.5f, 3);
  for (float& n : sphere.normals) n = -n;
  for (float value : vertexMeanCurvature(sphere.positions, sphere.normals, sphere.triangles))
    EXPECT_NEAR(value, -2.0f, 0.03f);
}

TEST(MeanCurvature, SplitSeamIsWeldedAndOpenBoundaryIsZero) {
  // The sphere with one vertex duplicated (a uv seam): the same curvature.
  test::FlatMesh sphere = test::makeIcosphere(1.0f, 3);
  const uint32_t twin = uint32_t(sphere.positions.size() / 3);
  for (int c = 0; c < 3; ++c) sphere.positions.push_back(sphere.positions[c]);
  for (int c = 0; c < 3; ++c) sphere.normals.push_back(sphere.normals[c]);
  int moved = 0;
  for (size_t i = 0; i < sphere.triangles.size() && moved < 2; i += 3)
    for (int k = 0; k < 3; ++k)
      if (sphere.triangles[i + k] == 0) {
        sphere.triangles[i + k] = twin;
        ++moved;
      }
  const std::vector<float> h = vertexMeanCurvature(sphere.positions, sphere.normals, sphere.triangles);
  EXPECT_NEAR(h[0], 1.0f, 0.02f);
  EXPECT_NEAR(h[twin], 1.0f, 0.02f);
  // A single triangle is all boundary.
  const std::vector<float> flat = {0, 0, 0, 1, 0, 0, 0, 1, 0}, up = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  for (float value : vertexMeanCurvature(flat, up, {0, 1, 2})) EXPECT_EQ(value, 0.0f);
}

}  // namespace
}  // namespace mq
