// Bending models on a clamped strip (a cantilever), and wind.
#include <gtest/gtest.h>

#include "cloth_test_scenes.h"

namespace mq::cloth {
namespace {

// A strip 2 vertices wide along +X, clamped at x = 0 by its first two columns.
float tipDroop(BendingModel model, float bendStiffness, float length) {
  const int columns = 21;
  SheetSpec spec;
  spec.columns = columns;
  spec.rows = 2;
  spec.width = length;
  spec.height = 0.01f;
  spec.origin = {0.0f, 1.0f, -0.005f};
  const Sheet strip = makeSheet(spec);
  ClothMesh mesh;
  mesh.positions = strip.positions;
  mesh.triangles = strip.triangles;
  Fabric fabric = fabricPreset("leather");
  fabric.bendStiffness = bendStiffness;
  ClothSettings settings;
  settings.bending = model;
  settings.airDamping = 20.0f;
  settings.substeps = 4;
  ClothSimulator sim(mesh, fabric, settings);
  for (int row = 0; row < 2; ++row)
    for (int c = 0; c < 2; ++c) sim.pinVertex(strip.index(row, c));
  for (int frame = 0; frame < 96; ++frame) sim.step(1.0f / 24.0f);
  EXPECT_TRUE(test::allFinite(sim));
  const glm::vec3 tip =
      0.5f * (sim.positions()[strip.index(0, columns - 1)] + sim.positions()[strip.index(1, columns - 1)]);
  return 1.0f - tip.y;
}

TEST(ClothBending, BothModelsMakeAStripStifferThanNoBending) {
  const float B = fabricPreset("leather").bendStiffness;
  const float none = tipDroop(BendingModel::Cantilever, 0.0f, 0.03f);
  EXPECT_LT(tipDroop(BendingModel::Cantilever, B, 0.03f), 0.8f * none);
  // Provot's bend springs act only through their compression (second order
  // in the angle): stiffer than nothing, but weakly.
  EXPECT_LT(tipDroop(BendingModel::Springs, B, 0.03f), 0.98f * none);
}

TEST(ClothBending, CantileverStripDroopsLikeAnElasticBeam) {
  // Small deflection of a beam under its own weight: tip = q L^4 / (8 EI)
  // with q / (EI) = rho g / B per unit width.
  const Fabric leather = fabricPreset("leather");
  const float L = 0.03f, clamped = L / 20.0f;  // the strip is clamped over its first segment
  const float span = L - clamped;
  const float expected = leather.massPerArea * 9.81f * span * span * span * span / (8.0f * leather.bendStiffness);
  const float droop = tipDroop(BendingModel::Cantilever, leather.bendStiffness, L);
  EXPECT_LT(expected, 0.15f * span);  // the linear theory applies
  EXPECT_NEAR(droop, expected, 0.35f * expected);
}

TEST(ClothForcesInScene, WindPushesAHangingSheetDownwind) {
  ClothSettings settings;
  settings.wind = {0.0f, 0.0f, 3.0f};
  settings.airDamping = 2.0f;
  ClothSimulator sim(test::hangingSheetMesh(10, 10, 0.4f, 0.4f, 1.0f), fabricPreset("silk"), settings);
  test::pinTopRow(sim, 10);
  for (int frame = 0; frame < 48; ++frame) sim.step(1.0f / 24.0f);
  EXPECT_GT(sim.stats().boundsMax.z, 0.1f);  // blown toward +Z (it started tilted toward -Z)
}

}  // namespace
}  // namespace mq::cloth
