#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <string>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/io/character_import.h"
#include "core/io/file_bytes.h"
#include "core/io/rigged_export.h"
#include "core/util/error.h"

namespace mq {
namespace {

namespace fs = std::filesystem;

std::string scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("mq_rigged_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}

float largestDifference(const Character& a, const Character& b, int clip, float time) {
  PosedCharacter pa, pb;
  pa.evaluate(a, clip, time, nullptr, nullptr);
  pb.evaluate(b, b.findClip(a.clips[clip].name), time, nullptr, nullptr);
  float worst = 0.0f;
  for (size_t m = 0; m < pa.meshes().size(); ++m)
    for (size_t i = 0; i < pa.meshes()[m].positions.size(); ++i)
      worst = std::max(worst, std::abs(pa.meshes()[m].positions[i] - pb.meshes()[m].positions[i]));
  return worst;
}

// The mannequin with helper bones, written rigged and read back by the glTF
// reader: plain LBS on the file gives the same skin as Mannequin does.
TEST(RiggedExport, MannequinWithHelperBonesRoundTrips) {
  Character original = makeDefaultMannequin();
  ASSERT_GT(addHelperBones(original), 0);
  const std::string path = scratch("mannequin.glb");
  exportRiggedCharacter(original, path, 30.0f);
  const Character back = importCharacter(path);
  ASSERT_EQ(back.skeleton.boneCount(), original.skeleton.boneCount());
  EXPECT_GE(back.skeleton.findBone("forearm_l_twist2"), 0);
  ASSERT_EQ(back.clips.size(), original.clips.size());
  ASSERT_EQ(back.meshes.size(), 1u);
  EXPECT_EQ(back.meshes[0].vertexCount(), original.meshes[0].vertexCount());
  // At a sample time the skins agree to float precision; between samples
  // the file's linear keys differ from the clip's own curves by millimetres
  // (4.5 mm on the walk at 30 fps).
  EXPECT_LT(largestDifference(original, back, 0, 0.4f), 1e-5f);
  EXPECT_LT(largestDifference(original, back, 1, 1.0f), 1e-5f);
  EXPECT_LT(largestDifference(original, back, 0, 0.41f), 1e-2f);
}

// CesiumMan: a file whose joints sit under non-joint nodes.
TEST(RiggedExport, CesiumManRoundTrips) {
  const Character original =
      importCharacter(std::string(MANNEQUIN_SHARED_DIR) + "/assets/characters/CesiumMan/glTF/CesiumMan.gltf");
  const std::string path = scratch("cesium.gltf");
  exportRiggedCharacter(original, path, 30.0f);
  const Character back = importCharacter(path);
  ASSERT_EQ(back.skeleton.boneCount(), original.skeleton.boneCount());
  ASSERT_FALSE(back.clips.empty());
  const float t = original.clips[0].startTime() + 10.0f / 30.0f;
  EXPECT_LT(largestDifference(original, back, 0, t), 1e-4f);
}

// A morph target animated by a clip: the file plays it as Mannequin does.
TEST(RiggedExport, MorphTargetsAndTheirWeightsRoundTrip) {
  Character original = makeDefaultMannequin();
  Mesh& body = original.meshes[0];
  MorphTarget swell{"swell", {}, {}};
  for (size_t v = 0; v < body.vertexCount(); ++v)
    for (int d = 0; d < 3; ++d) swell.positionDeltas.push_back(0.02f * body.normals[3 * v + d]);
  body.morphTargets.push_back(swell);
  body.morphWeights = {0.25f};
  MorphChannel channel;
  channel.mesh = 0;
  channel.weights.components = 1;
  channel.weights.times = {0.0f, 1.0f};
  channel.weights.values = {0.0f, 1.0f};
  original.clips[0].morphChannels.push_back(channel);
  const std::string path = scratch("swell.glb");
  exportRiggedCharacter(original, path, 30.0f);
  const Character back = importCharacter(path);
  ASSERT_EQ(back.meshes[0].morphTargets.size(), 1u);
  EXPECT_EQ(back.meshes[0].morphTargets[0].name, "swell");
  ASSERT_EQ(back.meshes[0].morphWeights.size(), 1u);
  EXPECT_FLOAT_EQ(back.meshes[0].morphWeights[0], 0.25f);
  EXPECT_LT(largestDifference(original, back, 0, 0.5f), 1e-5f);  // a sample time, weight 0.5
  EXPECT_LT(largestDifference(original, back, 1, 0.5f), 1e-5f);  // another clip: the default weight
}

// CesiumMan's material and its JPEG texture go into the file, byte for byte.
TEST(RiggedExport, MaterialsAndTexturesRoundTrip) {
  Character original =
      importCharacter(std::string(MANNEQUIN_SHARED_DIR) + "/assets/characters/CesiumMan/glTF/CesiumMan.gltf");
  ASSERT_FALSE(original.materials.empty());
  ASSERT_TRUE(original.materials[0].baseColorTexture.present());
  original.materials[0].skin = true;
  const std::string path = scratch("cesium_materials.glb");
  EXPECT_TRUE(exportRiggedCharacter(original, path, 30.0f).empty());
  const Character back = importCharacter(path);
  ASSERT_EQ(back.materials.size(), original.materials.size());
  const Material& m = back.materials[0];
  EXPECT_TRUE(m.skin);
  EXPECT_EQ(m.name, original.materials[0].name);
  EXPECT_FLOAT_EQ(m.roughnessFactor, original.materials[0].roughnessFactor);
  ASSERT_TRUE(m.baseColorTexture.present());
  const ImageSource& image = original.images[original.materials[0].baseColorTexture.image];
  const std::vector<uint8_t> originalBytes = image.encoded.empty() ? readFileBytes(image.path) : image.encoded;
  EXPECT_EQ(back.images[m.baseColorTexture.image].encoded, originalBytes);
  ASSERT_EQ(back.meshes.size(), original.meshes.size());
  EXPECT_EQ(back.meshes[0].drawRanges()[0].material, 0);
}

// A take: the walk's first frames with a baked sheet of cloth and a baked
// strand of hair; each frame of the file shows that frame's positions.
TEST(RiggedExport, BakedSurfacesPlayFrameByFrame) {
  const Character original = makeDefaultMannequin();
  RiggedExportOptions options;
  options.take = ExportTake{"walk take", 0, 0.2f, 24.0f, 5, nullptr};
  BakedSurface cloth{"sheet", {0, 1, 2, 1, 3, 2}, {}, {}, {0.2f, 0.3f, 0.8f, 1.0f}};
  BakedSurface hair{"strands", {}, {0, 1, 1, 2}, {}, {0.1f, 0.05f, 0.02f, 1.0f}};
  for (int f = 0; f < 5; ++f) {
    const float y = 1.0f - 0.1f * f;  // falling
    cloth.frames.push_back({0, y, 0, 1, y, 0, 0, y, 1, 1, y + 0.01f * f, 1});
    hair.frames.push_back({0, 1.7f, 0, 0.05f * f, 1.6f, 0, 0.1f * f, 1.5f, 0});
  }
  options.baked = {cloth, hair};
  const std::string path = scratch("take.gltf");
  exportRiggedCharacter(original, path, options);
  const Character back = importCharacter(path);
  ASSERT_EQ(back.clips.size(), 1u);
  EXPECT_EQ(back.clips[0].name, "walk take");
  ASSERT_EQ(back.meshes.size(), 3u);
  for (int f : {0, 3, 4}) {
    PosedCharacter posed, expected;
    posed.evaluate(back, 0, f / 24.0f, nullptr, nullptr);
    expected.evaluate(original, 0, 0.2f + f / 24.0f, nullptr, nullptr);
    for (int s = 0; s < 2; ++s) {
      const std::vector<float>& got = posed.meshes()[1 + s].positions;
      const std::vector<float>& want = options.baked[s].frames[f];
      ASSERT_EQ(got.size(), want.size());
      for (size_t k = 0; k < got.size(); ++k) EXPECT_NEAR(got[k], want[k], 1e-5f) << "surface " << s << " frame " << f;
    }
    float worst = 0.0f;  // the character plays the clip from the take's start
    for (size_t k = 0; k < expected.meshes()[0].positions.size(); ++k)
      worst = std::max(worst, std::abs(expected.meshes()[0].positions[k] - posed.meshes()[0].positions[k]));
    EXPECT_LT(worst, 1e-5f) << "frame " << f;
  }
  EXPECT_TRUE(back.meshes[2].triangles.empty());  // lines: no triangles to shade
}

TEST(RiggedExport, RefusesBakedFramesThatDoNotMatchTheTake) {
  const Character c = makeDefaultMannequin();
  RiggedExportOptions options;
  options.take = ExportTake{"take", 0, 0.0f, 30.0f, 3, nullptr};
  options.baked.push_back(BakedSurface{"sheet", {0, 1, 2}, {}, {{0, 0, 0, 1, 0, 0, 0, 1, 0}}, {}});
  EXPECT_THROW(exportRiggedCharacter(c, scratch("bad_take.glb"), options), FileError);
  options.baked[0].frames.assign(3, {0, 0, 0, 1, 0, 0});  // two vertices, index 2
  EXPECT_THROW(exportRiggedCharacter(c, scratch("bad_take.glb"), options), FileError);
  EXPECT_FALSE(fs::exists(scratch("bad_take.glb")));
}

TEST(RiggedExport, RefusesOtherFormatsNamingTheFile) {
  const Character c = makeDefaultMannequin();
  try {
    exportRiggedCharacter(c, scratch("mannequin.obj"), 30.0f);
    FAIL() << "no error";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(".gltf or .glb"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(scratch("mannequin.obj")));
}

}  // namespace
}  // namespace mq
