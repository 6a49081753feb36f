// Mutated files (seeded random byte changes) must import or throw FileError:
// never crash, hang or throw anything else.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include <unistd.h>
#include <nlohmann/json.hpp>

#include "core/io/character_import.h"
#include "core/io/file_bytes.h"
#include "core/scene/scene_document.h"
#include "core/util/error.h"
#include "import_test_util.h"

namespace mq {
namespace {

const std::string kAssets = std::string(MANNEQUIN_SHARED_DIR) + "/assets/";

void fuzz(const std::string& source, const std::string& extension, int rounds, int flipsPerRound,
          const std::string& alphabet = "") {
  const std::string original = loadFileText(kAssets + source);
  const auto dir = test::scratchDir("mq_fuzz");
  // Companion files (external buffers) beside the mutant.
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(kAssets + source).parent_path()))
    if (entry.path().extension() == ".bin")
      std::filesystem::copy_file(entry.path(), dir / entry.path().filename(),
                                 std::filesystem::copy_options::overwrite_existing);
  const std::string path = (dir / ("mutant." + extension)).string();
  std::mt19937 rng(12111);
  int imported = 0, refused = 0;
  for (int round = 0; round < rounds; ++round) {
    std::string bytes = original;
    for (int f = 0; f < flipsPerRound; ++f) {
      const size_t at = std::uniform_int_distribution<size_t>(0, bytes.size() - 1)(rng);
      bytes[at] = alphabet.empty() ? static_cast<char>(rng() & 0xFF) : alphabet[rng() % alphabet.size()];
    }
    std::ofstream(path, std::ios::binary) << bytes;
    try {
      const Character c = importCharacter(path);
      c.validate();
      ++imported;
    } catch (const FileError& e) {
      EXPECT_EQ(e.path(), path);
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << source << " round " << round << ": " << e.what();
    }
  }
  EXPECT_EQ(imported + refused, rounds);
  std::cout << "[ fuzz ] " << source << ": " << imported << " imported, " << refused << " refused\n";
}

TEST(ImportFuzz, GltfJsonDigitsAndPunctuation) {
  // Digits and JSON punctuation keep the file parseable often, so the
  // reader's own checks (indices, counts, offsets) get exercised.
  fuzz("characters/RiggedSimple/RiggedSimple.gltf", "gltf", 300, 2, "0123456789");
  fuzz("characters/CesiumMan/glTF/CesiumMan.gltf", "gltf", 100, 3, "0123456789-.,:[]{}\"e");
}

void collectIntegers(nlohmann::json& j, std::vector<nlohmann::json*>& out) {
  if (j.is_number_integer()) out.push_back(&j);
  if (j.is_structured())
    for (auto& child : j) collectIntegers(child, out);
}

// Integer fields (indices, counts, offsets, strides, component types) set to
// hostile values: the bounds checks must catch every one.
TEST(ImportFuzz, GltfIntegerFields) {
  const nlohmann::json original =
      nlohmann::json::parse(loadFileText(kAssets + "characters/SimpleSkin/SimpleSkin.gltf"));
  const auto dir = test::scratchDir("mq_fuzz");
  const std::string path = (dir / "integers.gltf").string();
  const std::vector<int64_t> hostile = {
      0, 1, -1, 2, 3, 7, 255, 5126, 65535, 2147483647LL, 4294967295LL, 1000000000000LL};
  std::mt19937 rng(12111);
  int refused = 0;
  for (int round = 0; round < 400; ++round) {
    nlohmann::json j = original;
    std::vector<nlohmann::json*> integers;
    collectIntegers(j, integers);
    for (int k = 0; k < 2; ++k) *integers[rng() % integers.size()] = hostile[rng() % hostile.size()];
    std::ofstream(path) << j.dump();
    try {
      importCharacter(path).validate();
    } catch (const FileError&) {
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "round " << round << ": " << e.what();
    }
  }
  EXPECT_GT(refused, 100);
}

TEST(ImportFuzz, GlbBytes) { fuzz("characters/CesiumMan/glTF-Binary/CesiumMan.glb", "glb", 120, 8); }

TEST(ImportFuzz, SimpleSkinEmbedded) {
  fuzz("characters/SimpleSkin/SimpleSkin.gltf", "gltf", 300, 2, "0123456789AZaz+/=-,:");
}

TEST(ImportFuzz, BvhDigits) { fuzz("motion/makehuman_walk1.bvh", "bvh", 100, 4, "0123456789-. \nxyz{}"); }

TEST(ImportFuzz, ColladaText) {
  fuzz("characters/assimp_collada_library_animation_clips/library_animation_clips.dae", "dae", 60, 4,
       "0123456789 <>/\"#");
}

}  // namespace
}  // namespace mq

namespace mq {
namespace {

// A scene document's material changes, mutated: parsed, or refused with a
// FileError naming the document.
TEST(ImportFuzz, SceneDocumentMaterialChanges) {
  const std::string original = R"({"format": "mannequin-scene", "version": 1, "character": "default",
    "view": {"skeleton": false, "look": "auto"},
    "materials": {"coat": {"base_color": [0.5, 0.25, 0.125, 1.0], "roughness": 0.35, "metallic": 0.0,
      "alpha_mode": "MASK", "alpha_cutoff": 0.5, "emissive": [0, 0, 0], "double_sided": true, "skin": false}}})";
  std::mt19937 rng(4242);
  const std::string alphabet = "0123456789-.,:[]{}\"eE";
  int parsed = 0, refused = 0;
  for (int round = 0; round < 2000; ++round) {
    std::string text = original;
    for (int f = 0; f < 2; ++f)
      text[std::uniform_int_distribution<size_t>(0, text.size() - 1)(rng)] = alphabet[rng() % alphabet.size()];
    try {
      const SceneDocument doc = parseSceneDocument(text, "mutant.mqscene");
      for (const auto& [name, changes] : doc.materials) {
        Material m;
        changes.applyTo(m);
        EXPECT_TRUE(m.roughnessFactor >= 0.0f && m.roughnessFactor <= 1.0f);
        EXPECT_TRUE(m.alphaCutoff >= 0.0f && m.alphaCutoff <= 1.0f);
      }
      ++parsed;
    } catch (const FileError& e) {
      EXPECT_EQ(e.path(), "mutant.mqscene");
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "round " << round << ": " << e.what();
    }
  }
  EXPECT_GT(parsed, 0);
  EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace mq
