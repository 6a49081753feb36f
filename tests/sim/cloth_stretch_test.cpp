// Provot's elongation limit on a heavy hanging sheet, and a hanging strip
// that settles into a catenary.
#include <gtest/gtest.h>

#include <cmath>

#include "cloth_test_scenes.h"
#include "sim/cloth/constraints/stretch_limit.h"

namespace mq::cloth {
namespace {

// Heavy and soft: under its own weight the top of a 1 m sheet would stretch ~25 %.
Fabric heavyFabric() {
  Fabric f = fabricPreset("leather");
  f.name = "heavy";
  f.massPerArea = 5.0f;
  f.stretchStiffness = 200.0f;
  f.shearStiffness = 20.0f;
  f.damping = 0.05f;
  return f;
}

float hangAndMeasure(StretchLimitMode mode) {
  ClothSettings settings;
  settings.stretchLimit = mode;
  settings.maxRefinement = 1;
  settings.stretchIterations = 1000;
  ClothSimulator sim(test::hangingSheetMesh(12, 12, 1.0f, 1.0f, 1.0f), heavyFabric(), settings);
  test::pinTopRow(sim, 12);
  float worst = 1.0f;
  for (int frame = 0; frame < 72; ++frame) {
    sim.step(1.0f / 24.0f);
    worst = std::max(worst, sim.stats().maxStretch);
  }
  EXPECT_TRUE(test::allFinite(sim));
  return worst;
}

TEST(ClothStretchLimit, HeavySheetExceedsTenPercentWithoutTheLimit) {
  EXPECT_GT(hangAndMeasure(StretchLimitMode::Off), 1.10f);
}

TEST(ClothStretchLimit, PositionCorrectionKeepsEverySpringWithinTenPercent) {
  EXPECT_LE(hangAndMeasure(StretchLimitMode::PositionCorrection), 1.10f);
}

TEST(ClothStretchLimit, VelocityCorrectionReducesTheStretch) {
  const float off = hangAndMeasure(StretchLimitMode::Off);
  const float velocity = hangAndMeasure(StretchLimitMode::VelocityCorrection);
  EXPECT_LT(velocity, off);
  EXPECT_LE(velocity, 1.15f);
}

// Solves 2 a sinh(D / (2 a)) = L for the catenary parameter a (L > D).
double catenaryParameter(double span, double length) {
  double lo = 1e-4, hi = 1e4;
  for (int k = 0; k < 200; ++k) {
    const double a = std::sqrt(lo * hi);
    (2.0 * a * std::sinh(span / (2.0 * a)) > length ? lo : hi) = a;
  }
  return std::sqrt(lo * hi);
}

TEST(ClothCatenary, HangingStripPinnedAtBothEndsIsACatenary) {
  // A 1 m strip, 2 vertices wide, ends pinned 0.8 m apart at y = 1.
  const int columns = 41;
  SheetSpec spec;
  spec.columns = columns;
  spec.rows = 2;
  spec.width = 1.0f;
  spec.height = 0.02f;
  spec.origin = {-0.5f, 1.0f, -0.01f};
  const Sheet strip = makeSheet(spec);
  ClothMesh mesh;
  mesh.positions = strip.positions;
  mesh.triangles = strip.triangles;
  Fabric fabric = fabricPreset("cotton");
  fabric.bendStiffness = 0.0f;  // a chain: no bending stiffness
  fabric.damping = 0.05f;
  ClothSettings settings;
  settings.substeps = 4;
  settings.airDamping = 20.0f;  // settle quickly
  ClothSimulator sim(mesh, fabric, settings);
  const float halfSpan = 0.4f;
  for (int row = 0; row < 2; ++row) {
    const glm::vec3 left = glm::vec3(-halfSpan, 1.0f, 0.0f) + glm::vec3(0, 0, row == 0 ? -0.01f : 0.01f);
    sim.pinVertex(strip.index(row, 0), left);
    sim.pinVertex(strip.index(row, columns - 1), left + glm::vec3(2.0f * halfSpan, 0, 0));
  }
  for (int frame = 0; frame < 24 * 8; ++frame) sim.step(1.0f / 24.0f);
  ASSERT_TRUE(test::allFinite(sim));
  EXPECT_LT(sim.kineticEnergy(), 1e-6);  // settled

  // Centre line of the strip and its length.
  std::vector<glm::vec3> centre(columns);
  for (int c = 0; c < columns; ++c)
    centre[c] = 0.5f * (sim.positions()[strip.index(0, c)] + sim.positions()[strip.index(1, c)]);
  double length = 0.0;
  for (int c = 1; c < columns; ++c) length += glm::length(centre[c] - centre[c - 1]);
  const double a = catenaryParameter(2.0 * halfSpan, length);
  const double sag = 1.0 - centre[columns / 2].y;
  EXPECT_GT(sag, 0.2);
  double worst = 0.0;
  for (int c = 0; c < columns; ++c) {
    const double x = centre[c].x;
    const double expected = 1.0 + a * (std::cosh(x / a) - std::cosh(halfSpan / a));
    worst = std::max(worst, std::abs(centre[c].y - expected));
  }
  EXPECT_LT(worst, 0.03 * sag) << "sag " << sag << " catenary a " << a;
}

}  // namespace
}  // namespace mq::cloth
