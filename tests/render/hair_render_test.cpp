// The hair shader: strands combed over a sphere head, drawn with Kajiya-Kay shading, shifted highlights and
// self-shadowing. Checks that hair shows, that it has highlights and shadowed inner strands, that the self-shadow term
// darkens with depth, and compares a baseline.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/hair/character_groom.h"
#include "core/hair/hairstyle.h"
#include "core/hair/head_fit.h"
#include "core/hair_test_util.h"
#include "core/io/character_import.h"
#include "core/optics/hair_bsdf.h"
#include "render/hair_actor.h"
#include "render/image_checks.h"
#include "render/offscreen.h"
#include "render/scene_view.h"

namespace mq {
namespace {

constexpr int kWidth = 320, kHeight = 320;
using test::combedStrands;
using test::kHeadCenter;
using test::kHeadRadius;

class HairRenderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { test::useSoftwareRendering(); }

  void SetUp() override {
    sphere->SetCenter(kHeadCenter.x, kHeadCenter.y, kHeadCenter.z);
    sphere->SetRadius(kHeadRadius * 0.99);
    sphere->SetThetaResolution(48);
    sphere->SetPhiResolution(32);
    sphereMapper->SetInputConnection(sphere->GetOutputPort());
    head->SetMapper(sphereMapper);
    head->GetProperty()->SetColor(0.85, 0.68, 0.58);
    view.addProp(head);
    view.setGridVisible(false);
    view.setCamera(kHeadCenter + glm::vec3(0.55f, 0.25f, -0.75f), kHeadCenter + glm::vec3(0.0f, -0.08f, 0.0f));
  }

  render::SceneView view;
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> sphereMapper;
  vtkNew<vtkActor> head;
};

double luminance(const uint8_t* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

TEST_F(HairRenderTest, DrapedHairHasHighlightsAndShadowedInnerStrands) {
  const Strands strands = combedStrands(8000, 24, 0.3f);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage bare = renderer.capture();
  render::HairActor hair;
  hair.setStrands(strands);
  view.addProp(hair.actor());
  const render::RgbImage image = renderer.capture();

  const test::Foreground f = test::foregroundOf(image, bare);
  EXPECT_GT(f.fraction, 0.10);  // the hair covers a good part of the picture
  // Luminance over the hair pixels: dark shadowed strands and bright
  // highlights both present (not a flat helmet).
  std::vector<double> lum;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t *a = image.at(x, y), *b = bare.at(x, y);
      if (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) > 72) lum.push_back(luminance(a));
    }
  ASSERT_GT(lum.size(), 1000u);
  std::sort(lum.begin(), lum.end());
  const double dark = lum[lum.size() / 20], bright = lum[lum.size() * 99 / 100];
  EXPECT_LT(dark, 40.0);
  EXPECT_GT(bright, 2.5 * std::max(dark, 8.0));

  // Without self-shadowing the hair is brighter on average.
  render::HairShading unshadowed = hair.shading();
  unshadowed.selfShadowing = false;
  hair.setShading(unshadowed);
  const render::RgbImage flat = renderer.capture();
  double sumShadowed = 0.0, sumFlat = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      sumShadowed += luminance(image.at(x, y));
      sumFlat += luminance(flat.at(x, y));
    }
  EXPECT_GT(sumFlat, sumShadowed * 1.03);

  const std::string why = test::checkAgainstBaseline(image, "hair_draped_sphere");
  EXPECT_TRUE(why.empty()) << why;
}

// ---- The physical fibre (core/optics/hair_bsdf.h in the shader) ----

// The hair's pixels: where the Kajiya-Kay image differs from the bare head
// (the same pixels for every model and pigment compared).
std::vector<bool> hairMask(const render::RgbImage& image, const render::RgbImage& bare) {
  std::vector<bool> mask(size_t(image.width) * image.height);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t *a = image.at(x, y), *b = bare.at(x, y);
      mask[size_t(y) * image.width + x] = std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) > 72;
    }
  return mask;
}

double meanLuminance(const render::RgbImage& image, const std::vector<bool>& mask) {
  double sum = 0.0;
  size_t count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (mask[size_t(y) * image.width + x]) sum += luminance(image.at(x, y)), ++count;
  return count ? sum / double(count) : 0.0;
}

// The highlight of a one-lobe image: its brightest 2 % of hair pixels, their
// luminance-weighted centre (pixels, y down) and their mean red / blue.
struct Highlight {
  glm::dvec2 centre{0.0};
  double redOverBlue = 0.0;
  double level = 0.0;
};
Highlight highlightOf(const render::RgbImage& image, const std::vector<bool>& mask) {
  std::vector<double> lum;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (mask[size_t(y) * image.width + x]) lum.push_back(luminance(image.at(x, y)));
  Highlight h;
  if (lum.empty()) return h;
  std::sort(lum.begin(), lum.end());
  h.level = lum[lum.size() * 98 / 100];
  double weight = 0.0, ratio = 0.0;
  size_t count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.at(x, y);
      const double l = luminance(p);
      if (!mask[size_t(y) * image.width + x] || l < h.level) continue;
      h.centre += (l - h.level + 1.0) * glm::dvec2(x, y);
      weight += l - h.level + 1.0;
      ratio += (p[0] + 1.0) / (p[2] + 1.0);
      ++count;
    }
  h.centre /= weight;
  h.redOverBlue = ratio / double(count);
  return h;
}

render::HairShading physical(const render::HairShading& base, const char* pigment, unsigned lobes = 31u) {
  render::HairShading s = base;
  const optics::HairPigment p = optics::hairPigmentPreset(pigment);
  s.fibre.model = HairShadingModel::Physical;
  s.fibre.melanin = float(p.eumelanin);
  s.fibre.pheomelanin = float(p.pheomelanin);
  s.physicalLobes = lobes;
  return s;
}

TEST_F(HairRenderTest, PhysicalPigmentsOrderTheBrightness) {
  const Strands strands = combedStrands(8000, 24, 0.3f);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage bare = renderer.capture();
  render::HairActor hair;
  hair.setStrands(strands);
  view.addProp(hair.actor());
  const std::vector<bool> mask = hairMask(renderer.capture(), bare);
  const render::HairShading kajiyaKay = hair.shading();
  double previous = 0.0;
  for (const char* pigment : {"black", "brown", "blond"}) {
    hair.setShading(physical(kajiyaKay, pigment));
    const render::RgbImage image = renderer.capture();
    const double mean = meanLuminance(image, mask);
    std::printf("physical %s: mean luminance %.1f\n", pigment, mean);
    EXPECT_GT(mean, 1.15 * previous) << pigment;
    previous = mean;
    if (std::string(pigment) == "brown") {
      const std::string why = test::checkAgainstBaseline(image, "hair_physical_brown");
      EXPECT_TRUE(why.empty()) << why;
    }
  }
  // The Kajiya-Kay picture is the same after a trip through the physical model.
  hair.setShading(kajiyaKay);
  const std::string why = test::checkAgainstBaseline(renderer.capture(), "hair_draped_sphere");
  EXPECT_TRUE(why.empty()) << why;
}

// Painted pigments (a paint_melanin map over the scalp): brown hair painted
// blond all over must look about as bright as blond hair (the tint is the
// ratio of the fibres' mean albedos, the lobes stay the brown's), and
// painting it darker must darken it, under either model.
TEST_F(HairRenderTest, PaintedPigmentsTintTheStrands) {
  const Strands plain = combedStrands(8000, 24, 0.3f);
  auto paintedAs = [&](const optics::HairPigment& p) {
    Strands painted = plain;
    painted.pigmentPaint.clear();
    for (size_t s = 0; s < painted.strandCount(); ++s)
      painted.pigmentPaint.insert(painted.pigmentPaint.end(), {0.0f, float(p.eumelanin), 0.0f, float(p.pheomelanin)});
    return painted;
  };
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage bare = renderer.capture();
  render::HairActor hair;
  hair.setStrands(plain);
  view.addProp(hair.actor());
  const std::vector<bool> mask = hairMask(renderer.capture(), bare);
  const double kajiyaKay = meanLuminance(renderer.capture(), mask);
  hair.setStrands(paintedAs(optics::hairPigmentPreset("black")));
  const double kajiyaKayBlack = meanLuminance(renderer.capture(), mask);
  EXPECT_LT(kajiyaKayBlack, 0.8 * kajiyaKay);

  const render::HairShading brown = physical(hair.shading(), "brown");
  hair.setShading(physical(hair.shading(), "blond"));
  hair.setStrands(plain);
  const double blond = meanLuminance(renderer.capture(), mask);
  hair.setShading(brown);
  hair.setStrands(plain);
  const double unpainted = meanLuminance(renderer.capture(), mask);
  hair.setStrands(paintedAs(optics::hairPigmentPreset("blond")));
  const double paintedBlond = meanLuminance(renderer.capture(), mask);
  std::printf("brown %.1f, painted blond %.1f, blond %.1f; Kajiya-Kay %.1f, painted black %.1f\n", unpainted,
              paintedBlond, blond, kajiyaKay, kajiyaKayBlack);
  EXPECT_GT(paintedBlond, 1.3 * unpainted);
  EXPECT_NEAR(paintedBlond, blond, 0.25 * blond);
}

// Marschner's two highlights: the white R reflected at the cuticle, shifted
// toward the root (alpha_R = -3 degrees), and the TRT, tinted by the
// pigment it crossed twice, shifted toward the tip (-3/2 alpha_R = +4.5
// degrees). Rendered one lobe at a time, the TRT highlight must sit further
// toward the tips (down the picture: the strands comb down) and be redder
// than R's. With the shifts' signs swapped, no shift, or the lobes' colours
// mixed up, this fails.
TEST_F(HairRenderTest, PhysicalTrtHighlightIsShiftedAndTintedAgainstR) {
  const Strands strands = combedStrands(8000, 24, 0.3f);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage bare = renderer.capture();
  render::HairActor hair;
  render::HairShading shading = hair.shading();
  shading.selfShadowing = false;  // the lobes alone
  shading.ambient = 0.0f;
  shading.colorVariation = 0.0f;
  shading.tipOpacity = 1.0f;
  hair.setShading(shading);
  hair.setStrands(strands);
  view.addProp(hair.actor());
  const std::vector<bool> mask = hairMask(renderer.capture(), bare);
  hair.setShading(physical(shading, "blond", optics::kHairR));
  const Highlight r = highlightOf(renderer.capture(), mask);
  hair.setShading(physical(shading, "blond", optics::kHairTRT));
  const Highlight trt = highlightOf(renderer.capture(), mask);
  std::printf(
      "R highlight at (%.1f, %.1f), level %.0f, red/blue %.2f; TRT at (%.1f, %.1f), level %.0f, red/blue %.2f\n",
      r.centre.x, r.centre.y, r.level, r.redOverBlue, trt.centre.x, trt.centre.y, trt.level, trt.redOverBlue);
  ASSERT_GT(r.level, 8.0);  // a highlight at all (8-bit levels)
  ASSERT_GT(trt.level, 8.0);
  EXPECT_GT(trt.centre.y - r.centre.y, 4.0);  // toward the tips
  EXPECT_GT(trt.redOverBlue, 1.3 * r.redOverBlue);
  EXPECT_LT(r.redOverBlue, 1.25);  // R: the light's colour
}

// The default hairstyle groomed on the default mannequin, seen from the
// front three-quarter and from behind.
TEST(HairRenderDefault, DefaultMannequinWithDefaultHairstyle) {
  test::useSoftwareRendering();
  const Character character = makeDefaultMannequin();
  const std::unique_ptr<HairGroom> groom = makeCharacterGroom(character, ScalpRegion{});
  const HairStyle style = builtinHairStyle(builtinHairStyleNames().front());
  groom->grow(style, 20000);
  ASSERT_EQ(groom->countPointsInside(), 0u);

  render::SceneView view;
  view.setCharacter(character);
  PosedCharacter posed;
  posed.evaluate(character, -1, 0.0f, nullptr, nullptr);
  view.updatePose(posed);
  const glm::vec3 head = groom->proxy().headCenter();
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  render::HairActor hair;
  hair.setStrands(groom->strands());
  hair.setColors(style.rootColor, style.tipColor);
  view.addProp(hair.actor());
  for (const auto& [name, offset] :
       {std::pair{"front", glm::vec3(0.45f, 0.15f, 1.0f)}, std::pair{"back", glm::vec3(-0.45f, 0.2f, -1.0f)}}) {
    view.setCamera(head + offset, head + glm::vec3(0.0f, -0.15f, 0.0f));
    hair.setVisible(false);
    const render::RgbImage bare = renderer.capture();
    hair.setVisible(true);
    const render::RgbImage image = renderer.capture();
    const test::Foreground f = test::foregroundOf(image, bare);
    EXPECT_GT(f.fraction, 0.08) << name;
    const std::string why = test::checkAgainstBaseline(image, std::string("hair_default_") + name);
    EXPECT_TRUE(why.empty()) << why;
  }
}

TEST_F(HairRenderTest, OpacityShadowMapsShadeInnerStrands) {
  const Strands strands = combedStrands(8000, 24, 0.3f);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage bare = renderer.capture();
  render::HairActor hair;
  hair.setStrands(strands);
  render::HairShading shading = hair.shading();
  shading.shadowMethod = render::HairShadowMethod::OpacityMaps;
  hair.setShading(shading);
  view.addProp(hair.actor());
  const render::RgbImage image = renderer.capture();
  shading.selfShadowing = false;
  hair.setShading(shading);
  const render::RgbImage flat = renderer.capture();
  shading.selfShadowing = true;
  shading.shadowMethod = render::HairShadowMethod::PointCount;
  hair.setShading(shading);
  const render::RgbImage counted = renderer.capture();

  EXPECT_GT(test::foregroundOf(image, bare).fraction, 0.10);
  double sumMaps = 0.0, sumFlat = 0.0, sumCounted = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      sumMaps += luminance(image.at(x, y));
      sumFlat += luminance(flat.at(x, y));
      sumCounted += luminance(counted.at(x, y));
    }
  EXPECT_GT(sumFlat, sumMaps * 1.03);            // the maps shadow the hair
  EXPECT_NEAR(sumMaps / sumCounted, 1.0, 0.05);  // about as much as the exact count
  const std::string why = test::checkAgainstBaseline(image, "hair_draped_sphere_osm");
  EXPECT_TRUE(why.empty()) << why;
}

// A built-in style on an imported character (CesiumMan: no scalp tags, no
// "head" bone, a head about 1.5 times the mannequin's), fitted to its head.
// Seen from the same place relative to the head (distances in head sizes),
// the bob covers about as much of the picture as on the default mannequin:
// it is proportional to the head, not a mannequin-sized cap.
TEST(HairRenderImported, FittedBobOnCesiumManLooksLikeOnTheMannequin) {
  test::useSoftwareRendering();
  auto hairCoverage = [](const Character& character, const std::string& baseline) {
    HairSection section;
    section.style = builtinHairStyle("bob");
    std::unique_ptr<HairGroom> groom = makeSectionGroom(character, section);
    groom->grow(section.style, 20000);
    EXPECT_EQ(groom->countPointsInside(), 0u) << character.name;
    render::SceneView view;
    view.setCharacter(character);
    view.setGridVisible(false);
    PosedCharacter posed;
    posed.evaluate(character, -1, 0.0f, nullptr, nullptr);
    view.updatePose(posed);
    const glm::vec3 head = groom->proxy().headCenter();
    const float size = headSize(groom->proxy());
    view.setCamera(head + size * glm::vec3(-7.0f, 3.0f, -11.0f), head + size * glm::vec3(0.0f, -1.0f, 0.0f));
    render::OffscreenRenderer renderer(view, kWidth, kHeight);
    const render::RgbImage bare = renderer.capture();
    render::HairActor hair;
    hair.setStrands(groom->strands());
    hair.setColors(section.style.rootColor, section.style.tipColor);
    view.addProp(hair.actor());
    const render::RgbImage image = renderer.capture();
    if (!baseline.empty()) {
      const std::string why = test::checkAgainstBaseline(image, baseline);
      EXPECT_TRUE(why.empty()) << why;
    }
    return test::foregroundOf(image, bare);
  };
  const std::string path = std::string(MANNEQUIN_SHARED_DIR) + "/assets/characters/CesiumMan/glTF-Binary/CesiumMan.glb";
  const test::Foreground cesium = hairCoverage(importCharacter(path), "hair_cesium_man_bob");
  const test::Foreground mannequin = hairCoverage(makeDefaultMannequin(), "");
  EXPECT_GT(cesium.fraction, 0.08);
  EXPECT_GT(cesium.fraction / mannequin.fraction, 0.6);
  EXPECT_LT(cesium.fraction / mannequin.fraction, 1.6);
  // Centred on the head, as on the mannequin.
  EXPECT_LT(glm::length(cesium.centre - mannequin.centre), 0.15);
}

}  // namespace
}  // namespace mq
