#include <gtest/gtest.h>

#include "core/mesh/mesh_checks.h"

namespace mq {
namespace {

struct SoupMesh {
  std::vector<float> positions;
  std::vector<uint32_t> triangles;
  size_t vertexCount() const { return positions.size() / 3; }
};

// Unit cube [0,1]^3, 12 triangles wound counter-clockwise from outside.
SoupMesh cube(float x0 = 0.0f) {
  SoupMesh m;
  for (int i = 0; i < 8; ++i)
    m.positions.insert(m.positions.end(), {x0 + float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)});
  m.triangles = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  return m;
}

SoupMesh merged(const SoupMesh& a, const SoupMesh& b) {
  SoupMesh m = a;
  const uint32_t offset = uint32_t(a.vertexCount());
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  for (uint32_t i : b.triangles) m.triangles.push_back(i + offset);
  return m;
}

TEST(MeshChecks, CubeIsAClosedManifoldOfUnitVolume) {
  const SoupMesh m = cube();
  const MeshTopologyReport r = checkTopology(m.vertexCount(), m.triangles);
  EXPECT_TRUE(r.closedManifold());
  EXPECT_EQ(r.edges, 18u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_NEAR(signedVolume(m.positions, m.triangles), 1.0, 1e-9);
  EXPECT_TRUE(selfIntersections(m.positions, m.triangles).empty());
}

TEST(MeshChecks, MissingTriangleLeavesBoundaryEdges) {
  SoupMesh m = cube();
  m.triangles.resize(m.triangles.size() - 3);
  const MeshTopologyReport r = checkTopology(m.vertexCount(), m.triangles);
  EXPECT_EQ(r.boundaryEdges, 3u);
  EXPECT_FALSE(r.closedManifold());
}

TEST(MeshChecks, FlippedTriangleIsMisoriented) {
  SoupMesh m = cube();
  std::swap(m.triangles[0], m.triangles[1]);
  const MeshTopologyReport r = checkTopology(m.vertexCount(), m.triangles);
  EXPECT_EQ(r.misorientedEdges, 3u);
  EXPECT_EQ(r.boundaryEdges, 0u);
}

TEST(MeshChecks, InsideOutCubeHasNegativeVolume) {
  SoupMesh m = cube();
  for (size_t t = 0; t < m.triangles.size(); t += 3) std::swap(m.triangles[t], m.triangles[t + 1]);
  EXPECT_NEAR(signedVolume(m.positions, m.triangles), -1.0, 1e-9);
  EXPECT_TRUE(checkTopology(m.vertexCount(), m.triangles).closedManifold());
}

TEST(MeshChecks, CubesSharingOnlyACornerMakeANonManifoldVertex) {
  SoupMesh a = cube(), b = cube(1.0f);
  // Move b so that its corner 0 lands on a's corner 7, then weld them.
  for (size_t v = 0; v < b.vertexCount(); ++v) b.positions[3 * v + 1] += 1.0f, b.positions[3 * v + 2] += 1.0f;
  SoupMesh m = merged(a, b);
  for (uint32_t& i : m.triangles)
    if (i == 8) i = 7;
  const MeshTopologyReport r = checkTopology(m.vertexCount(), m.triangles);
  EXPECT_EQ(r.nonManifoldVertices, 1u);
  EXPECT_EQ(r.isolatedVertices, 1u);  // the welded-away vertex 8
  EXPECT_EQ(r.boundaryEdges, 0u);
  EXPECT_EQ(r.components, 1u);
}

TEST(MeshChecks, FinEdgeIsOverShared) {
  SoupMesh m = cube();
  m.positions.insert(m.positions.end(), {0.5f, -1.0f, 0.5f});
  m.triangles.insert(m.triangles.end(), {0, 1, 8});
  EXPECT_EQ(checkTopology(m.vertexCount(), m.triangles).overSharedEdges, 1u);
}

TEST(MeshChecks, OverlappingCubesIntersectAndSeparateOnesDoNot) {
  SoupMesh apart = merged(cube(), cube(1.5f));
  EXPECT_EQ(checkTopology(apart.vertexCount(), apart.triangles).components, 2u);
  EXPECT_TRUE(selfIntersections(apart.positions, apart.triangles).empty());
  SoupMesh overlapping = merged(cube(), cube(0.5f));
  EXPECT_FALSE(selfIntersections(overlapping.positions, overlapping.triangles).empty());
}

}  // namespace
}  // namespace mq
