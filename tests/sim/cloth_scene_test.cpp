// The cloth section of scene documents: the benchmark scenes parse and
// round-trip; bad values give errors naming the file and the key.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/util/error.h"
#include "sim/cloth/cloth_scene_io.h"

namespace mq::cloth {
namespace {

using nlohmann::json;

json readJson(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return json::parse(s.str());
}

std::string benchScene(const std::string& name) {
  return std::string(MANNEQUIN_SOURCE_DIR) + "/tests/bench/scenes/" + name + ".json";
}

TEST(ClothScene, BenchmarkScenesParse) {
  for (const char* name : {"drape_64", "drape_128", "pinned_64", "pinned_128"}) {
    const json doc = readJson(benchScene(name));
    EXPECT_TRUE(doc["character"].is_null()) << name;
    const ClothSceneSpec spec = parseClothScene(doc["cloth"], doc["colliders"], name);
    std::vector<uint32_t> pinned;
    const ClothMesh mesh = buildClothMesh(spec, pinned);
    const int n = spec.sheet.columns;
    EXPECT_TRUE(n == 64 || n == 128);
    EXPECT_EQ(mesh.vertexCount(), size_t(n * n));
    EXPECT_FLOAT_EQ(mesh.masses[0], 0.3f);  // Blender's Cotton: 0.3 kg per vertex
    if (std::string(name).rfind("drape", 0) == 0) {
      ASSERT_EQ(spec.colliders.size(), 1u);
      EXPECT_FLOAT_EQ(spec.colliders[0].radius, 0.3f);
      EXPECT_NEAR(mesh.positions[1], 0.8f, 1e-6f);  // 0.5 m above the sphere's top
      EXPECT_TRUE(pinned.empty());
    } else {
      EXPECT_EQ(pinned.size(), size_t(n));
      EXPECT_NEAR(mesh.positions[1], 1.0f, 1e-6f);  // top edge at 1 m
    }
  }
}

TEST(ClothScene, WriteThenParseGivesTheSameSpec) {
  const json doc = readJson(benchScene("pinned_64"));
  ClothSceneSpec a = parseClothScene(doc["cloth"], doc["colliders"], "pinned_64");
  EXPECT_EQ(a.bakeFrames, 120);  // not in the file: the default
  a.bakeFrames = 48;
  json cloth, colliders;
  writeClothScene(a, cloth, colliders);
  const ClothSceneSpec b = parseClothScene(cloth, colliders, "again");
  EXPECT_EQ(b.sheet.columns, a.sheet.columns);
  EXPECT_EQ(b.sheet.vertical, a.sheet.vertical);
  EXPECT_FLOAT_EQ(b.fabric.stretchStiffness, a.fabric.stretchStiffness);
  EXPECT_FLOAT_EQ(b.massPerVertex, a.massPerVertex);
  EXPECT_EQ(b.settings.integrator, a.settings.integrator);
  EXPECT_EQ(b.pinnedRows, a.pinnedRows);
  EXPECT_EQ(b.bakeFrames, 48);
  EXPECT_EQ(b.settings.cgPreconditioner, a.settings.cgPreconditioner);
}

TEST(ClothScene, ThePreconditionerIsReadAndWritten) {
  json doc = readJson(benchScene("pinned_64"));
  ASSERT_FALSE(doc["cloth"].contains("cg_preconditioner"));
  EXPECT_EQ(parseClothScene(doc["cloth"], doc["colliders"], "pinned_64").settings.cgPreconditioner,
            CgPreconditioner::TwoLevel);  // the default
  doc["cloth"]["cg_preconditioner"] = "block_jacobi";
  const ClothSceneSpec a = parseClothScene(doc["cloth"], doc["colliders"], "pinned_64");
  EXPECT_EQ(a.settings.cgPreconditioner, CgPreconditioner::BlockJacobi);
  json cloth, colliders;
  writeClothScene(a, cloth, colliders);
  EXPECT_EQ(cloth["cg_preconditioner"], "block_jacobi");
}

std::string errorFor(const json& cloth, const json& colliders = json()) {
  try {
    parseClothScene(cloth, colliders, "scene.json");
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

TEST(ClothScene, BadValuesNameTheFileAndTheKey) {
  EXPECT_EQ(errorFor({{"integrator", "leapfrog"}}),
            "scene.json: cloth.integrator: unknown integrator 'leapfrog' (known: symplectic_euler, verlet, rk4, "
            "implicit_euler)");
  EXPECT_NE(errorFor({{"air_damping", "nan"}}).find("cloth.air_damping: must be a number"), std::string::npos);
  EXPECT_NE(errorFor({{"gravity", {0, 1}}}).find("cloth.gravity: must be an array of 3 numbers"), std::string::npos);
  EXPECT_NE(errorFor({{"fabric", "velvet"}}).find("unknown fabric preset 'velvet'"), std::string::npos);
  EXPECT_NE(errorFor({{"fabric", {{"stretch", -1}}}}).find("cloth.fabric.stretch: must be positive"),
            std::string::npos);
  EXPECT_NE(errorFor({{"garment", {{"columns", 1}}}}).find("cloth.garment.columns"), std::string::npos);
  EXPECT_NE(errorFor(json::object(), json::array({{{"type", "cone"}}})).find("colliders[0].type: unknown collider"),
            std::string::npos);
  EXPECT_NE(errorFor(json()).find("no cloth section"), std::string::npos);
  EXPECT_NE(errorFor({{"bake_frames", 0}}).find("cloth.bake_frames: must be an integer between 1 and 100000"),
            std::string::npos);
  EXPECT_NE(errorFor({{"cg_preconditioner", "multigrid"}})
                .find("cloth.cg_preconditioner: unknown preconditioner 'multigrid' (known: block_jacobi, two_level)"),
            std::string::npos);
  // Numbers too large for a float are not finite.
  EXPECT_NE(errorFor({{"wind", {0, 1e300, 0}}}).find("cloth.wind"), std::string::npos);
}

}  // namespace
}  // namespace mq::cloth
