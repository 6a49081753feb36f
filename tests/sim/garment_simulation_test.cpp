// GarmentSimulation: results and pins in garment-mesh order across the weld,
// and the scene documents' garments (fabric, pins, solver settings).
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "core/garment/garment_json.h"
#include "core/util/error.h"
#include "garment_test_garments.h"
#include "sim/garment/garment_scene.h"
#include "sim/garment/garment_simulation.h"

namespace mq {
namespace {

using namespace mq::cloth;

GarmentSimulationSettings noGravity() {
  GarmentSimulationSettings s;
  s.fabric = fabricPreset("cotton");
  s.cloth.gravity = glm::vec3(0.0f);
  return s;
}

TEST(GarmentSimulation, SewsWeldsAndKeepsTheGarmentMeshOrderAndPins) {
  const GarmentMesh mesh = buildGarmentMesh(test::twoSewnSquares());
  GarmentSimulation sim(mesh, noGravity(), {}, {});
  ASSERT_GT(mesh.seamPairs.size(), 0u);
  const uint32_t pinned = mesh.panelFirstVertex[0];  // a corner of the left panel, off the seam
  const glm::vec3 where = mesh.position(pinned);
  sim.pin(pinned);
  EXPECT_NEAR(sim.seamGap(), 0.05f, 1e-3f);
  EXPECT_FALSE(sim.welded());
  for (int f = 0; f < 60 && !sim.welded(); ++f) sim.step(1.0f / 30.0f);
  ASSERT_TRUE(sim.welded());
  EXPECT_EQ(sim.seamGap(), 0.0f);
  for (int f = 0; f < 5; ++f) sim.step(1.0f / 30.0f);
  const std::vector<float> x = sim.positions();
  ASSERT_EQ(x.size(), 3 * mesh.vertexCount());
  EXPECT_EQ(sim.vertexCount(), mesh.vertexCount());
  EXPECT_EQ(sim.triangles(), mesh.triangles);
  // Both vertices of every seam pair report the one welded position.
  for (auto [a, b] : mesh.seamPairs) EXPECT_EQ(vec3At(x, a), vec3At(x, b));
  // The pin held through sewing and weld.
  EXPECT_LT(glm::length(vec3At(x, pinned) - where), 1e-5f);
  EXPECT_EQ(sim.pinnedVertices(), std::vector<uint32_t>{pinned});
  const std::vector<float> stretch = sim.vertexStretch();
  ASSERT_EQ(stretch.size(), mesh.vertexCount());
  for (float s : stretch) EXPECT_LE(s, 1.1f + 1e-3f);
}

TEST(GarmentSimulation, GentleSewingClosesAtTheSewingSpeed) {
  GarmentSimulationSettings settings = noGravity();
  settings.sewingSpeed = 0.3f;  // m/s: a 5 cm gap takes about 1/6 s
  GarmentSimulation sim(buildGarmentMesh(test::twoSewnSquares()), settings, {}, {});
  sim.step(1.0f / 30.0f);
  // One frame closes at most 1 cm, not the whole gap as a stiff spring would.
  EXPECT_GT(sim.seamGap(), 0.05f - 0.3f / 30.0f - 1e-3f);
  EXPECT_LT(sim.seamGap(), 0.05f);
}

TEST(GarmentScene, FabricAndPinsOfTheDocumentReachTheSimulation) {
  Garment g = test::twoSewnSquares();
  Fabric silk = fabricPreset("silk");
  silk.damping = 0.01f;
  g.fabric = "silk";
  g.customFabric = silk;
  g.pins.attach = GarmentPins::Attach::Space;
  g.pins.vertices = {0, 1};
  ClothSceneSpec spec = parseClothScene(nlohmann::json::object(), nullptr, "scene.json", true);
  EXPECT_FALSE(spec.hasSheet);
  EXPECT_FLOAT_EQ(garmentSimulationSettings(g, spec).fabric.damping, 0.01f);
  auto sim = makeGarmentSimulation(g, spec, {}, {}, "garments[0]");
  EXPECT_EQ(sim->pinnedVertices(), (std::vector<uint32_t>{0, 1}));
  g.pins.vertices = {100000};
  try {
    makeGarmentSimulation(g, spec, {}, {}, "garments[0]");
    FAIL() << "a pin beyond the mesh was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("garments[0].pins.vertices[0]: vertex 100000 is beyond"), std::string::npos);
  }
  g.pins = {{0}, GarmentPins::Attach::Body};
  EXPECT_THROW(makeGarmentSimulation(g, spec, {}, {}, "garments[0]"), Error);  // no body to pin to
}

nlohmann::json readScene(const std::string& relative) {
  std::ifstream in(std::string(MANNEQUIN_SOURCE_DIR) + "/" + relative);
  return nlohmann::json::parse(in);
}

TEST(GarmentScene, ExampleAndBenchmarkScenesParse) {
  for (const char* path : {"resources/scenes/garment_tshirt_walk.json", "tests/bench/scenes/tshirt_walk_10k.json"}) {
    const nlohmann::json doc = readScene(path);
    const std::vector<Garment> garments = garmentsFromJson(doc["garments"]);
    ASSERT_EQ(garments.size(), 1u) << path;
    EXPECT_EQ(garments[0].fabric, "cotton");
    const ClothSceneSpec spec = parseClothScene(doc.at("cloth"), nullptr, path, true);
    EXPECT_FALSE(spec.hasSheet);
    EXPECT_EQ(doc["animation"]["clip"], "walk");
    EXPECT_EQ(spec.fps, 30.0f);
  }
  const nlohmann::json bench = readScene("tests/bench/scenes/tshirt_walk_10k.json");
  EXPECT_TRUE(parseClothScene(bench["cloth"], nullptr, "bench", true).settings.selfCollisions);
  const size_t vertices = buildGarmentMesh(garmentsFromJson(bench["garments"])[0]).vertexCount();
  EXPECT_GT(vertices, 9500u);
  EXPECT_LT(vertices, 10500u);
}

TEST(GarmentScene, ClothSectionWithoutSheetRoundTrips) {
  ClothSceneSpec spec = parseClothScene({{"self_collisions", true}, {"max_refinement", 2}}, nullptr, "s", true);
  nlohmann::json cloth, colliders;
  writeClothScene(spec, cloth, colliders);
  EXPECT_FALSE(cloth.contains("garment"));
  const ClothSceneSpec back = parseClothScene(cloth, colliders, "s", true);
  EXPECT_FALSE(back.hasSheet);
  EXPECT_TRUE(back.settings.selfCollisions);
  EXPECT_EQ(back.settings.maxRefinement, 2);
  // Sheet pins without a sheet are refused.
  EXPECT_THROW(parseClothScene({{"pins", {{"rows", {0}}}}}, nullptr, "s", true), FileError);
}

}  // namespace
}  // namespace mq
