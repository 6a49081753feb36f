// Panel outlines and their CGAL meshing.
#include <gtest/gtest.h>

#include <cmath>

#include "core/garment/panel.h"
#include "core/garment/panel_mesher.h"
#include "core/util/error.h"
#include "garment_test_util.h"

namespace mq {
namespace {

Panel rectangle(float w, float h) { return test::rectanglePanel("rect", w, h); }

// An L-shaped (concave) panel with a curved top and a cubic side.
Panel curvedPanel() {
  Panel p;
  p.name = "curved";
  p.addLine("bottom", {0, 0});
  p.addLine("right", {0.5f, 0});
  p.addLine("inner", {0.5f, 0.2f});
  p.addCubic("side", {0.25f, 0.25f}, {0.3f, 0.3f}, {0.25f, 0.4f});
  p.addQuadratic("top", {0.25f, 0.5f}, {0.1f, 0.65f});
  p.addLine("left", {0, 0.5f});
  return p;
}

TEST(GarmentPanel, EdgeLengthsOfLinesAndCurves) {
  Panel p = rectangle(0.4f, 0.3f);
  EXPECT_NEAR(p.edgeLength(0), 0.4f, 1e-6f);
  EXPECT_NEAR(p.area(), 0.12f, 1e-6f);
  // A quadratic through a symmetric control point is longer than its chord.
  Panel c = curvedPanel();
  int top = c.findEdge("top");
  float chord = glm::length(c.edgeEnd(top) - c.edgeStart(top));
  EXPECT_GT(c.edgeLength(top), chord * 1.05f);
  // Equal arc-length samples: consecutive distances are equal.
  std::vector<glm::vec2> s = c.sampleEdge(top, 10);
  ASSERT_EQ(s.size(), 11u);
  float first = glm::length(s[1] - s[0]);
  for (size_t i = 1; i < 10; ++i) EXPECT_NEAR(glm::length(s[i + 1] - s[i]), first, 0.03f * first);
  EXPECT_EQ(s.front(), c.edgeStart(top));
  EXPECT_EQ(s.back(), c.edgeEnd(top));
}

TEST(GarmentPanel, ValidateRejectsClockwiseAndDuplicateNames) {
  Panel cw;
  cw.name = "cw";
  cw.addLine("a", {0, 0});
  cw.addLine("b", {0, 1});
  cw.addLine("c", {1, 1});
  EXPECT_THROW(cw.validate(), Error);
  Panel dup = rectangle(1, 1);
  dup.edges[1].name = "bottom";
  EXPECT_THROW(dup.validate(), Error);
}

std::string validationError(const Panel& panel) {
  try {
    panel.validate();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// Outlines the mesher cannot take (it crashed on a crossing outline, and a
// corner at 1e37 made the outline sampling run for minutes) are refused first.
TEST(GarmentPanel, ValidateRejectsCrossingAndFarOutlines) {
  EXPECT_EQ(validationError(rectangle(0.5f, 0.7f)), "");
  EXPECT_EQ(validationError(curvedPanel()), "");
  Panel bowtie = rectangle(1, 1);
  std::swap(bowtie.corners[2], bowtie.corners[3]);
  EXPECT_EQ(validationError(bowtie), "panel 'rect': outline crosses itself");
  Panel curveCrossing = curvedPanel();  // the cubic side bulges across the left edge
  curveCrossing.edges[3].control[0] = {-1.0f, 0.3f};
  EXPECT_EQ(validationError(curveCrossing), "panel 'curved': outline crosses itself");
  Panel far = rectangle(1, 1);
  far.corners[1].x = 1e37f;
  EXPECT_EQ(validationError(far), "panel 'rect': edge 1 has a point more than 10 m from the pattern's origin");
}

void expectMeshRespectsOutline(const Panel& panel, float target) {
  PanelMesh mesh = meshPanel(panel, {target, {}});
  ASSERT_GT(mesh.triangleCount(), 10u);
  float outlineArea = panel.area(0.001f);
  EXPECT_NEAR(mesh.area(), outlineArea, 0.01f * outlineArea) << panel.name;
  // The size criterion bounds every edge; CGAL's refinement keeps most well below.
  EXPECT_LE(mesh.maxEdgeLength(), target * 1.001f) << panel.name;
  EXPECT_GT(mesh.meanEdgeLength(), 0.45f * target) << panel.name;
  // Every triangle is counter-clockwise (faces the panel's outside).
  for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
    glm::vec2 a = mesh.vertices[mesh.triangles[t]], b = mesh.vertices[mesh.triangles[t + 1]],
              c = mesh.vertices[mesh.triangles[t + 2]];
    EXPECT_GT((b - a).x * (c - a).y - (b - a).y * (c - a).x, 0.0f);
  }
  // Boundary vertices per edge run from corner to corner with increasing arc length.
  ASSERT_EQ(mesh.edgeVertices.size(), size_t(panel.edgeCount()));
  for (int e = 0; e < panel.edgeCount(); ++e) {
    const std::vector<uint32_t>& along = mesh.edgeVertices[e];
    ASSERT_GE(along.size(), 2u);
    EXPECT_LT(glm::length(mesh.vertices[along.front()] - panel.edgeStart(e)), 1e-5f);
    EXPECT_LT(glm::length(mesh.vertices[along.back()] - panel.edgeEnd(e)), 1e-5f);
    for (size_t i = 1; i < along.size(); ++i) EXPECT_GT(mesh.edgeArcLengths[e][i], mesh.edgeArcLengths[e][i - 1]);
    EXPECT_NEAR(mesh.edgeArcLengths[e].back(), panel.edgeLength(e), 1e-5f);
  }
}

TEST(GarmentPanel, MeshOfRectangleMatchesAreaAndTarget) { expectMeshRespectsOutline(rectangle(0.5f, 0.7f), 0.02f); }

TEST(GarmentPanel, MeshOfConcaveCurvedPanelMatchesAreaAndTarget) {
  expectMeshRespectsOutline(curvedPanel(), 0.02f);
  expectMeshRespectsOutline(curvedPanel(), 0.05f);
}

TEST(GarmentPanel, FinerTargetGivesMoreTriangles) {
  size_t coarse = meshPanel(rectangle(0.5f, 0.5f), {0.04f, {}}).triangleCount();
  size_t fine = meshPanel(rectangle(0.5f, 0.5f), {0.02f, {}}).triangleCount();
  EXPECT_GT(fine, 3 * coarse);
}

TEST(GarmentPanel, EdgeSegmentOverrideSetsBoundaryCount) {
  PanelMeshOptions options{0.05f, {7, 0, 0, 0}};
  PanelMesh mesh = meshPanel(rectangle(0.3f, 0.3f), options);
  EXPECT_GE(mesh.edgeVertices[0].size(), 8u);  // 7 sampled pieces; the mesher may split one
}

TEST(GarmentPanel, SplitBoundaryKeepsAreaAndOrder) {
  PanelMesh mesh = meshPanel(rectangle(0.3f, 0.2f), {0.05f, {}});
  float area = mesh.area();
  size_t before = mesh.edgeVertices[0].size();
  float s = 0.5f * (mesh.edgeArcLengths[0][1] + mesh.edgeArcLengths[0][2]);
  uint32_t v = mesh.splitBoundary(0, 1, s);
  EXPECT_EQ(mesh.edgeVertices[0].size(), before + 1);
  EXPECT_EQ(mesh.edgeVertices[0][2], v);
  EXPECT_NEAR(mesh.vertices[v].x, s, 1e-6f);
  EXPECT_NEAR(mesh.area(), area, 1e-6f);
}

TEST(GarmentPanel, PlacementOnCylinderIsAnIsometry) {
  PanelPlacement placement;
  placement.shape = PanelPlacement::Shape::Cylinder;
  placement.center = {0, 1, 0};
  placement.radius = 0.2f;
  glm::vec3 a = placement.place({0, 0}), b = placement.place({0.2f * float(M_PI) / 2, 0});
  EXPECT_NEAR(glm::length(a - glm::vec3(0, 1, 0.2f)), 0.0f, 1e-6f);  // anchor faces +Z
  EXPECT_NEAR(glm::length(b - glm::vec3(0.2f, 1, 0)), 0.0f, 1e-5f);  // +u turns to +X (axis x facing)
  // Geodesic length of a pattern segment is kept: a small step keeps its length.
  glm::vec3 c = placement.place({0.1f, 0.05f}), d = placement.place({0.101f, 0.05f});
  EXPECT_NEAR(glm::length(d - c), 0.001f, 1e-6f);
}

TEST(GarmentPanel, InvalidTargetThrows) { EXPECT_THROW(meshPanel(rectangle(1, 1), {0.0f, {}}), Error); }

}  // namespace
}  // namespace mq
