// Materials from files on screen: textures show, alpha MASK cuts, normal
// maps shade, a missing image is a warning, the floor sits under the feet.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkUnsignedCharArray.h>

#include "core/character/posed_character.h"
#include "core/gltf_test_util.h"
#include "core/io/character_import.h"
#include "render/image_checks.h"
#include "render/material_textures.h"
#include "render/offscreen.h"
#include "render/scene_view.h"

namespace mq {
namespace {

using nlohmann::json;
constexpr int kWidth = 240, kHeight = 240;
const std::string kShared = MANNEQUIN_SHARED_DIR;

// PNG bytes of a width x height RGBA image from `texel(x, y)` (y = 0 the top row).
template <typename Texel>
std::vector<uint8_t> encodePng(int width, int height, Texel texel) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::array<uint8_t, 4> c = texel(x, y);
      auto* out = static_cast<uint8_t*>(image->GetScalarPointer(x, height - 1 - y, 0));  // VTK rows go up
      for (int k = 0; k < 4; ++k) out[k] = c[k];
    }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* result = writer->GetResult();
  return {result->GetPointer(0), result->GetPointer(0) + result->GetNumberOfValues()};
}

// A unit quad facing +z (uv (0,0) at its top left) with one material.
std::string writeQuad(const std::string& name, const json& material, const std::vector<json>& images) {
  test::Buffer b;
  const size_t positions = b.add(std::vector<float>{-0.5f, 0, 0, 0.5f, 0, 0, -0.5f, 1, 0, 0.5f, 1, 0});
  const size_t normals = b.add(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
  const size_t uvs = b.add(std::vector<float>{0, 1, 1, 1, 0, 0, 1, 0});
  const size_t indices = b.add(std::vector<uint16_t>{0, 1, 2, 1, 3, 2});
  json g;
  g["bufferViews"] = {{{"buffer", 0}, {"byteOffset", positions}, {"byteLength", 48}},
                      {{"buffer", 0}, {"byteOffset", normals}, {"byteLength", 48}},
                      {{"buffer", 0}, {"byteOffset", uvs}, {"byteLength", 32}},
                      {{"buffer", 0}, {"byteOffset", indices}, {"byteLength", 12}}};
  g["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                    {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                    {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
                    {{"bufferView", 3}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}};
  g["meshes"] = {
      {{"primitives",
        {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}}, {"indices", 3}, {"material", 0}}}}}};
  g["nodes"] = {{{"mesh", 0}}};
  g["scenes"] = {{{"nodes", {0}}}};
  g["materials"] = {material};
  if (!images.empty()) {
    g["images"] = images;
    g["textures"] = json::array();
    for (size_t i = 0; i < images.size(); ++i) g["textures"].push_back({{"source", i}});
  }
  return test::writeGltf(name, g, b);
}

json pngImage(const std::vector<uint8_t>& png) { return {{"uri", "data:image/png;base64," + test::base64(png)}}; }

class MaterialRenderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { test::useSoftwareRendering(); }

  void show(const Character& c, int clip = -1, float time = 0.0f) {
    character = c;
    view.setCharacter(character);
    posed.evaluate(character, clip, time, nullptr, nullptr);
    view.updatePose(posed);
    view.frameAll(double(kWidth) / kHeight);
  }
  // Straight on, so the quad fills the middle of the image.
  void lookStraightAtQuad() { view.setCamera({0.0f, 0.5f, 2.2f}, {0.0f, 0.5f, 0.0f}); }
  render::RgbImage withoutCharacter(render::OffscreenRenderer& r) {
    for (int i = 0; vtkActor* a = view.meshActor(i); ++i) a->VisibilityOff();
    render::RgbImage image = r.capture();
    for (int i = 0; vtkActor* a = view.meshActor(i); ++i) a->VisibilityOn();
    return image;
  }

  Character character;
  render::SceneView view;
  PosedCharacter posed;
};

// Pixels of the figure where blue or green clearly leads: CesiumMan's
// texture is white with blue and green bands.
struct BandPixels {
  size_t blue = 0, green = 0, figure = 0;
};
BandPixels bandPixels(const render::RgbImage& image, const render::RgbImage& empty) {
  BandPixels n;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.at(x, y);
      const uint8_t* e = empty.at(x, y);
      if (std::abs(int(p[0]) - e[0]) + std::abs(int(p[1]) - e[1]) + std::abs(int(p[2]) - e[2]) <= 36) continue;
      ++n.figure;
      if (p[2] > p[0] + 50 && p[2] > p[1] + 10) ++n.blue;
      if (p[1] > p[0] + 30 && p[1] > p[2] + 20) ++n.green;
    }
  return n;
}

TEST_F(MaterialRenderTest, CesiumManShowsItsTexture) {
  show(importCharacter(kShared + "/assets/characters/CesiumMan/glTF/CesiumMan.gltf"), 0, 0.5f);
  EXPECT_TRUE(view.warnings().empty());
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage empty = withoutCharacter(renderer);
  const render::RgbImage textured = renderer.capture();
  const BandPixels bands = bandPixels(textured, empty);
  ASSERT_GT(bands.figure, 2000u);
  EXPECT_GT(bands.blue, bands.figure / 20) << "the texture's blue bands";
  EXPECT_GT(bands.green, bands.figure / 40) << "the texture's green bands";
  view.setLookMode(render::LookMode::Plain);
  const BandPixels plain = bandPixels(renderer.capture(), empty);
  EXPECT_LT(plain.blue + plain.green, bands.figure / 200) << "without the texture, no bands";
  view.setLookMode(render::LookMode::Auto);
  const std::string problem = test::checkAgainstBaseline(renderer.capture(), "material_cesium_man");
  EXPECT_TRUE(problem.empty()) << problem;
}

TEST_F(MaterialRenderTest, SkinMaterialKeepsItsTextureAsAlbedo) {
  Character c = importCharacter(kShared + "/assets/characters/CesiumMan/glTF/CesiumMan.gltf");
  c.materials[0].skin = true;
  show(c, 0, 0.5f);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage empty = withoutCharacter(renderer);
  const render::RgbImage skin = renderer.capture();
  const BandPixels bands = bandPixels(skin, empty);
  ASSERT_GT(bands.figure, 2000u);
  EXPECT_GT(bands.blue, bands.figure / 25) << "the texture's blue bands under skin shading";
  // And it is shaded differently from the physically based material.
  c.materials[0].skin = false;
  view.setMaterial(0, c.materials[0]);
  EXPECT_GT(test::compareImages(skin, renderer.capture()).rms, 2.0);
}

TEST_F(MaterialRenderTest, GlbEmbeddedTextureMatchesTheGltfOne) {
  show(importCharacter(kShared + "/assets/characters/CesiumMan/glTF/CesiumMan.gltf"), 0, 0.5f);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage fromFile = renderer.capture();
  show(importCharacter(kShared + "/assets/characters/CesiumMan/glTF-Binary/CesiumMan.glb"), 0, 0.5f);
  const test::ImageDifference d = test::compareImages(fromFile, renderer.capture());
  EXPECT_LT(d.rms, 1.0);
}

// Left half of the texture transparent, right half opaque red.
std::vector<uint8_t> halfTransparentPng() {
  return encodePng(16, 16, [](int x, int) { return std::array<uint8_t, 4>{220, 30, 30, uint8_t(x < 8 ? 0 : 255)}; });
}

double coveredFraction(const render::RgbImage& image, const render::RgbImage& empty, int x0, int x1) {
  size_t covered = 0, all = 0;
  for (int y = kHeight / 3; y < 2 * kHeight / 3; ++y)
    for (int x = x0; x < x1; ++x, ++all)
      if (std::abs(int(image.at(x, y)[0]) - empty.at(x, y)[0]) > 24) ++covered;
  return double(covered) / double(all);
}

TEST_F(MaterialRenderTest, AlphaMaskCutsWhereTheTextureIsTransparent) {
  const json texture = {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0.0}};
  const auto png = halfTransparentPng();
  show(importCharacter(
      writeQuad("mask.gltf", {{"pbrMetallicRoughness", texture}, {"alphaMode", "MASK"}}, {pngImage(png)})));
  lookStraightAtQuad();
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage empty = withoutCharacter(renderer);
  const render::RgbImage masked = renderer.capture();
  // The quad spans about the middle half of the image, straight on.
  EXPECT_LT(coveredFraction(masked, empty, kWidth / 3, kWidth / 2 - 4), 0.05) << "transparent half cut away";
  EXPECT_GT(coveredFraction(masked, empty, kWidth / 2 + 4, 2 * kWidth / 3), 0.95) << "opaque half drawn";

  show(importCharacter(writeQuad("opaque.gltf", {{"pbrMetallicRoughness", texture}}, {pngImage(png)})));
  lookStraightAtQuad();
  const render::RgbImage opaque = renderer.capture();
  EXPECT_GT(coveredFraction(opaque, empty, kWidth / 3, kWidth / 2 - 4), 0.95) << "OPAQUE ignores alpha";
}

TEST_F(MaterialRenderTest, NormalMapShadesAFlatQuad) {
  // Vertical stripes of normals tilted left and right.
  const auto bumps = encodePng(32, 32, [](int x, int) {
    const uint8_t tilt = (x / 4) % 2 ? 200 : 55;
    return std::array<uint8_t, 4>{tilt, 128, 230, 255};
  });
  const json base = {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.6}};
  show(importCharacter(writeQuad("flat.gltf", {{"pbrMetallicRoughness", base}}, {})));
  lookStraightAtQuad();
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage flat = renderer.capture();
  show(importCharacter(
      writeQuad("bumpy.gltf", {{"pbrMetallicRoughness", base}, {"normalTexture", {{"index", 0}}}}, {pngImage(bumps)})));
  lookStraightAtQuad();
  const render::RgbImage bumpy = renderer.capture();
  EXPECT_GT(test::compareImages(flat, bumpy).rms, 3.0);
  // A flat normal map (all texels straight out) changes nothing visible.
  const auto straight = encodePng(8, 8, [](int, int) { return std::array<uint8_t, 4>{128, 128, 255, 255}; });
  show(importCharacter(writeQuad("straight.gltf", {{"pbrMetallicRoughness", base}, {"normalTexture", {{"index", 0}}}},
                                 {pngImage(straight)})));
  lookStraightAtQuad();
  EXPECT_LT(test::compareImages(flat, renderer.capture()).rms, 1.5);
}

TEST_F(MaterialRenderTest, UnreadableImageIsAWarningAndTheFactorsRemain) {
  const json material = {
      {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"baseColorFactor", {0.1, 0.6, 0.1, 1}}}}};
  // Bytes that claim to be a PNG and are not one.
  const std::vector<uint8_t> broken{0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A, 1, 2, 3};
  show(importCharacter(writeQuad("broken_image.gltf", material, {pngImage(broken)})));
  ASSERT_EQ(view.warnings().size(), 1u);
  EXPECT_NE(view.warnings()[0].find("image 0"), std::string::npos) << view.warnings()[0];
  lookStraightAtQuad();
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage image = renderer.capture();
  const uint8_t* centre = image.at(kWidth / 2, kHeight / 2);
  EXPECT_GT(centre[1], centre[0] + 40) << "the green factor still shows";
}

TEST_F(MaterialRenderTest, TruncatedEmbeddedJpegIsAWarningNotACrash) {
  Character c = importCharacter(kShared + "/assets/characters/CesiumMan/glTF-Binary/CesiumMan.glb");
  ASSERT_EQ(c.images.size(), 1u);
  std::vector<uint8_t>& jpeg = c.images[0].encoded;
  for (size_t keep : {jpeg.size() / 2, size_t(600), size_t(3)}) {
    Character cut = c;
    cut.images[0].encoded.resize(keep);
    show(cut);
    render::OffscreenRenderer renderer(view, 64, 64);
    renderer.capture();
    // A partly decodable JPEG may still show its top rows; a stub must warn.
    if (keep <= 600) {
      ASSERT_EQ(view.warnings().size(), 1u) << keep;
      EXPECT_NE(view.warnings()[0].find("could not be decoded"), std::string::npos) << view.warnings()[0];
    }
  }
}

TEST_F(MaterialRenderTest, FloorSitsUnderTheLowestPointWhateverTheOrigin) {
  Character c = importCharacter(writeQuad("low.gltf", {{"name", "m"}}, {}));
  for (size_t v = 0; v < c.meshes[0].vertexCount(); ++v) c.meshes[0].positions[3 * v + 1] -= 0.9f;  // origin at the top
  show(c);
  EXPECT_NEAR(view.floorHeight(), -0.9f, 1e-6f);
}

}  // namespace
}  // namespace mq

namespace mq {
namespace {

// Mutated texture images (random bytes changed in CesiumMan's JPEG and in a
// PNG): each decodes or becomes a warning; never a crash.
TEST(MaterialTexturesFuzz, MutatedImagesDecodeOrWarn) {
  const Character c = importCharacter(kShared + "/assets/characters/CesiumMan/glTF-Binary/CesiumMan.glb");
  const std::vector<uint8_t> jpeg = c.images.at(0).encoded;
  const std::vector<uint8_t> png = encodePng(24, 24, [](int x, int y) {
    return std::array<uint8_t, 4>{uint8_t(x * 10), uint8_t(y * 10), 99, 255};
  });
  std::mt19937 rng(777);
  for (const std::vector<uint8_t>* original : {&jpeg, &png}) {
    int decoded = 0, warned = 0;
    for (int round = 0; round < 60; ++round) {
      std::vector<ImageSource> images(1);
      images[0].name = "mutant";
      images[0].encoded = *original;
      for (int f = 0; f < 4; ++f)
        images[0].encoded[std::uniform_int_distribution<size_t>(0, original->size() - 1)(rng)] = uint8_t(rng());
      render::MaterialTextures textures(images);
      TextureRef ref;
      ref.image = 0;
      if (textures.colour(ref))
        ++decoded;
      else
        ++warned;
      EXPECT_EQ(textures.warnings().size(), textures.colour(ref) ? 0u : 1u);
    }
    EXPECT_EQ(decoded + warned, 60);
  }
}

}  // namespace
}  // namespace mq
