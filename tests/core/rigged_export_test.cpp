#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <string>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/io/character_import.h"
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
