// Garments in the scene document's "garments" section.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/garment/garment_json.h"
#include "core/util/error.h"

namespace mq {
namespace {

Garment sample() {
  Garment g;
  g.name = "apron";
  g.fabric = "denim";
  g.targetEdgeLength = 0.03f;
  g.recipe = {"custom", {{"width", 0.5f}}};
  Panel front;
  front.name = "front";
  front.addLine("hem", {-0.25f, 0});
  front.addQuadratic("side_l", {0.25f, 0}, {0.3f, 0.3f});
  front.addCubic("top", {0.2f, 0.6f}, {0.1f, 0.5f}, {-0.1f, 0.5f});
  front.addLine("side_r", {-0.2f, 0.6f});
  front.placement.shape = PanelPlacement::Shape::Cylinder;
  front.placement.bone = "spine";
  front.placement.center = {0.0f, 1.1f, 0.01f};
  front.placement.radius = 0.21f;
  front.placement.anchor = {0.0f, 0.6f};
  Panel back = front;
  back.name = "back";
  back.placement.facing = {0, 0, -1};
  g.panels = {front, back};
  g.seams = {{"front", "side_l", "back", "side_r", true}, {"front", "side_r", "back", "side_l", false}};
  return g;
}

TEST(GarmentJson, RoundTripKeepsEverything) {
  Garment g = sample();
  nlohmann::json j = garmentsToJson({g});
  // Through text, as the scene document stores it.
  std::vector<Garment> back = garmentsFromJson(nlohmann::json::parse(j.dump(2)));
  ASSERT_EQ(back.size(), 1u);
  const Garment& r = back[0];
  EXPECT_EQ(r.name, g.name);
  EXPECT_EQ(r.fabric, "denim");
  EXPECT_FLOAT_EQ(r.targetEdgeLength, 0.03f);
  EXPECT_EQ(r.recipe.type, "custom");
  EXPECT_FLOAT_EQ(r.recipe.parameters.at("width"), 0.5f);
  ASSERT_EQ(r.panels.size(), 2u);
  for (size_t p = 0; p < 2; ++p) {
    const Panel &a = g.panels[p], &b = r.panels[p];
    EXPECT_EQ(a.name, b.name);
    ASSERT_EQ(a.corners.size(), b.corners.size());
    for (size_t i = 0; i < a.corners.size(); ++i) {
      EXPECT_EQ(a.corners[i], b.corners[i]);
      EXPECT_EQ(a.edges[i].name, b.edges[i].name);
      EXPECT_EQ(a.edges[i].shape, b.edges[i].shape);
      EXPECT_EQ(a.edges[i].control[0], b.edges[i].control[0]);
      EXPECT_EQ(a.edges[i].control[1], b.edges[i].control[1]);
    }
    EXPECT_EQ(a.placement.shape, b.placement.shape);
    EXPECT_EQ(a.placement.bone, b.placement.bone);
    EXPECT_EQ(a.placement.center, b.placement.center);
    EXPECT_EQ(a.placement.facing, b.placement.facing);
    EXPECT_FLOAT_EQ(a.placement.radius, b.placement.radius);
    EXPECT_EQ(a.placement.anchor, b.placement.anchor);
  }
  ASSERT_EQ(r.seams.size(), 2u);
  EXPECT_EQ(r.seams[1].edgeB, "side_l");
  EXPECT_FALSE(r.seams[1].reversed);
  // Serialising again gives the same JSON.
  EXPECT_EQ(garmentsToJson(back), j);
}

TEST(GarmentJson, MissingSectionIsNoGarments) { EXPECT_TRUE(garmentsFromJson(nlohmann::json()).empty()); }

std::string errorOf(const nlohmann::json& j) {
  try {
    garmentsFromJson(j);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(GarmentJson, MalformedGarmentsGiveErrorsNamingThePlace) {
  nlohmann::json good = garmentsToJson({sample()});
  nlohmann::json j = good;
  j[0]["panels"][1]["corners"][2] = {1.0, "x"};
  EXPECT_EQ(errorOf(j), "garments[0].panels[1].corners[2]: expected [u, v] (two numbers)");
  j = good;
  j[0]["panels"][0]["edges"][1]["shape"] = "spline";
  EXPECT_EQ(errorOf(j), "garments[0].panels[0].edges[1].shape: unknown edge shape 'spline' (line, quadratic or cubic)");
  j = good;
  j[0]["panels"][0]["edges"][2]["controls"].erase(1);
  EXPECT_EQ(errorOf(j), "garments[0].panels[0].edges[2].controls: a cubic edge needs 2 control point(s), got 1");
  j = good;
  j[0].erase("panels");
  EXPECT_EQ(errorOf(j), "garments[0]: missing \"panels\"");
  j = good;
  j[0]["seams"][0]["b"] = {"back", "collar"};
  EXPECT_NE(errorOf(j).find("unknown edge 'collar'"), std::string::npos) << errorOf(j);
  j = good;
  j[0]["panels"][0]["edges"].erase(0);
  EXPECT_EQ(errorOf(j), "garments[0].panels[0].edges: has 3 edges for 4 corners (one edge leaves each corner)");
  j = good;
  j[0]["panels"][0]["placement"]["radius"] = -1;
  EXPECT_EQ(errorOf(j), "garments[0].panels[0].placement.radius: must be between 0 and 100 (metres)");
  // A placement two million kilometres away collapsed the mesh's edges to zero length.
  j = good;
  j[0]["panels"][0]["placement"]["anchor"] = {2147483648.0, 0.0};
  EXPECT_EQ(errorOf(j), "garments[0].panels[0].placement.anchor: must hold numbers between -100 and 100 (metres)");
  EXPECT_EQ(errorOf(nlohmann::json::object()), "garments: expected an array");
}

}  // namespace
}  // namespace mq

namespace mq {
namespace {

// Round trip through text, as the scene document stores it.
Garment throughText(const Garment& g) {
  const std::string text = garmentsToJson({g}).dump();
  return garmentsFromJson(nlohmann::json::parse(text)).at(0);
}

TEST(GarmentJson, PresetFabricStaysAName) {
  Garment g = sample();
  EXPECT_TRUE(garmentToJson(g)["fabric"].is_string());
  const Garment back = throughText(g);
  EXPECT_EQ(back.fabric, "denim");
  EXPECT_FALSE(back.customFabric.has_value());
  EXPECT_FLOAT_EQ(back.solverFabric().stretchStiffness, fabricPreset("denim").stretchStiffness);
}

TEST(GarmentJson, CustomFabricAndPinsRoundTrip) {
  Garment g = sample();
  Fabric f = fabricPreset("silk");
  f.stretchStiffness = 1234.5f;
  f.damping = 0.02f;
  g.fabric = "silk";
  g.customFabric = f;
  g.pins.vertices = {3, 7, 11};
  g.pins.attach = GarmentPins::Attach::Space;
  const nlohmann::json j = garmentToJson(g);
  EXPECT_EQ(j["fabric"]["preset"], "silk");
  EXPECT_EQ(j["pins"]["attach"], "space");
  const Garment back = throughText(g);
  EXPECT_EQ(back.fabric, "silk");
  ASSERT_TRUE(back.customFabric.has_value());
  EXPECT_FLOAT_EQ(back.solverFabric().stretchStiffness, 1234.5f);
  EXPECT_FLOAT_EQ(back.solverFabric().damping, 0.02f);
  EXPECT_FLOAT_EQ(back.solverFabric().massPerArea, fabricPreset("silk").massPerArea);
  EXPECT_EQ(back.pins.vertices, (std::vector<uint32_t>{3, 7, 11}));
  EXPECT_EQ(back.pins.attach, GarmentPins::Attach::Space);
  // Written again, the same JSON.
  EXPECT_EQ(garmentToJson(back).dump(), j.dump());
}

TEST(GarmentJson, FabricObjectOverridesOnlyTheKeysGiven) {
  nlohmann::json j = garmentToJson(sample());
  j["fabric"] = {{"preset", "wool"}, {"bend", 2e-5}};
  j["pins"] = {{"vertices", {0, 1}}};
  const Garment g = garmentFromJson(j);
  EXPECT_EQ(g.fabric, "wool");
  EXPECT_FLOAT_EQ(g.solverFabric().bendStiffness, 2e-5f);
  EXPECT_FLOAT_EQ(g.solverFabric().stretchStiffness, fabricPreset("wool").stretchStiffness);
  EXPECT_EQ(g.pins.attach, GarmentPins::Attach::Body);  // the default
}

TEST(GarmentJson, BadFabricAndPinsNameTheJsonPath) {
  auto errorFor = [](const char* key, const nlohmann::json& value) {
    nlohmann::json section = garmentsToJson({sample()});
    section[0][key] = value;
    try {
      garmentsFromJson(section);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(errorFor("fabric", "velvet").find("garments[0].fabric: unknown fabric preset 'velvet'"), std::string::npos);
  EXPECT_NE(errorFor("fabric", {{"preset", "velvet"}}).find("garments[0].fabric.preset: unknown fabric preset"),
            std::string::npos);
  // JSON text has no NaN; an editor's in-memory document can.
  EXPECT_NE(errorFor("fabric", {{"stretch", std::nan("")}}).find("garments[0].fabric.stretch: must be a finite number"),
            std::string::npos);
  EXPECT_NE(errorFor("fabric", {{"stretch", "stiff"}}).find("garments[0].fabric.stretch: must be a number"),
            std::string::npos);
  EXPECT_NE(errorFor("fabric", {{"stretch", -3}}).find("garments[0].fabric.stretch: must be positive"),
            std::string::npos);
  EXPECT_NE(errorFor("fabric", {{"strech", 3}}).find("garments[0].fabric.strech: unknown fabric key"),
            std::string::npos);
  EXPECT_NE(errorFor("pins", {{"vertices", {1, -2}}}).find("garments[0].pins.vertices[1]"), std::string::npos);
  EXPECT_NE(errorFor("pins", {{"attach", "glue"}}).find("garments[0].pins.attach: unknown attach 'glue'"),
            std::string::npos);
}

}  // namespace
}  // namespace mq

namespace mq {
namespace {

TEST(GarmentJson, LayerRoundTripsAndBadLayersNameTheJsonPath) {
  Garment g = sample();
  EXPECT_FALSE(garmentToJson(g).contains("layer"));  // layer 0 is not written
  EXPECT_EQ(garmentsFromJson(garmentsToJson({g})).at(0).layer, 0);
  g.layer = 3;
  EXPECT_EQ(garmentToJson(g)["layer"], 3);
  EXPECT_EQ(garmentsFromJson(nlohmann::json::parse(garmentsToJson({g}).dump())).at(0).layer, 3);
  const std::string expected = "garments[0].layer: expected a layer number, an integer from 0 to 99";
  for (const nlohmann::json& bad :
       {nlohmann::json(-1), nlohmann::json(100), nlohmann::json(1.5), nlohmann::json("top")}) {
    nlohmann::json j = garmentsToJson({g});
    j[0]["layer"] = bad;
    EXPECT_EQ(errorOf(j), expected) << bad.dump();
  }
}

}  // namespace
}  // namespace mq
