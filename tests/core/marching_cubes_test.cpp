#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "core/mesh/marching_cubes.h"
#include "core/mesh/mesh_checks.h"

namespace mq {
namespace {

ScalarGrid gridOf(int n, float cell, const std::function<float(const glm::vec3&)>& f) {
  ScalarGrid g;
  g.dims = glm::ivec3(n);
  g.cellSize = cell;
  g.origin = glm::vec3(-0.5f * cell * (n - 1));
  g.values.resize(size_t(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) g.values[g.index(i, j, k)] = f(g.point(i, j, k));
  return g;
}

TEST(MarchingCubes, SphereIsClosedOutwardAndAccurate) {
  const float r = 0.8f;
  const ScalarGrid g = gridOf(41, 0.05f, [&](const glm::vec3& p) { return glm::length(p) - r; });
  const IsoSurface s = extractIsoSurface(g, 0.0f);
  const MeshTopologyReport report = checkTopology(s.positions.size() / 3, s.triangles);
  EXPECT_TRUE(report.closedManifold());
  EXPECT_EQ(report.components, 1u);
  const double volume = signedVolume(s.positions, s.triangles);
  EXPECT_NEAR(volume / (4.0 / 3.0 * M_PI * r * r * r), 1.0, 0.02);
  for (size_t v = 0; v < s.positions.size(); v += 3)
    ASSERT_NEAR(std::hypot(s.positions[v], s.positions[v + 1], s.positions[v + 2]), r, 0.01f);
  EXPECT_TRUE(selfIntersections(s.positions, s.triangles).empty());
}

// Random samples make every face and cube ambiguity appear many times; the
// face-consistent contouring must still close up into a manifold.
TEST(MarchingCubes, RandomFieldsGiveClosedManifolds) {
  std::mt19937 rng(12111);
  std::uniform_real_distribution<float> noise(-1.0f, 1.0f);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 12;
    ScalarGrid g = gridOf(n, 1.0f, [&](const glm::vec3&) { return noise(rng); });
    // Outside on the border so the surface cannot leave the grid.
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          if (i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 || k == n - 1) g.values[g.index(i, j, k)] = 1.0f;
    const IsoSurface s = extractIsoSurface(g, 0.0f);
    ASSERT_FALSE(s.triangles.empty());
    const MeshTopologyReport report = checkTopology(s.positions.size() / 3, s.triangles);
    ASSERT_TRUE(report.closedManifold()) << "trial " << trial << ": boundary " << report.boundaryEdges
                                         << ", misoriented " << report.misorientedEdges << ", non-manifold vertices "
                                         << report.nonManifoldVertices;
    EXPECT_GT(signedVolume(s.positions, s.triangles), 0.0);
  }
}

TEST(MarchingCubes, EmptyAndFullGridsGiveNothing) {
  EXPECT_TRUE(extractIsoSurface(gridOf(5, 1.0f, [](const glm::vec3&) { return 1.0f; }), 0.0f).triangles.empty());
  EXPECT_TRUE(extractIsoSurface(gridOf(5, 1.0f, [](const glm::vec3&) { return -1.0f; }), 0.0f).triangles.empty());
}

}  // namespace
}  // namespace mq
