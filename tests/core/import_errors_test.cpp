// Bad input never crashes the importer: truncated, garbage, mislabelled or
// missing files each throw one FileError that names the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "core/io/character_import.h"
#include "core/io/file_bytes.h"
#include "core/util/error.h"
#include "import_test_util.h"

namespace mq {
namespace {

const std::string kCharacters = std::string(MANNEQUIN_SHARED_DIR) + "/assets/characters/";

std::filesystem::path tempDir() {
  const auto dir = test::scratchDir("mq_import_errors");
  return dir;
}

std::string writeTemp(const std::string& name, const std::string& content) {
  const std::string path = (tempDir() / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

std::string garbage(size_t n) {
  std::string s(n, '\0');
  uint32_t x = 2463534242u;
  for (char& c : s) {
    x ^= x << 13, x ^= x >> 17, x ^= x << 5;
    c = static_cast<char>(x & 0xFF);
  }
  return s;
}

// Returns the message so callers can check more of it.
std::string expectFileError(const std::string& path) {
  try {
    importCharacter(path);
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), path);
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
    EXPECT_FALSE(e.problem().empty());
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << path << ": not a FileError: " << e.what();
    return {};
  }
  ADD_FAILURE() << path << ": imported without error";
  return {};
}

TEST(ImportErrors, MissingFile) {
  EXPECT_NE(expectFileError((tempDir() / "nothing_here.gltf").string()).find("no such file"), std::string::npos);
}

TEST(ImportErrors, TruncatedGltfJson) {
  const std::string text = loadFileText(kCharacters + "CesiumMan/glTF/CesiumMan.gltf");
  for (size_t cut : {size_t(0), size_t(1), text.size() / 3, text.size() - 2})
    expectFileError(writeTemp("cut" + std::to_string(cut) + ".gltf", text.substr(0, cut)));
}

TEST(ImportErrors, TruncatedGlb) {
  const std::string bytes = loadFileText(kCharacters + "CesiumMan/glTF-Binary/CesiumMan.glb");
  for (size_t cut : {size_t(3), size_t(16), size_t(100), bytes.size() / 2, bytes.size() - 1})
    expectFileError(writeTemp("cut" + std::to_string(cut) + ".glb", bytes.substr(0, cut)));
}

TEST(ImportErrors, TruncatedExternalBuffer) {
  const auto dir = tempDir() / "shortbin";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(kCharacters + "RiggedSimple/RiggedSimple.gltf", dir / "RiggedSimple.gltf",
                             std::filesystem::copy_options::overwrite_existing);
  const std::string bin = loadFileText(kCharacters + "RiggedSimple/RiggedSimple0.bin");
  std::ofstream(dir / "RiggedSimple0.bin", std::ios::binary) << bin.substr(0, bin.size() / 2);
  EXPECT_NE(expectFileError((dir / "RiggedSimple.gltf").string()).find("truncated"), std::string::npos);
  std::filesystem::remove(dir / "RiggedSimple0.bin");
  EXPECT_NE(expectFileError((dir / "RiggedSimple.gltf").string()).find("RiggedSimple0.bin"), std::string::npos);
}

TEST(ImportErrors, GltfWithBadReferences) {
  expectFileError(writeTemp("v1.gltf", R"({"asset": {"version": "1.0"}})"));
  expectFileError(
      writeTemp("badnode.gltf", R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [5]}], "nodes": []})"));
  expectFileError(writeTemp("badmesh.gltf", R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 3}]})"));
  expectFileError(writeTemp("cycle.gltf", R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}],
                                              "nodes": [{"children": [1]}, {"children": [0]}]})"));
  EXPECT_NE(expectFileError(writeTemp("draco.gltf", R"({"asset": {"version": "2.0"},
      "extensionsRequired": ["KHR_draco_mesh_compression"], "extensionsUsed": ["KHR_draco_mesh_compression"]})"))
                .find("KHR_draco_mesh_compression"),
            std::string::npos);
  expectFileError(writeTemp("hugecount.gltf", R"({"asset": {"version": "2.0"},
      "accessors": [{"componentType": 5126, "count": 9000000000000, "type": "VEC3"}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0}]})"));
  expectFileError(writeTemp("badaccessor.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 4,
      "uri": "data:application/octet-stream;base64,AAAAAA=="}], "bufferViews": [{"buffer": 0, "byteLength": 4}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0}]})"));
}

TEST(ImportErrors, GarbageBytesWithEveryExtension) {
  for (const char* ext : {"gltf", "glb", "fbx", "dae", "bvh"})
    expectFileError(writeTemp(std::string("garbage.") + ext, garbage(4096)));
}

TEST(ImportErrors, EmptyFiles) {
  for (const char* ext : {"gltf", "glb", "fbx", "dae", "bvh"})
    expectFileError(writeTemp(std::string("empty.") + ext, ""));
}

TEST(ImportErrors, WrongExtension) {
  // A glTF under a name the importer does not know, and a BVH called .gltf.
  const std::string text = loadFileText(kCharacters + "SimpleSkin/SimpleSkin.gltf");
  EXPECT_NE(expectFileError(writeTemp("skin.txt", text)).find("unsupported file type"), std::string::npos);
  expectFileError(
      writeTemp("motion.gltf", loadFileText(std::string(MANNEQUIN_SHARED_DIR) + "/assets/motion/makehuman_walk1.bvh")));
  expectFileError(writeTemp("gltf_as.fbx", text));
}

TEST(ImportErrors, TruncatedFbxAndDae) {
  const std::string fbx = loadFileText(kCharacters + "assimp_fbx_animation_with_skeleton/animation_with_skeleton.fbx");
  expectFileError(writeTemp("cut.fbx", fbx.substr(0, fbx.size() / 3)));
  const std::string dae =
      loadFileText(kCharacters + "assimp_collada_library_animation_clips/library_animation_clips.dae");
  expectFileError(writeTemp("cut.dae", dae.substr(0, dae.size() / 2)));
}

// One line of the Collada test file changed by `edit`.
std::string colladaWith(const std::string& from, const std::string& to) {
  std::string dae = loadFileText(kCharacters + "assimp_collada_library_animation_clips/library_animation_clips.dae");
  const size_t at = dae.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return dae.replace(at, from.size(), to);
}

TEST(ImportErrors, ColladaCountsBeyondTheFileAreRefusedBeforeReading) {
  // Assimp would reserve 720 million weights (14 s of page faults here) first.
  const std::string message = expectFileError(
      writeTemp("counts.dae", colladaWith("<vertex_weights count=\"72\">", "<vertex_weights count=\"720000000\">")));
  EXPECT_NE(message.find("line 170: count=\"720000000\" is more than the file holds"), std::string::npos) << message;
}

TEST(ImportErrors, ColladaThatMakesAssimpAbortIsRefused) {
  // An index past its source's values trips an assertion inside Assimp
  // (Debian builds it with assertions on), which aborts the process.
  const std::string message =
      expectFileError(writeTemp("index.dae", colladaWith("<v> 0 0 0 1", "<v> 0 0 0 1999999999")));
  EXPECT_NE(message.find("the importer (Assimp) crashed"), std::string::npos) << message;
}

TEST(ImportErrors, ColladaNegativeWeightIsIgnored) {
  const std::string path = writeTemp("negative.dae", colladaWith("skin_weights-array\" count=\"112\"> 1.0",
                                                                 "skin_weights-array\" count=\"112\"> -1.0"));
  const Character c = importCharacter(path);
  ASSERT_FALSE(c.meshes.empty());
  for (const Mesh& mesh : c.meshes)
    for (float w : mesh.skin.weights) EXPECT_TRUE(w >= 0.0f && w <= 1.0f) << w;
}

TEST(ImportErrors, BvhThatIsNotUtf8) {
  std::string bvh = loadFileText(std::string(MANNEQUIN_SHARED_DIR) + "/assets/motion/cmu_01_01.bvh");
  bvh.insert(bvh.find("JOINT ") + 6, "\xff\xfe");
  EXPECT_NE(expectFileError(writeTemp("latin.bvh", bvh)).find("not UTF-8 text"), std::string::npos);
}

}  // namespace
}  // namespace mq
