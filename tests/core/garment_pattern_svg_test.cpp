// The sewing pattern as SVG: true scale, exact edges, the cutting line, the
// seam marks, and the sewn edges' lengths.
#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/garment/garment.h"
#include "core/garment/pattern_svg.h"
#include "core/util/error.h"
#include "garment_test_util.h"

namespace mq {
namespace {

Panel rectangle(const std::string& name, float width, float height) {
  return test::rectanglePanel(name, width, height);
}

// Two 40 x 60 cm panels, the right side of "a" sewn to the left side of "b".
Garment twoPanels() {
  Garment g;
  g.name = "tube";
  g.panels = {rectangle("a", 0.4f, 0.6f), rectangle("b", 0.4f, 0.6f)};
  g.seams = {{"a", "right", "b", "left", true}};
  return g;
}

std::vector<std::string> attributes(const std::string& svg, const std::string& element, const std::string& name) {
  std::vector<std::string> values;
  const std::regex pattern(element + R"([^>]*? )" + name + R"re(="([^"]*)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), pattern); it != std::sregex_iterator(); ++it)
    values.push_back((*it)[1]);
  return values;
}

// The d of every path of that class, in order.
std::vector<std::string> paths(const std::string& svg, const std::string& cls) {
  return attributes(svg, "<path class=\"" + cls + "\"", "d");
}

std::vector<float> numbers(const std::string& text) {
  std::vector<float> out;
  const std::regex number(R"(-?[0-9]+\.[0-9]+)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it)
    out.push_back(std::stof(it->str()));
  return out;
}

TEST(PatternSvg, PanelsAreLaidOutAtTrueScaleInMillimetres) {
  const std::string svg = patternSvg(twoPanels());
  // 20 mm margins, two 400 mm panels; a 24 mm title band above 600 mm of panel.
  EXPECT_NE(svg.find("width=\"860.000mm\" height=\"664.000mm\" viewBox=\"0 0 860.000 664.000\""), std::string::npos);
  const std::vector<std::string> sewing = paths(svg, "sew");
  ASSERT_EQ(sewing.size(), 2u);
  // Pattern v is up, the sheet's y is down: the corner (0, 0) is the bottom left.
  EXPECT_EQ(sewing[0], "M 20.000 644.000 L 420.000 644.000 L 420.000 44.000 L 20.000 44.000 L 20.000 644.000 Z");
  EXPECT_EQ(sewing[1], "M 440.000 644.000 L 840.000 644.000 L 840.000 44.000 L 440.000 44.000 L 440.000 644.000 Z");
  EXPECT_EQ(paths(svg, "cut").size(), 0u);
  EXPECT_EQ(paths(svg, "grain").size(), 2u);
}

TEST(PatternSvg, CurvedEdgesKeepTheirControlPoints) {
  Garment g;
  g.name = "cap";
  Panel p;
  p.name = "cap";
  p.addLine("base", {0.0f, 0.0f});
  p.addLine("side", {0.3f, 0.0f});
  p.addCubic("arc", {0.3f, 0.1f}, {0.3f, 0.3f}, {0.0f, 0.3f});
  g.panels = {p};
  const std::vector<std::string> sewing = paths(patternSvg(g), "sew");
  ASSERT_EQ(sewing.size(), 1u);
  const std::regex shape(R"(M \S+ \S+ L \S+ \S+ L \S+ \S+ C \S+ \S+ \S+ \S+ \S+ \S+ Z)");
  EXPECT_TRUE(std::regex_match(sewing[0], shape)) << sewing[0];
  // Relative to the first corner (0, 0): millimetres, y down.
  const std::vector<float> v = numbers(sewing[0]);
  ASSERT_EQ(v.size(), 12u);
  const float expected[12] = {0, 0, 300, 0, 300, -100, 300, -300, 0, -300, 0, 0};
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(v[i] - v[i % 2], expected[i], 0.001f) << i;
}

TEST(PatternSvg, TheCuttingLineIsTheAllowanceOutside) {
  PatternSvgOptions options;
  options.seamAllowance = 0.01f;
  const std::string svg = patternSvg(twoPanels(), options);
  const std::vector<std::string> cutting = paths(svg, "cut");
  ASSERT_EQ(cutting.size(), 2u);
  // A rectangle 10 mm larger on every side: four corners, the sewing line 10 mm inside.
  const std::vector<float> corners = numbers(cutting[0]);
  ASSERT_EQ(corners.size(), 8u) << cutting[0];
  float minX = 1e9f, maxX = -1e9f, minY = 1e9f, maxY = -1e9f;
  for (size_t i = 0; i < corners.size(); i += 2) {
    minX = std::min(minX, corners[i]), maxX = std::max(maxX, corners[i]);
    minY = std::min(minY, corners[i + 1]), maxY = std::max(maxY, corners[i + 1]);
  }
  EXPECT_NEAR(maxX - minX, 420.0f, 0.01f);
  EXPECT_NEAR(maxY - minY, 620.0f, 0.01f);
  const std::vector<float> sewing = numbers(paths(svg, "sew")[0]);
  EXPECT_NEAR(sewing[0] - minX, 10.0f, 0.01f);
  EXPECT_NEAR(maxY - sewing[1], 10.0f, 0.01f);
  // The sheet grows by the allowance on both sides of both panels.
  EXPECT_NE(svg.find("width=\"900.000mm\" height=\"684.000mm\""), std::string::npos);
}

TEST(PatternSvg, BothEdgesOfASeamCarryItsNotchAndNumber) {
  const std::string svg = patternSvg(twoPanels());
  const std::vector<std::string> seams = paths(svg, "seam");
  ASSERT_EQ(seams.size(), 2u);
  EXPECT_EQ(seams[0], "M 420.000 644.000 L 420.000 44.000");  // a.right
  EXPECT_EQ(seams[1], "M 440.000 44.000 L 440.000 644.000");  // b.left
  const std::vector<std::string> notches = paths(svg, "notch");
  ASSERT_EQ(notches.size(), 2u);
  // At the middle of each edge, 6 mm into its panel.
  EXPECT_EQ(notches[0], "M 420.000 344.000 L 414.000 344.000");
  EXPECT_EQ(notches[1], "M 440.000 344.000 L 446.000 344.000");
  EXPECT_EQ(attributes(svg, "<path class=\"seam\"", "stroke")[0], attributes(svg, "<path class=\"seam\"", "stroke")[1]);
  const std::regex label(R"(<text class="seam-label"[^>]*>1</text>)");
  EXPECT_EQ(std::distance(std::sregex_iterator(svg.begin(), svg.end(), label), std::sregex_iterator()), 2);
}

TEST(PatternSvg, NamesAreEscaped) {
  Garment g = twoPanels();
  g.name = "a<b & \"c\"";
  g.panels[0].name = "front<1>";
  g.seams[0].panelA = "front<1>";
  const std::string svg = patternSvg(g);
  EXPECT_NE(svg.find("<title>a&lt;b &amp; &quot;c&quot;: sewing pattern"), std::string::npos);
  EXPECT_NE(svg.find(">front&lt;1&gt;</text>"), std::string::npos);
  EXPECT_EQ(svg.find("front<1>"), std::string::npos);
}

TEST(PatternSvg, RefusesABadAllowanceOrGarment) {
  PatternSvgOptions options;
  for (float bad : {-0.001f, 0.2f, std::nanf("")}) {
    options.seamAllowance = bad;
    EXPECT_THROW(patternSvg(twoPanels(), options), Error) << bad;
  }
  Garment g = twoPanels();
  g.seams[0].edgeB = "nowhere";
  EXPECT_THROW(patternSvg(g), Error);
}

TEST(PatternSvg, SeamLengthsAreTheSewnEdgesArcLengths) {
  Garment g = twoPanels();
  g.panels[1] = rectangle("b", 0.4f, 0.5f);
  g.seams.push_back({"a", "top", "b", "top", true});
  const std::vector<SeamLengths> lengths = seamLengths(g);
  ASSERT_EQ(lengths.size(), 2u);
  EXPECT_FLOAT_EQ(lengths[0].a, 0.6f);
  EXPECT_FLOAT_EQ(lengths[0].b, 0.5f);
  EXPECT_FLOAT_EQ(lengths[1].a, 0.4f);
  EXPECT_FLOAT_EQ(lengths[1].b, 0.4f);
  g.seams[1].panelB = "c";
  EXPECT_THROW(seamLengths(g), Error);
}

}  // namespace
}  // namespace mq
