// Built-in garments on the default mannequin: placed around the body, clear
// of it, and shaped by their measurements.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/garment/body_capsules.h"
#include "core/garment/body_measurements.h"
#include "core/garment/parametric_garments.h"
#include "core/util/error.h"

namespace mq {
namespace {

const Character& mannequin() {
  static const Character character = makeDefaultMannequin();
  return character;
}

const std::vector<BodyCapsule>& capsules() {
  static const std::vector<BodyCapsule> c = fitBodyCapsules(mannequin());
  return c;
}

TEST(GarmentBody, CapsulesEncloseTheSkin) {
  const Character& body = mannequin();
  ASSERT_GE(capsules().size(), 15u);
  // Every skin vertex lies inside (or on) some capsule.
  PosedCharacter rest;
  rest.evaluate(body, -1, 0.0f, nullptr, nullptr);
  for (const PosedMesh& mesh : rest.meshes())
    for (size_t v = 0; v < mesh.positions.size(); v += 3) {
      glm::vec3 p(mesh.positions[v], mesh.positions[v + 1], mesh.positions[v + 2]);
      ASSERT_LE(distanceToCapsules(capsules(), p), 1e-4f);
    }
}

TEST(GarmentBody, MeasurementsArePlausibleForAnAdult) {
  BodyMeasurements m = measureBody(mannequin());
  EXPECT_GT(m.chestGirth, 0.7f);
  EXPECT_LT(m.chestGirth, 1.3f);
  EXPECT_GT(m.hipGirth, 0.7f);
  EXPECT_LT(m.waistGirth, m.hipGirth);
  EXPECT_GT(m.upperArmGirth, 0.2f);
  EXPECT_LT(m.upperArmGirth, 0.45f);
  EXPECT_GT(m.shoulder[0].x, 0.0f);  // index 0 is the left, +X
  EXPECT_LT(m.shoulder[1].x, 0.0f);
}

// Angular coverage around the torso axis at height y: the largest gap
// between garment vertices near that height, in radians.
float largestAngularGap(const GarmentMesh& mesh, const BodyMeasurements& m, float y) {
  std::vector<float> angles;
  glm::vec3 axis = m.torsoAxisAt(y);
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    glm::vec3 p = mesh.position(v);
    if (std::abs(p.y - y) < 0.03f) angles.push_back(std::atan2(p.x - axis.x, p.z - axis.z));
  }
  if (angles.empty()) return 7.0f;
  std::sort(angles.begin(), angles.end());
  float gap = angles.front() + 2.0f * float(M_PI) - angles.back();
  for (size_t i = 1; i < angles.size(); ++i) gap = std::max(gap, angles[i] - angles[i - 1]);
  return gap;
}

class BuiltInGarment : public ::testing::TestWithParam<std::string> {};

TEST_P(BuiltInGarment, SurroundsTheBodyWithoutTouchingIt) {
  Garment garment = makeParametricGarment(GetParam(), mannequin());
  GarmentMesh mesh = buildGarmentMesh(garment);
  ASSERT_GT(mesh.vertexCount(), 500u);
  ASSERT_FALSE(mesh.seamPairs.empty());
  float nearest = 1e30f;
  for (size_t v = 0; v < mesh.vertexCount(); ++v)
    nearest = std::min(nearest, distanceToCapsules(capsules(), mesh.position(v)));
  EXPECT_GT(nearest, 0.0f) << GetParam() << ": a panel vertex starts inside the body";
  // Around the torso (the chest for the shirt, the hips for the others) the
  // panels leave no gap wider than the side seams still to close.
  BodyMeasurements m = measureBody(mannequin());
  float y = GetParam() == "tshirt" ? m.chest.y : m.hip[0].y - 0.05f;
  EXPECT_LT(largestAngularGap(mesh, m, y), 1.2f) << GetParam();
  // Seam pairs join vertices of the named panels.
  for (auto [a, b] : mesh.seamPairs) {
    ASSERT_LT(a, mesh.vertexCount());
    ASSERT_LT(b, mesh.vertexCount());
  }
}

INSTANTIATE_TEST_SUITE_P(Types, BuiltInGarment, ::testing::Values("tshirt", "skirt", "trousers"));

float edgeLength(const Garment& g, const std::string& panel, const std::string& edge) {
  const Panel& p = g.panels[g.findPanel(panel)];
  return p.edgeLength(p.findEdge(edge));
}

TEST(GarmentParametric, LongerSleevesMakeLongerSleevePanels) {
  Garment shortSleeves = makeParametricGarment("tshirt", mannequin(), {{"sleeveLength", 0.15f}});
  Garment longSleeves = makeParametricGarment("tshirt", mannequin(), {{"sleeveLength", 0.45f}});
  EXPECT_NEAR(edgeLength(longSleeves, "sleeve_l", "under_a") - edgeLength(shortSleeves, "sleeve_l", "under_a"), 0.3f,
              1e-4f);
  GarmentMesh a = buildGarmentMesh(shortSleeves), b = buildGarmentMesh(longSleeves);
  EXPECT_GT(b.vertexCount(), a.vertexCount());
  // The long sleeve reaches further down the arm: its lowest point is lower.
  auto lowestOfPanel = [](const GarmentMesh& mesh, int panel) {
    float lowest = 1e30f;
    for (size_t v = 0; v < mesh.vertexCount(); ++v)
      if (mesh.panelIds[v] == panel) lowest = std::min(lowest, mesh.position(v).y);
    return lowest;
  };
  int sleeve = shortSleeves.findPanel("sleeve_l");
  EXPECT_LT(lowestOfPanel(b, sleeve), lowestOfPanel(a, sleeve) - 0.15f);
}

TEST(GarmentParametric, LengthAndEaseChangeTheBodyPanels) {
  Garment base = makeParametricGarment("tshirt", mannequin());
  Garment longer = makeParametricGarment("tshirt", mannequin(), {{"length", 0.8f}});
  Garment wider = makeParametricGarment("tshirt", mannequin(), {{"ease", 0.3f}});
  EXPECT_NEAR(edgeLength(longer, "front", "side_l") - edgeLength(base, "front", "side_l"), 0.8f - 0.66f, 1e-4f);
  EXPECT_NEAR(edgeLength(wider, "front", "hem") - edgeLength(base, "front", "hem"), 0.5f * (0.3f - 0.2f), 1e-4f);
  Garment skirt = makeParametricGarment("skirt", mannequin(), {{"flare", 0.1f}});
  Garment flared = makeParametricGarment("skirt", mannequin(), {{"flare", 0.6f}});
  EXPECT_NEAR(edgeLength(flared, "front", "hem") - edgeLength(skirt, "front", "hem"), 0.5f, 1e-4f);
  Garment shorts = makeParametricGarment("trousers", mannequin(), {{"length", 0.45f}});
  Garment trousers = makeParametricGarment("trousers", mannequin());
  EXPECT_LT(boundsOf(buildGarmentMesh(trousers).positions).min.y,
            boundsOf(buildGarmentMesh(shorts).positions).min.y - 0.4f);
}

TEST(GarmentParametric, RecipeRebuildsTheSameGarment) {
  Garment g = makeParametricGarment("skirt", mannequin(), {{"length", 0.7f}});
  EXPECT_EQ(g.recipe.type, "skirt");
  EXPECT_FLOAT_EQ(g.recipe.parameters.at("length"), 0.7f);
  g.recipe.parameters["length"] = 0.4f;
  Garment rebuilt = rebuildParametricGarment(g, mannequin());
  auto height = [](const Garment& garment) {
    const Panel& front = garment.panels[garment.findPanel("front")];
    float top = -1e30f, bottom = 1e30f;
    for (glm::vec2 c : front.corners) top = std::max(top, c.y), bottom = std::min(bottom, c.y);
    return top - bottom;
  };
  EXPECT_NEAR(height(rebuilt), height(g) - 0.3f, 1e-5f);
  EXPECT_EQ(rebuilt.name, g.name);
}

TEST(GarmentParametric, BadParametersAreRejected) {
  EXPECT_THROW(makeParametricGarment("poncho", mannequin()), Error);
  EXPECT_THROW(makeParametricGarment("tshirt", mannequin(), {{"sleeves", 0.2f}}), Error);
  EXPECT_THROW(makeParametricGarment("tshirt", mannequin(), {{"length", 5.0f}}), Error);
}

}  // namespace
}  // namespace mq
