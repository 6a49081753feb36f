// Sewing patterns in and out of DXF: Mannequin's own files come back whole
// (panels within 0.01 mm, edge names, seams, placements), outlines another
// program drew become panels, and a broken or hostile file gets a clear error.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/character/default_mannequin.h"
#include "core/garment/garment.h"
#include "core/garment/parametric_garments.h"
#include "core/garment/pattern_dxf.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "garment_test_util.h"

namespace mq {
namespace {

constexpr float kRoundTrip = 0.00001f;  // metres: 0.01 mm

const Character& mannequin() {
  static const Character character = makeDefaultMannequin();
  return character;
}

std::string scratchPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("mq_dxf_test_" + name)).string();
}

Garment roundTrip(const Garment& garment, float allowance = 0.0f) {
  const std::string path = scratchPath(garment.name + ".dxf");
  writePatternDxf(path, garment, {allowance});
  Garment back = readPatternDxf(path);
  std::filesystem::remove(path);
  return back;
}

void expectSamePattern(const Garment& a, const Garment& b) {
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.panels.size(), b.panels.size());
  for (size_t p = 0; p < a.panels.size(); ++p) {
    const Panel &pa = a.panels[p], &pb = b.panels[p];
    SCOPED_TRACE(pa.name);
    EXPECT_EQ(pa.name, pb.name);
    ASSERT_EQ(pa.edgeCount(), pb.edgeCount());
    for (int e = 0; e < pa.edgeCount(); ++e) {
      EXPECT_EQ(pa.edges[e].name, pb.edges[e].name);
      EXPECT_LT(glm::length(pa.corners[e] - pb.corners[e]), kRoundTrip);
      ASSERT_EQ(pa.edges[e].shape, pb.edges[e].shape) << pa.edges[e].name;
      const int controls = pa.edges[e].shape == EdgeShape::Cubic ? 2 : pa.edges[e].shape == EdgeShape::Quadratic;
      for (int c = 0; c < controls; ++c)
        EXPECT_LT(glm::length(pa.edges[e].control[c] - pb.edges[e].control[c]), kRoundTrip);
    }
    EXPECT_EQ(pa.placement.shape, pb.placement.shape);
    EXPECT_EQ(pa.placement.bone, pb.placement.bone);
    EXPECT_LT(glm::length(pa.placement.center - pb.placement.center), 1e-6f);
    EXPECT_LT(glm::length(pa.placement.facing - pb.placement.facing), 1e-6f);
    EXPECT_NEAR(pa.placement.radius, pb.placement.radius, 1e-6f);
  }
  ASSERT_EQ(a.seams.size(), b.seams.size());
  for (size_t s = 0; s < a.seams.size(); ++s) {
    EXPECT_EQ(a.seams[s].panelA + "." + a.seams[s].edgeA, b.seams[s].panelA + "." + b.seams[s].edgeA);
    EXPECT_EQ(a.seams[s].panelB + "." + a.seams[s].edgeB, b.seams[s].panelB + "." + b.seams[s].edgeB);
    EXPECT_EQ(a.seams[s].reversed, b.seams[s].reversed);
  }
}

TEST(PatternDxf, EveryBuiltInGarmentComesBackWithin0_01mm) {
  for (const std::string& type : parametricGarmentTypes()) {
    SCOPED_TRACE(type);
    const Garment garment = makeParametricGarment(type, mannequin());
    expectSamePattern(garment, roundTrip(garment));
  }
}

TEST(PatternDxf, TheSeamAllowanceChangesTheBoundaryNotThePanels) {
  const Garment shirt = makeParametricGarment("tshirt", mannequin());
  expectSamePattern(shirt, roundTrip(shirt, 0.01f));
  const std::string path = scratchPath("allowance.dxf");
  writePatternDxf(path, shirt, {0.01f});
  EXPECT_NE(readFileText(path).find("$INSUNITS"), std::string::npos);
  std::filesystem::remove(path);
}

TEST(PatternDxf, NamesWithSpacesAndASeamOnOnePanelSurvive) {
  Garment tube;
  tube.name = "a tube, rolled";
  tube.panels = {test::rectanglePanel("front piece", 0.4f, 0.6f)};
  tube.panels[0].edges[1].name = "right side";
  tube.seams = {{"front piece", "right side", "front piece", "left", true}};
  tube.panels[0].placement.shape = PanelPlacement::Shape::Cylinder;
  tube.panels[0].placement.bone = "upper spine";
  tube.panels[0].placement.radius = 0.15f;
  expectSamePattern(tube, roundTrip(tube));
}

// A closed polyline on layer 0, as a general CAD program draws a panel.
std::string polylineDxf(const std::vector<glm::dvec2>& points, const std::string& header = "") {
  std::ostringstream out;
  out << "0\nSECTION\n2\nHEADER\n"
      << header << "0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\n0\n90\n"
      << points.size() << "\n70\n1\n";
  for (glm::dvec2 p : points) out << "10\n" << p.x << "\n20\n" << p.y << "\n";
  out << "0\nENDSEC\n0\nEOF\n";
  return out.str();
}

TEST(PatternDxf, AClosedPolylineFromElsewhereIsAPanelWithStraightEdges) {
  // Clockwise, in millimetres: comes back counter-clockwise, in metres.
  const Garment g = patternFromDxf(polylineDxf({{0, 0}, {0, 300}, {200, 300}, {200, 0}}), "square");
  EXPECT_EQ(g.name, "square");
  ASSERT_EQ(g.panels.size(), 1u);
  const Panel& panel = g.panels[0];
  EXPECT_EQ(panel.edgeCount(), 4);
  EXPECT_NEAR(panel.area(), 0.06f, 1e-6f);  // counter-clockwise: positive
  for (const PanelEdge& edge : panel.edges) EXPECT_EQ(edge.shape, EdgeShape::Line);
  EXPECT_EQ(panel.edges[0].name, "e0");
  EXPECT_TRUE(g.seams.empty());
}

TEST(PatternDxf, InchesAreConverted) {
  const Garment g = patternFromDxf(polylineDxf({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, "9\n$INSUNITS\n70\n1\n"));
  EXPECT_NEAR(g.panels[0].area(), 0.254f * 0.254f, 1e-6f);
}

TEST(PatternDxf, ACurvedOutlineIsFittedWithBeziersWithinHalfAMillimetre) {
  // A 20 cm half circle over a straight 40 cm base, 200 segments.
  std::vector<glm::dvec2> points;
  for (int i = 0; i <= 200; ++i) {
    const double a = M_PI * i / 200.0;
    points.push_back({200.0 * std::cos(a), 200.0 * std::sin(a)});
  }
  const Garment g = patternFromDxf(polylineDxf(points));
  const Panel& panel = g.panels[0];
  EXPECT_LT(panel.edgeCount(), 20);  // curves, not 201 segments
  int curves = 0;
  for (const PanelEdge& edge : panel.edges) curves += edge.shape == EdgeShape::Cubic;
  EXPECT_GE(curves, 1);
  for (glm::vec2 p : panel.outline(0.002f)) {
    const float radius = glm::length(p);
    const float off = p.y < 1e-5f ? 0.0f : std::abs(radius - 0.2f);  // the base, or the arc
    EXPECT_LT(off, 0.0005f) << p.x << " " << p.y;
  }
}

std::string errorOf(const std::string& dxf) {
  try {
    patternFromDxf(dxf);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(PatternDxf, BrokenFilesGetClearErrors) {
  EXPECT_NE(errorOf("hello\nworld\n").find("not an ASCII DXF file"), std::string::npos) << errorOf("hello\nworld\n");
  const std::string square = polylineDxf({{0, 0}, {100, 0}, {100, 100}, {0, 100}});
  EXPECT_NE(errorOf(square.substr(0, square.size() / 2)).find("truncated"), std::string::npos);
  const std::string lines = "0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n0\n10\n0\n20\n0\n11\n5\n21\n5\n0\nENDSEC\n0\nEOF\n";
  EXPECT_NE(errorOf(lines).find("not a sewing pattern: no closed outline"), std::string::npos) << errorOf(lines);
  const std::string open = "0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n14\n10\n0\n20\n0\n11\n5\n21\n5\n0\nENDSEC\n0\nEOF\n";
  EXPECT_NE(errorOf(open).find("an outline on layer 14 does not close"), std::string::npos) << errorOf(open);
  std::string hostile = square;
  hostile.replace(hostile.find("90\n4\n"), 5, "90\n99999999\n");
  EXPECT_NE(errorOf(hostile).find("LWPOLYLINE gives a count of 99999999"), std::string::npos) << errorOf(hostile);
  // Found by fuzzing: dxflib reads on past an EOF marker, so the counts after one are checked too (a count
  // too large for an int made it free its vertex array twice).
  const std::string afterEof = square + hostile;
  EXPECT_NE(errorOf(afterEof).find("LWPOLYLINE gives a count of 99999999"), std::string::npos) << errorOf(afterEof);
  EXPECT_NE(errorOf(polylineDxf({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "9\n$INSUNITS\n70\n3\n")).find("unsupported"),
            std::string::npos);
  // Found by fuzzing: a closed polyline of two corners (one side a bulge arc, the other straight back).
  const std::string twoCorners = polylineDxf({{0, 0}, {100, 0}});
  EXPECT_NE(errorOf(twoCorners).find("encloses no area"), std::string::npos) << errorOf(twoCorners);
  // Found by fuzzing: a centred text without its alignment point (dxflib gives NaN) stands at its
  // insertion point.
  std::string text = square;
  text.insert(text.find("0\nENDSEC\n0\nEOF"), "0\nTEXT\n8\n14\n10\n5\n20\n5\n40\n2\n1\nPiece Name: front\n72\n1\n");
  EXPECT_EQ(errorOf(text), "");
  EXPECT_EQ(patternFromDxf(text).panels[0].name, "front");
}

// 100,000 sew lines between the same two points: chained through a grid of
// their ends (it used to compare every line with every other one, about 10^10
// steps), and refused for the pieces they make.
TEST(PatternDxf, ManyLinesAtOnePointAreChainedInLinearTime) {
  std::ostringstream out;
  out << "0\nSECTION\n2\nENTITIES\n";
  for (int i = 0; i < 100000; ++i) out << "0\nLINE\n8\n14\n10\n0\n20\n0\n11\n100\n21\n0\n";
  out << "0\nENDSEC\n0\nEOF\n";
  const std::string error = errorOf(out.str());
  EXPECT_NE(error.find("more than 500 pattern pieces"), std::string::npos) << error;
}

TEST(PatternDxf, ReadingNamesTheFile) {
  const std::string path = scratchPath("broken.dxf");
  { std::ofstream(path) << "0\nSECTION\n"; }
  try {
    readPatternDxf(path);
    ADD_FAILURE() << "read a truncated DXF";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.dxf"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

TEST(PatternDxf, AFailedWriteLeavesTheOldFile) {
  const std::string path = scratchPath("kept.dxf");
  { std::ofstream(path) << "old"; }
  Garment bad;
  bad.name = "bad";
  bad.panels = {test::rectanglePanel("a", 0.1f, 0.1f)};
  EXPECT_THROW(writePatternDxf(path, bad, {-1.0f}), Error);
  EXPECT_EQ(readFileText(path), "old");
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace mq
