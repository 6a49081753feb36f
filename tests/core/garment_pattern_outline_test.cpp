// The marks a pattern carries: the grain line stays inside the panel (a
// two-legged one too), and a notch points into the panel.
#include <gtest/gtest.h>

#include "core/garment/pattern_outline.h"
#include "core/util/error.h"
#include "garment_test_util.h"

namespace mq {
namespace {

bool inside(const std::vector<glm::vec2>& polygon, glm::vec2 p) {
  bool in = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    if ((polygon[i].y > p.y) != (polygon[j].y > p.y) &&
        p.x < (polygon[j].x - polygon[i].x) * (p.y - polygon[i].y) / (polygon[j].y - polygon[i].y) + polygon[i].x)
      in = !in;
  return in;
}

// Trousers-like: a 60 cm wide, 100 cm tall panel split into two legs below 40 cm.
Panel twoLegs() {
  Panel p;
  p.name = "legs";
  p.addLine("left_hem", {0.0f, 0.0f});
  p.addLine("inseam_left", {0.25f, 0.0f});
  p.addLine("crotch_left", {0.25f, 0.6f});
  p.addLine("crotch_right", {0.35f, 0.6f});
  p.addLine("right_hem", {0.35f, 0.0f});
  p.addLine("outseam_right", {0.6f, 0.0f});
  p.addLine("waist", {0.6f, 1.0f});
  p.addLine("outseam_left", {0.0f, 1.0f});
  return p;
}

TEST(PatternOutline, TheGrainLineStaysInsideATwoLeggedPanel) {
  const Panel panel = twoLegs();
  const PatternSegment grain = grainLine(panel);
  const std::vector<glm::vec2> polygon = panel.outline(0.01f);
  for (float t = 0.0f; t <= 1.0f; t += 0.05f) EXPECT_TRUE(inside(polygon, grain.from + t * (grain.to - grain.from)));
  EXPECT_FLOAT_EQ(grain.from.x, grain.to.x);   // along pattern v
  EXPECT_GT(grain.to.y - grain.from.y, 0.6f);  // two thirds of a full-height chord
}

TEST(PatternOutline, TheGrainLineOfARectangleIsCentred) {
  const PatternSegment grain = grainLine(test::rectanglePanel("r", 0.4f, 0.6f));
  EXPECT_NEAR(grain.from.x, 0.2f, 0.01f);
  EXPECT_NEAR(grain.from.y, 0.1f, 1e-4f);
  EXPECT_NEAR(grain.to.y, 0.5f, 1e-4f);
}

TEST(PatternOutline, ANotchPointsIntoThePanel) {
  const Panel panel = test::rectanglePanel("r", 0.4f, 0.6f);
  const PatternSegment notch = edgeNotch(panel, 0, 0.006f);  // the bottom edge
  EXPECT_NEAR(notch.from.x, 0.2f, 1e-5f);
  EXPECT_NEAR(notch.to.y, 0.006f, 1e-5f);
}

TEST(PatternOutline, TheCuttingLineIsOutsideAndSimplified) {
  const std::vector<glm::vec2> cut = cuttingLine(test::rectanglePanel("r", 0.4f, 0.6f), 0.01f);
  ASSERT_EQ(cut.size(), 4u);  // one segment per side
  EXPECT_NEAR(cut[0].x, -0.01f, 1e-5f);
  EXPECT_NEAR(cut[0].y, -0.01f, 1e-5f);
  EXPECT_THROW(checkSeamAllowance(0.2f), Error);
  EXPECT_THROW(checkSeamAllowance(-0.001f), Error);
}

}  // namespace
}  // namespace mq
