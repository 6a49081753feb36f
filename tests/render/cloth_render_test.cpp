// The cloth shader on a T-shirt placed around the default mannequin:
// the shirt shows, each model and option changes the picture the way it
// should, and one image matches its baseline. The draped PNGs are also
// written to <build>/Testing/Temporary/cloth_render/ for people to look at.
#include <gtest/gtest.h>

#include <filesystem>

#include <vtkActor.h>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/garment/parametric_garments.h"
#include "render/cloth_shading.h"
#include "render/image_checks.h"
#include "render/offscreen.h"
#include "render/scene_view.h"

namespace mq {
namespace {

constexpr int kWidth = 320, kHeight = 320;

struct DrapedShirt {
  std::vector<float> positions, uvs;
  std::vector<uint32_t> triangles;
};

// The T-shirt as placed around the body before sewing (panels wrapped on
// cylinders around the torso and the upper arms): a fixed subject for the
// shading, independent of the solver. (A sewn drape, GarmentSimulation,
// would be the better one now that sewing settles on the shoulders.)
DrapedShirt placedShirt(const Character& body) {
  Garment shirt = makeParametricGarment("tshirt", body);
  shirt.targetEdgeLength = 0.02f;
  GarmentMesh garment = buildGarmentMesh(shirt);
  return {garment.positions, garment.restUvs, garment.triangles};
}

class ClothRenderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    test::useSoftwareRendering();
    body = new Character(makeDefaultMannequin());
    shirt = new DrapedShirt(placedShirt(*body));
  }
  static void TearDownTestSuite() {
    delete shirt;
    delete body;
  }

  void SetUp() override {
    view.setCharacter(*body);
    view.setGridVisible(false);
    view.setSkeletonVisible(false);
    cloth.setMesh(shirt->positions, shirt->triangles, shirt->uvs);
    view.addProp(cloth.actor());
    view.setCamera({0.55f, 1.45f, 1.5f}, {0.0f, 1.2f, 0.0f});
  }

  render::RgbImage shot(const render::ClothShading& shading, const std::string& name) {
    cloth.setShading(shading);
    render::OffscreenRenderer renderer(view, kWidth, kHeight);
    render::RgbImage image = renderer.capture();
    auto dir = std::filesystem::path(MANNEQUIN_BINARY_DIR) / "Testing" / "Temporary" / "cloth_render";
    std::filesystem::create_directories(dir);
    render::writePng(image, (dir / (name + ".png")).string());
    return image;
  }
  render::RgbImage withoutShirt() {
    cloth.setVisible(false);
    render::OffscreenRenderer renderer(view, kWidth, kHeight);
    render::RgbImage image = renderer.capture();
    cloth.setVisible(true);
    return image;
  }

  static Character* body;
  static DrapedShirt* shirt;
  render::SceneView view;
  render::ClothActor cloth;
};

Character* ClothRenderTest::body = nullptr;
DrapedShirt* ClothRenderTest::shirt = nullptr;

// Mean brightness of the pixels that the shirt changed.
double shirtBrightness(const render::RgbImage& image, const render::RgbImage& background) {
  double sum = 0.0;
  size_t n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t *a = image.at(x, y), *b = background.at(x, y);
      if (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) < 40) continue;
      sum += (a[0] + a[1] + a[2]) / 3.0;
      ++n;
    }
  return n ? sum / n : 0.0;
}

TEST_F(ClothRenderTest, ShirtCoversTheTorso) {
  render::RgbImage background = withoutShirt();
  render::RgbImage image = shot(render::clothShadingForFabric("cotton"), "cotton");
  test::Foreground shirtPixels = test::foregroundOf(image, background);
  EXPECT_GT(shirtPixels.fraction, 0.08);
  EXPECT_GT(shirtPixels.centre.y, 0.2);  // the torso, not the legs or the head
  EXPECT_LT(shirtPixels.centre.y, 0.8);
}

TEST_F(ClothRenderTest, MinnaertBrightensGrazingAnglesForVelvetAndDarkensForLeather) {
  render::RgbImage background = withoutShirt();
  render::ClothShading s = render::clothShadingForFabric("cotton");
  s.minnaertK = 1.0f;
  double lambert = shirtBrightness(shot(s, "minnaert_k1"), background);
  s.minnaertK = 0.55f;
  double velvet = shirtBrightness(shot(s, "minnaert_k055"), background);
  s.minnaertK = 1.4f;
  double dark = shirtBrightness(shot(s, "minnaert_k14"), background);
  // (N.V)^(k-1) >= 1 for k < 1 and <= 1 for k > 1, at the same N.L.
  EXPECT_GT(velvet, lambert + 3.0);
  EXPECT_LT(dark, lambert - 3.0);
}

TEST_F(ClothRenderTest, SheenPrintAndRibsEachChangeTheImage) {
  render::ClothShading base = render::clothShadingForFabric("velvet");
  render::RgbImage minnaert = shot(base, "velvet_minnaert");
  render::ClothShading sheen = base;
  sheen.model = render::ClothModel::AshikhminSheen;
  render::RgbImage ashikhmin = shot(sheen, "velvet_ashikhmin");
  EXPECT_GT(test::compareImages(minnaert, ashikhmin).rms, 2.0);

  render::ClothShading printed = render::clothShadingForFabric("cotton");
  render::RgbImage plain = shot(printed, "plain");
  cloth.setPrint(render::ClothActor::defaultPrint());
  printed.printed = true;
  render::RgbImage print = shot(printed, "printed");
  EXPECT_GT(test::compareImages(plain, print).changedFraction, 0.03);
  // The print's navy stripes show: pixels clearly bluer than red.
  size_t navy = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      if (print.at(x, y)[2] > print.at(x, y)[0] + 30) ++navy;
  EXPECT_GT(navy, size_t(kWidth * kHeight / 200));

  render::ClothShading ribbed = render::clothShadingForFabric("rib-knit");
  render::ClothShading flat = ribbed;
  flat.ribbed = false;
  ribbed.ribSpacing = 0.02f;  // wide enough to resolve at this image size
  EXPECT_GT(test::compareImages(shot(flat, "rib_off"), shot(ribbed, "rib_on")).rms, 1.0);
}

TEST_F(ClothRenderTest, VelvetShirtMatchesBaseline) {
  render::RgbImage image = shot(render::clothShadingForFabric("velvet"), "baseline_velvet");
  const std::string why = test::checkAgainstBaseline(image, "cloth_tshirt_velvet");
  EXPECT_TRUE(why.empty()) << why;
}

}  // namespace
}  // namespace mq
