// Pins carried across a rebuild of the garment's mesh (core/garment/pin_remap.h).
#include <gtest/gtest.h>

#include <algorithm>

#include "core/character/default_mannequin.h"
#include "core/garment/parametric_garments.h"
#include "core/garment/pin_remap.h"

namespace mq {
namespace {

const Character& mannequin() {
  static const Character character = makeDefaultMannequin();
  return character;
}

// The vertices of `panel` in the top `fraction` of its pattern (largest v).
std::vector<uint32_t> topOfPanel(const GarmentMesh& mesh, uint16_t panel, float fraction) {
  float top = -1e9f, bottom = 1e9f;
  for (size_t v = 0; v < mesh.vertexCount(); ++v)
    if (mesh.panelIds[v] == panel)
      top = std::max(top, mesh.restUvs[2 * v + 1]), bottom = std::min(bottom, mesh.restUvs[2 * v + 1]);
  std::vector<uint32_t> out;
  for (size_t v = 0; v < mesh.vertexCount(); ++v)
    if (mesh.panelIds[v] == panel && mesh.restUvs[2 * v + 1] >= top - fraction * (top - bottom))
      out.push_back(uint32_t(v));
  return out;
}

TEST(GarmentPinRemap, SameMeshKeepsThePins) {
  const GarmentMesh mesh = buildGarmentMesh(makeParametricGarment("tshirt", mannequin()));
  const std::vector<uint32_t> pins = {0, 7, 100, uint32_t(mesh.vertexCount() - 1)};
  EXPECT_EQ(remapPins(mesh, pins, mesh), pins);
}

TEST(GarmentPinRemap, CoarserMeshKeepsPanelAndPlace) {
  Garment fine = makeParametricGarment("tshirt", mannequin());
  fine.targetEdgeLength = 0.02f;
  Garment coarse = fine;
  coarse.targetEdgeLength = 0.04f;
  const GarmentMesh before = buildGarmentMesh(fine), after = buildGarmentMesh(coarse);
  ASSERT_LT(after.vertexCount() * 2, before.vertexCount());
  const std::vector<uint32_t> pins = topOfPanel(before, 0, 0.08f);
  ASSERT_GT(pins.size(), 5u);
  const std::vector<uint32_t> remapped = remapPins(before, pins, after);
  ASSERT_FALSE(remapped.empty());
  EXPECT_LE(remapped.size(), pins.size());
  EXPECT_TRUE(std::is_sorted(remapped.begin(), remapped.end()));
  const std::vector<uint32_t> top = topOfPanel(after, 0, 0.2f);
  for (uint32_t v : remapped) {
    EXPECT_EQ(after.panelIds[v], 0);
    // Still at the top of the front panel, a coarse edge from a pinned vertex in the rest pose.
    EXPECT_TRUE(std::count(top.begin(), top.end(), v)) << "vertex " << v << " left the top of the panel";
    float nearest = 1e9f;
    for (uint32_t p : pins) nearest = std::min(nearest, glm::length(after.position(v) - before.position(p)));
    EXPECT_LT(nearest, 0.05f);
  }
}

TEST(GarmentPinRemap, LongerShirtKeepsShoulderPinsAtTheShoulders) {
  const Garment shirt = makeParametricGarment("tshirt", mannequin());
  const float length = shirt.recipe.parameters.count("length") ? shirt.recipe.parameters.at("length") : 0.66f;
  Garment longer = shirt;
  longer.recipe.parameters["length"] = length + 0.1f;
  longer = rebuildParametricGarment(longer, mannequin());
  const GarmentMesh before = buildGarmentMesh(shirt), after = buildGarmentMesh(longer);
  const std::vector<uint32_t> pins = topOfPanel(before, 1, 0.05f);  // the back's shoulders and neck
  const std::vector<uint32_t> remapped = remapPins(before, pins, after);
  ASSERT_FALSE(remapped.empty());
  const std::vector<uint32_t> top = topOfPanel(after, 1, 0.1f);
  for (uint32_t v : remapped) {
    EXPECT_EQ(after.panelIds[v], 1);
    EXPECT_TRUE(std::count(top.begin(), top.end(), v)) << "vertex " << v << " slid down the longer panel";
  }
}

TEST(GarmentPinRemap, OutOfRangePinsAreDropped) {
  const GarmentMesh mesh = buildGarmentMesh(makeParametricGarment("skirt", mannequin()));
  EXPECT_EQ(remapPins(mesh, {uint32_t(mesh.vertexCount() + 5)}, mesh), std::vector<uint32_t>{});
  EXPECT_EQ(remapPins(mesh, {3, 3}, mesh), std::vector<uint32_t>{3});
}

}  // namespace
}  // namespace mq
