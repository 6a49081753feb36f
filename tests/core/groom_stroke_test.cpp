// Grooming brushes: each brush's effect on the guides it touches, none on
// the others, children following, strokes kept through a flow edit, JSON.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/hair/groom_stroke.h"
#include "core/hair/hair_groom.h"
#include "core/hair/hairstyle_json.h"
#include "core/hair/head_fit.h"
#include "core/util/error.h"
#include "hair_test_util.h"

namespace mq {
namespace {

constexpr size_t kGuides = 300, kStrands = 3000;

HairGroom sphereGroom() {
  return HairGroom(test::sphereScalp(test::kHeadCenter, test::kHeadRadius, -0.1f),
                   sphereProxy(test::kHeadCenter, 0.099f), 200);
}

HairStyle styleNamed(const char* name) {
  HairStyle style = builtinHairStyle(name);
  style.guideCount = int(kGuides);
  return style;
}

glm::vec3 point(const Strands& s, size_t strand, int k) {
  const float* p = s.strand(strand);
  return {p[3 * k], p[3 * k + 1], p[3 * k + 2]};
}

float strandLength(const Strands& s, size_t strand) {
  float sum = 0.0f;
  for (int k = 1; k < s.pointsPerStrand; ++k) sum += glm::length(point(s, strand, k) - point(s, strand, k - 1));
  return sum;
}

bool sameStrand(const Strands& a, const Strands& b, size_t strand) {
  for (int k = 0; k < a.pointsPerStrand; ++k)
    if (point(a, strand, k) != point(b, strand, k)) return false;
  return true;
}

// A stroke of `brush` through guide `guide`'s point k (head space), moving
// by `motion` over its dabs.
GroomStroke strokeThrough(const HairGroom& groom, GroomBrush brush, size_t guide, int k, const glm::vec3& motion,
                          float radius = 0.03f, float strength = 1.0f) {
  GroomStroke stroke;
  stroke.brush = brush;
  stroke.radius = radius;
  stroke.strength = strength;
  const glm::vec3 at = point(groom.strands(), guide, k) - groom.proxy().headCenter();
  stroke.dabs = dabsAlong(at, at + motion, radius);
  return stroke;
}

struct Brushed {
  HairGroom before = sphereGroom(), after = sphereGroom();
  HairStyle style;
};

// The same style grown without and with one stroke through guide 0.
Brushed brush(const char* styleName, GroomBrush brush, int k, const glm::vec3& motion, float radius = 0.03f,
              float strength = 1.0f) {
  Brushed b;
  b.style = styleNamed(styleName);
  b.before.grow(b.style, kStrands);
  b.style.strokes.push_back(strokeThrough(b.before, brush, 0, k, motion, radius, strength));
  b.after.grow(b.style, kStrands);
  return b;
}

// Guides whose points all lie farther than `reach` from every dab: the
// brush must leave them exactly as they were.
std::vector<size_t> farGuides(const HairGroom& groom, const GroomStroke& stroke, float reach) {
  std::vector<size_t> far;
  const Strands& s = groom.strands();
  for (size_t g = 0; g < groom.guideCount(); ++g) {
    bool isFar = true;
    for (int k = 0; k < s.pointsPerStrand && isFar; ++k)
      for (const GroomDab& d : stroke.dabs)
        if (glm::length(point(s, g, k) - (groom.proxy().headCenter() + d.position)) < reach) isFar = false;
    if (isFar) far.push_back(g);
  }
  return far;
}

void expectFarGuidesUntouched(const Brushed& b) {
  const std::vector<size_t> far = farGuides(b.before, b.style.strokes[0], 2.0f * b.style.strokes[0].radius + 0.02f);
  ASSERT_GT(far.size(), kGuides / 2);
  for (size_t g : far) EXPECT_TRUE(sameStrand(b.before.strands(), b.after.strands(), g)) << g;
}

TEST(GroomStroke, CombMovesTheHairUnderTheBrushAndKeepsItsLength) {
  const Brushed b = brush("long_straight", GroomBrush::Comb, 24, {0.06f, 0.0f, 0.0f});
  const Strands &was = b.before.strands(), &now = b.after.strands();
  const int tip = was.pointsPerStrand - 1;
  EXPECT_GT(point(now, 0, tip).x - point(was, 0, tip).x, 0.02f);
  EXPECT_EQ(point(now, 0, 0), point(was, 0, 0));  // the root stays
  for (size_t g = 0; g < kGuides; ++g) EXPECT_NEAR(strandLength(now, g), strandLength(was, g), 1e-4f) << g;
  expectFarGuidesUntouched(b);
  EXPECT_EQ(b.after.countPointsInside(), 0u);
}

TEST(GroomStroke, CutShortensTheGuidesItCrossesAndTheirChildren) {
  const Brushed b = brush("long_straight", GroomBrush::Cut, 16, {0.05f, 0.0f, 0.0f});
  const Strands &was = b.before.strands(), &now = b.after.strands();
  // Guide 0 is cut where the brush met it: at most about half its length.
  EXPECT_LT(strandLength(now, 0), 0.6f * strandLength(was, 0));
  EXPECT_GT(strandLength(now, 0), 0.2f * strandLength(was, 0));
  // Its children are cut with it.
  double before = 0.0, after = 0.0;
  int children = 0;
  for (size_t c = kGuides; c < kStrands; ++c)
    if (now.guideOf[c] == 0) {
      before += strandLength(was, c);
      after += strandLength(now, c);
      ++children;
    }
  ASSERT_GT(children, 0);
  EXPECT_LT(after, 0.7 * before);
  expectFarGuidesUntouched(b);
  EXPECT_EQ(b.after.countPointsInside(), 0u);
}

TEST(GroomStroke, LengthGrowsOrShortensWithTheSignOfItsStrength) {
  const Brushed longer = brush("bob", GroomBrush::Length, 20, {0.0f, 0.0f, 0.0f}, 0.04f, 1.0f);
  const Brushed shorter = brush("bob", GroomBrush::Length, 20, {0.0f, 0.0f, 0.0f}, 0.04f, -1.0f);
  const float was = strandLength(longer.before.strands(), 0);
  EXPECT_GT(strandLength(longer.after.strands(), 0), 1.05f * was);
  EXPECT_LT(strandLength(shorter.after.strands(), 0), 0.95f * was);
  expectFarGuidesUntouched(longer);
  EXPECT_EQ(longer.after.countPointsInside(), 0u);
}

TEST(GroomStroke, PuffLiftsTheHairFromTheScalp) {
  const Brushed b = brush("long_straight", GroomBrush::Puff, 6, {0.0f, 0.0f, 0.0f}, 0.05f);
  const glm::vec3 center = b.before.proxy().headCenter();
  // Near the root the strand now stands off the head.
  const float was = glm::length(point(b.before.strands(), 0, 6) - center);
  const float now = glm::length(point(b.after.strands(), 0, 6) - center);
  EXPECT_GT(now, was + 0.003f);
  expectFarGuidesUntouched(b);
}

// Sum of the turning angles along a strand, at points first..last.
float turning(const Strands& s, size_t g, int first, int last) {
  float sum = 0.0f;
  for (int k = first; k <= last; ++k) {
    const glm::vec3 a = glm::normalize(point(s, g, k) - point(s, g, k - 1));
    const glm::vec3 b = glm::normalize(point(s, g, k + 1) - point(s, g, k));
    sum += std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f));
  }
  return sum;
}

TEST(GroomStroke, SmoothStraightensCurls) {
  const Brushed b = brush("curly", GroomBrush::Smooth, 20, {0.0f, -0.05f, 0.0f}, 0.04f);
  EXPECT_LT(turning(b.after.strands(), 0, 14, 27), 0.75f * turning(b.before.strands(), 0, 14, 27));
  EXPECT_NEAR(strandLength(b.after.strands(), 0), strandLength(b.before.strands(), 0), 1e-4f);
  expectFarGuidesUntouched(b);
}

TEST(GroomStroke, ClumpDrawsTheHairUnderTheBrushTogether) {
  const Brushed b = brush("long_straight", GroomBrush::Clump, 24, {0.0f, -0.03f, 0.0f}, 0.05f);
  // The guides with their point 24 inside the brush: those points' spread shrinks.
  const glm::vec3 center = b.before.proxy().headCenter() + b.style.strokes[0].dabs[0].position;
  std::vector<size_t> under;
  for (size_t g = 0; g < kGuides; ++g)
    if (glm::length(point(b.before.strands(), g, 24) - center) < 0.05f) under.push_back(g);
  ASSERT_GE(under.size(), 3u);
  auto spread = [&](const Strands& s) {
    glm::vec3 mean(0.0f);
    for (size_t g : under) mean += point(s, g, 24) / float(under.size());
    float sum = 0.0f;
    for (size_t g : under) sum += glm::length(point(s, g, 24) - mean);
    return sum;
  };
  EXPECT_LT(spread(b.after.strands()), 0.85f * spread(b.before.strands())) << under.size();
  expectFarGuidesUntouched(b);
}

TEST(GroomStroke, FrizzIsRandomButReproducible) {
  const Brushed a = brush("long_straight", GroomBrush::Frizz, 24, {0.0f, 0.0f, 0.0f}, 0.05f);
  const Brushed b = brush("long_straight", GroomBrush::Frizz, 24, {0.0f, 0.0f, 0.0f}, 0.05f);
  EXPECT_FALSE(sameStrand(a.before.strands(), a.after.strands(), 0));
  EXPECT_EQ(a.after.strands().points, b.after.strands().points);
  EXPECT_NEAR(strandLength(a.after.strands(), 0), strandLength(a.before.strands(), 0), 1e-4f);
}

TEST(GroomStroke, MirrorBrushesBothSides) {
  Brushed b;
  b.style = styleNamed("long_straight");
  b.before.grow(b.style, kStrands);
  // The guide farthest to the right (+x), and one mirrored stroke there.
  size_t right = 0;
  for (size_t g = 0; g < kGuides; ++g)
    if (point(b.before.strands(), g, 12).x > point(b.before.strands(), right, 12).x) right = g;
  GroomStroke stroke = strokeThrough(b.before, GroomBrush::Comb, right, 12, {0.0f, 0.0f, 0.05f}, 0.04f);
  stroke.mirror = true;
  b.style.strokes.push_back(stroke);
  b.after.grow(b.style, kStrands);
  int leftMoved = 0, rightMoved = 0;
  for (size_t g = 0; g < kGuides; ++g) {
    if (sameStrand(b.before.strands(), b.after.strands(), g)) continue;
    (point(b.before.strands(), g, 0).x < 0.0f ? leftMoved : rightMoved)++;
  }
  EXPECT_GT(rightMoved, 0);
  EXPECT_GT(leftMoved, 0);
}

TEST(GroomStroke, StrokesSurviveAFlowEditAndReplayWithoutRetracing) {
  Brushed b = brush("long_straight", GroomBrush::Cut, 16, {0.05f, 0.0f, 0.0f});
  const float cut = strandLength(b.after.strands(), 0);
  // A primitive moved: the guides are traced again, and cut again.
  HairStyle moved = b.style;
  moved.primitives.streams[0].strength *= 1.2f;
  b.after.regrowGuides(moved);
  EXPECT_LT(strandLength(b.after.strands(), 0), 0.6f * strandLength(b.before.strands(), 0));
  // Back to the first flow: the very same strands as a fresh groom's.
  b.after.regrowGuides(b.style);
  b.after.growChildren(b.style);
  HairGroom fresh = sphereGroom();
  fresh.grow(b.style, kStrands);
  EXPECT_EQ(b.after.strands().points, fresh.strands().points);
  EXPECT_FLOAT_EQ(strandLength(fresh.strands(), 0), cut);
  // Strokes taken away: the hair as it was before them.
  b.style.strokes.clear();
  b.after.regrowGuides(b.style);
  b.after.growChildren(b.style);
  EXPECT_EQ(b.after.strands().points, b.before.strands().points);
}

// A stroke drawn in steps (the editor regrows as the drag goes) replays the
// earlier strokes from a cache: the hair is the same as grown at once.
TEST(GroomStroke, AStrokeGrowingDabByDabGivesTheSameHairAsAtOnce) {
  HairStyle style = styleNamed("long_straight");
  HairGroom groom = sphereGroom();
  groom.grow(style, kStrands);
  style.strokes.push_back(strokeThrough(groom, GroomBrush::Frizz, 0, 20, {0.02f, 0.0f, 0.0f}, 0.04f));
  style.strokes.push_back(strokeThrough(groom, GroomBrush::Comb, 0, 24, {0.06f, 0.0f, 0.0f}, 0.04f));
  HairStyle growing = style;
  growing.strokes.back().dabs.clear();
  for (const GroomDab& dab : style.strokes.back().dabs) {
    growing.strokes.back().dabs.push_back(dab);
    groom.regrowGuides(growing);
  }
  groom.growChildren(style);
  HairGroom atOnce = sphereGroom();
  atOnce.grow(style, kStrands);
  EXPECT_EQ(groom.strands().points, atOnce.strands().points);
  // An earlier stroke changed (an undo, then another stroke): no stale cache.
  style.strokes[0].strength = 0.25f;
  groom.regrowGuides(style);
  groom.growChildren(style);
  atOnce.grow(style, kStrands);
  EXPECT_EQ(groom.strands().points, atOnce.strands().points);
}

// A paint stroke of one dab at guide 0's root.
GroomStroke paintAtRoot(const HairGroom& groom, GroomBrush brush, float value, float radius) {
  GroomStroke stroke;
  stroke.brush = brush;
  stroke.radius = radius;
  stroke.strength = 1.0f;
  stroke.value = value;
  stroke.dabs = {{point(groom.strands(), 0, 0) - groom.proxy().headCenter(), glm::vec3(0.0f)}};
  return stroke;
}

// `style` grown without and with one paint stroke at guide 0's root.
Brushed painted(const HairStyle& style, GroomBrush brush, float value, float radius) {
  Brushed b;
  b.style = style;
  b.before.grow(b.style, kStrands);
  b.style.strokes.push_back(paintAtRoot(b.before, brush, value, radius));
  b.after.grow(b.style, kStrands);
  return b;
}

TEST(GroomStroke, PaintedDensityThinsTheHairWhereItIsPainted) {
  const Brushed b = painted(styleNamed("long_straight"), GroomBrush::PaintDensity, 0.0f, 0.05f);
  const glm::vec3 center = point(b.before.strands(), 0, 0);
  auto count = [&](const HairGroom& g, float lo, float hi) {
    int n = 0;
    for (size_t c = 0; c < g.childRoots().size(); ++c) {
      const float d = glm::length(g.childRoots().position(c) - center);
      n += d >= lo && d < hi;
    }
    return n;
  };
  // Under the brush's core (a kept share of at most 0.44): less than half the hair is left.
  EXPECT_GT(count(b.before, 0.0f, 0.025f), 20);
  EXPECT_LT(count(b.after, 0.0f, 0.025f), count(b.before, 0.0f, 0.025f) / 2);
  // Outside the brush, every root is still there.
  EXPECT_EQ(count(b.after, 0.05f, 10.0f), count(b.before, 0.05f, 10.0f));
  EXPECT_LT(b.after.strands().strandCount(), b.before.strands().strandCount());
  EXPECT_EQ(b.after.guideCount(), b.before.guideCount());  // the guides stay: the hair keeps its shape
}

TEST(GroomStroke, PaintedLengthScalesTheHairWhereItIsPainted) {
  const Brushed b = painted(styleNamed("bob"), GroomBrush::PaintLength, 2.0f, 0.04f);
  EXPECT_GT(strandLength(b.after.strands(), 0), 1.8f * strandLength(b.before.strands(), 0));
  expectFarGuidesUntouched(b);
  EXPECT_EQ(b.after.countPointsInside(), 0u);
}

TEST(GroomStroke, PaintedClumpingGathersTheChildrenWherePainted) {
  HairStyle unclumped = styleNamed("long_straight");
  unclumped.clumping = 0.0f;
  const Brushed b = painted(unclumped, GroomBrush::PaintClumping, 1.0f, 0.06f);
  // Guide 0's children: their tips draw to its tip.
  const int tip = b.before.strands().pointsPerStrand - 1;
  float before = 0.0f, after = 0.0f;
  for (size_t c = kGuides; c < kStrands; ++c)
    if (b.after.strands().guideOf[c] == 0) {
      before += glm::length(point(b.before.strands(), c, tip) - point(b.before.strands(), 0, tip));
      after += glm::length(point(b.after.strands(), c, tip) - point(b.after.strands(), 0, tip));
    }
  EXPECT_LT(after, 0.5f * before);
  // The guides do not move: clumping is the children's.
  EXPECT_EQ(std::vector<float>(b.after.strands().points.begin(),
                               b.after.strands().points.begin() + 3 * kGuides * b.style.pointsPerStrand),
            std::vector<float>(b.before.strands().points.begin(),
                               b.before.strands().points.begin() + 3 * kGuides * b.style.pointsPerStrand));
}

// A pigment map: strands growing under the brush take its melanin (guide
// 0, at its centre, all of it); strands far from it keep the style's; the
// map is stored as shares of the style's (PaintedShare), so it follows a
// later change of the style's pigment.
TEST(GroomStroke, PaintedMelaninColoursTheStrandsWherePainted) {
  const Brushed b = painted(styleNamed("long_straight"), GroomBrush::PaintMelanin, 0.2f, 0.04f);
  EXPECT_TRUE(b.before.strands().pigmentPaint.empty());  // nothing painted: nothing stored
  const Strands& strands = b.after.strands();
  ASSERT_EQ(strands.pigmentPaint.size(), 4 * strands.strandCount());
  auto melanin = [&](size_t s, float style) {
    return strands.pigmentPaint[4 * s] * style + strands.pigmentPaint[4 * s + 1];
  };
  EXPECT_NEAR(melanin(0, b.style.shading.melanin), 0.2f, 1e-4f);
  EXPECT_NEAR(melanin(0, 5.0f), 0.2f, 1e-4f);  // fully painted: whatever the style's
  const glm::vec3 center = point(strands, 0, 0);
  size_t near = 0, far = 0;
  for (size_t s = 0; s < strands.strandCount(); ++s) {
    const float d = glm::length(point(strands, s, 0) - center);
    if (d < 0.01f) {
      EXPECT_LT(melanin(s, b.style.shading.melanin), 0.75f) << s;
      ++near;
    } else if (d > 0.04f) {
      EXPECT_EQ(melanin(s, 3.0f), 3.0f) << s;            // unpainted: the style's, whichever it is
      EXPECT_EQ(strands.pigmentPaint[4 * s + 2], 1.0f);  // pheomelanin untouched
      ++far;
    }
  }
  EXPECT_GT(near, 5u);
  EXPECT_GT(far, 100u);
  // The shapes are not the paint's: the strands are where they were.
  EXPECT_EQ(strands.points, b.before.strands().points);
}

TEST(GroomStroke, PaintedShareIsThePaintedValueOfAnyUnpaintedValue) {
  GroomStroke a, c;
  a.brush = c.brush = GroomBrush::PaintPheomelanin;
  a.radius = 0.05f, a.strength = 0.7f, a.value = 4.0f;
  a.dabs = {{glm::vec3(0.01f, 0.0f, 0.0f), glm::vec3(0.0f)}, {glm::vec3(0.02f, 0.0f, 0.0f), glm::vec3(0.0f)}};
  c.radius = 0.03f, c.strength = 0.4f, c.value = 0.5f, c.mirror = true;
  c.dabs = {{glm::vec3(0.03f, 0.01f, 0.0f), glm::vec3(0.0f)}};
  const std::vector<GroomStroke> strokes{a, c};
  for (const glm::vec3 at : {glm::vec3(0.02f, 0.0f, 0.0f), glm::vec3(-0.03f, 0.01f, 0.0f), glm::vec3(1.0f)}) {
    const PaintedShare share = paintedShare(strokes, GroomBrush::PaintPheomelanin, at);
    for (float unpainted : {0.0f, 0.3f, 2.0f, 8.0f})
      EXPECT_NEAR(share.of(unpainted), paintedValue(strokes, GroomBrush::PaintPheomelanin, at, unpainted), 1e-5f);
  }
  EXPECT_EQ(paintedShare(strokes, GroomBrush::PaintMelanin, glm::vec3(0.02f, 0.0f, 0.0f)).keep, 1.0f);
}

TEST(GroomStroke, JsonRoundTripAndClearErrors) {
  HairStyle style = builtinHairStyle("bob");
  GroomStroke stroke;
  stroke.brush = GroomBrush::Length;
  stroke.strength = -0.5f;
  stroke.mirror = true;
  stroke.dabs = dabsAlong({0.0f, 0.0f, -0.1f}, {0.04f, 0.0f, -0.1f}, 0.04f);
  style.strokes = {stroke};
  const HairStyle back = hairStyleFromJson(toJson(style));
  ASSERT_EQ(back.strokes.size(), 1u);
  EXPECT_EQ(back.strokes[0].brush, GroomBrush::Length);
  EXPECT_FLOAT_EQ(back.strokes[0].strength, -0.5f);
  EXPECT_TRUE(back.strokes[0].mirror);
  ASSERT_EQ(back.strokes[0].dabs.size(), stroke.dabs.size());
  EXPECT_NEAR(back.strokes[0].dabs[2].position.x, stroke.dabs[2].position.x, 1e-6f);
  EXPECT_EQ(toJson(back), toJson(style));
  // A style without strokes writes none (older files stay as they were).
  EXPECT_FALSE(toJson(builtinHairStyle("bob")).contains("strokes"));

  auto errorOf = [](const char* text) {
    try {
      hairStyleFromJson(nlohmann::json::parse(text));
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(errorOf(R"({"strokes": [{"brush": "shave"}]})").find("hair.style.strokes[0].brush: unknown brush 'shave'"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"strokes": [{"dabs": [[0, 0, 0]]}]})").find("hair.style.strokes[0].dabs"), std::string::npos);
  EXPECT_NE(errorOf(R"({"strokes": [{"dabs": [[0, 0, 0, 0, 0, 1e300]]}]})").find("at most 100"), std::string::npos);
  EXPECT_NE(errorOf(R"({"strokes": [{"brush": "comb", "strength": -1}]})").find("strokes[0].strength"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"strokes": [{"radius": 0}]})").find("strokes[0].radius"), std::string::npos);
  EXPECT_NE(errorOf(R"({"strokes": [{"size": 2}]})").find("size"), std::string::npos);
  EXPECT_NE(errorOf(R"({"strokes": [{"brush": "paint_density", "value": 2}]})").find("strokes[0].value"),
            std::string::npos);
  const HairStyle painted =
      hairStyleFromJson(nlohmann::json::parse(R"({"strokes": [{"brush": "paint_length", "value": 2.5}]})"));
  EXPECT_FLOAT_EQ(painted.strokes[0].value, 2.5f);
  EXPECT_FLOAT_EQ(hairStyleFromJson(toJson(painted)).strokes[0].value, 2.5f);
}

TEST(GroomStroke, AFittedStyleScalesItsStrokes) {
  HairStyle style = builtinHairStyle("bob");
  style.strokes.push_back({GroomBrush::Comb, 0.03f, 0.5f, 1.0f, false, {{{0.01f, 0.02f, 0.03f}, {0.0f, 0.0f, 0.01f}}}});
  const HairStyle big = scaledHairStyle(style, 2.0f);
  EXPECT_FLOAT_EQ(big.strokes[0].radius, 0.06f);
  EXPECT_FLOAT_EQ(big.strokes[0].dabs[0].position.y, 0.04f);
  EXPECT_FLOAT_EQ(big.strokes[0].dabs[0].motion.z, 0.02f);
}

TEST(GroomStroke, BrushNames) {
  for (const std::string& name : groomBrushNames()) EXPECT_EQ(groomBrushName(groomBrushFromName(name)), name);
  EXPECT_THROW(groomBrushFromName("shave"), Error);
}

}  // namespace
}  // namespace mq
