// Seam pairing (resampling both sides to matching vertices) and welding.
#include <gtest/gtest.h>

#include "core/garment/garment.h"
#include "core/garment/seam.h"
#include "core/garment/seam_weld.h"
#include "core/util/error.h"

#include <map>

#include "garment_test_util.h"

namespace mq {
namespace {

Panel rectangle(const std::string& name, float w, float h) { return test::rectanglePanel(name, w, h); }

float normalisedArc(const PanelMesh& mesh, int edge, uint32_t vertex) {
  const std::vector<uint32_t>& along = mesh.edgeVertices[edge];
  for (size_t i = 0; i < along.size(); ++i)
    if (along[i] == vertex) return mesh.edgeArcLengths[edge][i] / mesh.edgeArcLengths[edge].back();
  return -1.0f;
}

TEST(GarmentSeam, SidesWithDifferentCountsArePairedAtMatchingArcLength) {
  // Right edge of A (going up, 0.4 m, 8 segments) sewn to left edge of B
  // (going down, 0.5 m, 13 segments): B's edge runs opposite, so reversed.
  Panel a = rectangle("a", 0.3f, 0.4f), b = rectangle("b", 0.3f, 0.5f);
  PanelMesh ma = meshPanel(a, {0.05f, {0, 8, 0, 0}}), mb = meshPanel(b, {0.05f, {0, 0, 0, 13}});
  size_t verticesBefore = ma.vertexCount() + mb.vertexCount();
  std::vector<VertexPair> pairs = pairSeamVertices(ma, 1, mb, 3, true, 0.3f * 0.05f);
  EXPECT_EQ(ma.edgeVertices[1].size(), mb.edgeVertices[3].size());
  EXPECT_EQ(pairs.size(), ma.edgeVertices[1].size());
  EXPECT_GT(ma.vertexCount() + mb.vertexCount(), verticesBefore);  // A needed extra vertices
  for (auto [va, vb] : pairs) {
    float ta = normalisedArc(ma, 1, va), tb = normalisedArc(mb, 3, vb);
    ASSERT_GE(ta, 0.0f);
    ASSERT_GE(tb, 0.0f);
    EXPECT_NEAR(ta, 1.0f - tb, 0.3f * 0.05f / 0.4f + 1e-4f);  // within the match distance
  }
  // The ends pair corner with corner: A's bottom-right with B's bottom-left.
  EXPECT_EQ(ma.vertices[pairs.front().first], glm::vec2(0.3f, 0.0f));
  EXPECT_EQ(mb.vertices[pairs.front().second], glm::vec2(0.0f, 0.0f));
  EXPECT_EQ(ma.vertices[pairs.back().first], glm::vec2(0.3f, 0.4f));
  EXPECT_EQ(mb.vertices[pairs.back().second], glm::vec2(0.0f, 0.5f));
  // Inserting vertices kept both meshes whole.
  EXPECT_NEAR(ma.area(), 0.12f, 1e-5f);
  EXPECT_NEAR(mb.area(), 0.15f, 1e-5f);
}

TEST(GarmentSeam, NotReversedPairsStartWithStart) {
  Panel a = rectangle("a", 0.2f, 0.2f), b = rectangle("b", 0.2f, 0.2f);
  PanelMesh ma = meshPanel(a, {0.05f, {}}), mb = meshPanel(b, {0.05f, {}});
  std::vector<VertexPair> pairs = pairSeamVertices(ma, 0, mb, 0, false, 0.015f);
  ASSERT_EQ(pairs.size(), ma.edgeVertices[0].size());
  ASSERT_EQ(pairs.size(), mb.edgeVertices[0].size());
  ASSERT_GE(pairs.size(), 5u);
  for (auto [va, vb] : pairs) EXPECT_NEAR(ma.vertices[va].x, mb.vertices[vb].x, 1e-6f);
}

Garment tube() {
  // One panel sewn to itself: a tube (like a sleeve's underarm seam).
  Garment g;
  g.name = "tube";
  g.targetEdgeLength = 0.03f;
  Panel p = rectangle("sheet", 0.6f, 0.3f);
  p.placement.shape = PanelPlacement::Shape::Cylinder;
  p.placement.radius = 0.6f / (2.0f * float(M_PI));
  p.placement.anchor = {0.3f, 0.0f};
  g.panels.push_back(p);
  g.seams.push_back({"sheet", "right", "sheet", "left", true});
  return g;
}

TEST(GarmentSeam, GarmentMeshPairsSeamsAndWeldClosesThem) {
  GarmentMesh mesh = buildGarmentMesh(tube());
  ASSERT_GE(mesh.seamPairs.size(), 11u);  // 0.3 m at 0.03 m: 10 segments or more
  // Wrapped exactly once around the cylinder, the sewn edges already coincide.
  for (auto [a, b] : mesh.seamPairs) EXPECT_LT(glm::length(mesh.position(a) - mesh.position(b)), 1e-4f);
  SeamWeld weld = computeSeamWeld(mesh.vertexCount(), mesh.seamPairs);
  EXPECT_EQ(weld.mergedAway(), mesh.seamPairs.size());
  for (auto [a, b] : mesh.seamPairs) EXPECT_EQ(weld.newIndex[a], weld.newIndex[b]);
  std::vector<float> positions = weldAverage(weld, mesh.positions, 3);
  std::vector<uint32_t> triangles = weldTriangles(weld, mesh.triangles);
  EXPECT_EQ(triangles.size(), mesh.triangles.size());  // no triangle spans the seam
  for (uint32_t i : triangles) EXPECT_LT(i, weld.newVertexCount());
  // The welded tube is closed: every edge has two triangles except at the two rims.
  std::map<std::pair<uint32_t, uint32_t>, int> edgeUse;
  for (size_t t = 0; t < triangles.size(); t += 3)
    for (int i = 0; i < 3; ++i) {
      uint32_t u = triangles[t + i], v = triangles[t + (i + 1) % 3];
      ++edgeUse[{std::min(u, v), std::max(u, v)}];
    }
  int boundary = 0;
  for (auto& [edge, count] : edgeUse) {
    EXPECT_LE(count, 2);
    if (count != 1) continue;
    ++boundary;
    // Open edges lie on the rims (y = 0 or 0.3), none along the welded seam.
    for (uint32_t v : {edge.first, edge.second}) {
      float y = positions[3 * v + 1];
      EXPECT_TRUE(std::abs(y) < 1e-5f || std::abs(y - 0.3f) < 1e-5f) << y;
    }
  }
  EXPECT_GE(boundary, 2 * 20);  // two rims of 0.6 m at 0.03 m
}

TEST(GarmentSeam, WeldMergesChainsTransitively) {
  SeamWeld weld = computeSeamWeld(5, {{0, 3}, {3, 4}});
  EXPECT_EQ(weld.newVertexCount(), 3u);
  EXPECT_EQ(weld.newIndex[0], weld.newIndex[4]);
  EXPECT_EQ(weld.groupSize[weld.newIndex[0]], 3u);
  std::vector<float> mass = weldSum(weld, {1, 2, 3, 4, 5});
  EXPECT_FLOAT_EQ(mass[weld.newIndex[0]], 10.0f);
}

TEST(GarmentSeam, InvalidSeamsAreRejected) {
  Garment g = tube();
  g.seams.push_back({"sheet", "right", "sheet", "top", true});  // "right" sewn twice
  EXPECT_THROW(g.validate(), Error);
  g = tube();
  g.seams[0].edgeB = "nope";
  EXPECT_THROW(g.validate(), Error);
}

}  // namespace
}  // namespace mq
