// GarmentSimulation::snapshot / restore (a sewn garment reused without
// sewing again) and DrapeSchedule::skipSewing, and the sheet of a cloth
// section run as a GarmentSimulation (sim/garment/garment_scene.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/garment/garment.h"
#include "core/scene/scene_document.h"
#include "core/util/error.h"
#include "garment_test_garments.h"
#include "sim/garment/drape_schedule.h"
#include "sim/garment/garment_scene.h"
#include "sim/garment/garment_simulation.h"

namespace mq {
namespace {

using namespace mq::cloth;

GarmentSimulationSettings cotton() {
  GarmentSimulationSettings s;
  s.fabric = fabricPreset("cotton");
  return s;
}

float maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return INFINITY;
  float d = 0.0f;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

TEST(GarmentSnapshot, RestoredSimulationContinuesLikeTheOriginal) {
  const GarmentMesh mesh = buildGarmentMesh(test::twoSewnSquares());
  const uint32_t pinned = mesh.panelFirstVertex[0];
  GarmentSimulation original(mesh, cotton(), {}, {});
  original.pin(pinned);
  EXPECT_THROW(original.snapshot(), Error);  // not sewn yet
  for (int f = 0; f < 90 && !original.welded(); ++f) original.step(1.0f / 30.0f);
  ASSERT_TRUE(original.welded());
  for (int f = 0; f < 3; ++f) original.step(1.0f / 30.0f);
  const GarmentSimulation::Snapshot saved = original.snapshot();

  GarmentSimulation restored(mesh, cotton(), {}, {});
  restored.pin(pinned);
  restored.restore(saved);
  EXPECT_TRUE(restored.welded());
  EXPECT_EQ(restored.positions(), original.positions());  // the state, exactly
  EXPECT_EQ(restored.seamGap(), 0.0f);
  // Both hang from the pin and swing on the same way.
  for (int f = 0; f < 10; ++f) {
    original.step(1.0f / 30.0f);
    restored.step(1.0f / 30.0f);
  }
  EXPECT_LT(maxDifference(restored.positions(), original.positions()), 1e-3f);
  const std::vector<float> x = restored.positions();
  EXPECT_NEAR(x[3 * pinned + 1], mesh.position(pinned).y, 1e-4f);  // the pin held through the restore
  EXPECT_LT(*std::min_element(x.begin() + 1, x.end()), 1.0f);      // and the rest fell
}

TEST(GarmentSnapshot, SnapshotOfAnotherGarmentIsRefused) {
  const GarmentMesh mesh = buildGarmentMesh(test::twoSewnSquares());
  GarmentSimulation sim(mesh, cotton(), {}, {});
  for (int f = 0; f < 90 && !sim.welded(); ++f) sim.step(1.0f / 30.0f);
  ASSERT_TRUE(sim.welded());
  Garment finer = test::twoSewnSquares();
  finer.targetEdgeLength = 0.03f;
  GarmentSimulation other(buildGarmentMesh(finer), cotton(), {}, {});
  EXPECT_THROW(other.restore(sim.snapshot()), Error);
}

TEST(GarmentSnapshot, DrapeScheduleSkipsSewingForARestoredGarment) {
  const GarmentMesh mesh = buildGarmentMesh(test::twoSewnSquares());
  GarmentSimulation sim(mesh, cotton(), {}, {});
  DrapeSchedule fresh;
  EXPECT_FALSE(fresh.sewingDone(sim));
  EXPECT_EQ(fresh.advance(sim, 0.1f), 0.0f);  // holds the body at rest while sewing
  for (int f = 0; f < 90 && !sim.welded(); ++f) sim.step(1.0f / 30.0f);
  ASSERT_TRUE(sim.welded());
  DrapeSchedule skipped;
  skipped.skipSewing();
  EXPECT_TRUE(skipped.sewingDone(sim));
  EXPECT_GT(skipped.advance(sim, 0.1f), 0.0f);  // moves the body at once
}

// The editor's warm start after an edit: the same garment with another
// fabric and a pin chosen on the drape starts where the drape was, sewn, and
// the pin holds the cloth where it hangs instead of pulling it back to where
// the flat panels were placed.
TEST(GarmentSnapshot, StartFromDrapeKeepsTheDrapeAndPinsItWhereItIs) {
  const GarmentMesh mesh = buildGarmentMesh(test::twoSewnSquares());
  const uint32_t corner = mesh.panelFirstVertex[0];
  GarmentSimulation first(mesh, cotton(), {}, {});
  first.pin(corner);
  for (int f = 0; f < 90 && !first.welded(); ++f) first.step(1.0f / 30.0f);
  ASSERT_TRUE(first.welded());
  for (int f = 0; f < 30; ++f) first.step(1.0f / 30.0f);
  const std::vector<float> drape = first.positions();
  // A vertex that fell well away from where the panels were placed.
  uint32_t fallen = 0;
  for (uint32_t v = 0; v < mesh.vertexCount(); ++v)
    if (glm::length(vec3At(drape, v) - mesh.position(v)) > glm::length(vec3At(drape, fallen) - mesh.position(fallen)))
      fallen = v;
  ASSERT_GT(glm::length(vec3At(drape, fallen) - mesh.position(fallen)), 0.1f);

  GarmentSimulationSettings silk = cotton();
  silk.fabric = fabricPreset("silk");
  GarmentSimulation warm(mesh, silk, {}, {});
  warm.pin(corner);
  warm.pin(fallen);
  warm.startFromDrape(drape, {});
  EXPECT_TRUE(warm.welded());
  EXPECT_EQ(warm.seamGap(), 0.0f);
  EXPECT_LT(maxDifference(warm.positions(), drape), 1e-6f);
  for (int f = 0; f < 15; ++f) warm.step(1.0f / 30.0f);
  const std::vector<float> x = warm.positions();
  EXPECT_LT(glm::length(vec3At(x, fallen) - vec3At(drape, fallen)), 1e-4f);  // held where it hung
  EXPECT_LT(glm::length(vec3At(x, corner) - vec3At(drape, corner)), 1e-4f);
  const std::vector<float> stretch = warm.vertexStretch();
  EXPECT_LT(*std::max_element(stretch.begin(), stretch.end()), 1.1f);  // the pins do not pull it apart

  // Started from the flat panels instead, the same pin holds the placed position.
  GarmentSimulation cold(mesh, silk, {}, {});
  cold.pin(fallen);
  cold.step(1.0f / 30.0f);
  EXPECT_GT(glm::length(vec3At(cold.positions(), fallen) - vec3At(drape, fallen)), 0.1f);
}

TEST(GarmentSnapshot, StartFromDrapeRefusesAnotherMeshOrNonFinitePositions) {
  const GarmentMesh mesh = buildGarmentMesh(test::twoSewnSquares());
  GarmentSimulation sim(mesh, cotton(), {}, {});
  EXPECT_THROW(sim.startFromDrape(std::vector<float>(3 * mesh.vertexCount() - 3, 0.0f), {}), Error);
  std::vector<float> drape = mesh.positions;
  drape[4] = NAN;
  EXPECT_THROW(sim.startFromDrape(drape, {}), Error);
  EXPECT_THROW(sim.startFromDrape(mesh.positions, std::vector<float>(9, 0.0f)), Error);  // a body it was not built with
  EXPECT_FALSE(sim.welded());                                                            // refused: nothing changed
}

TEST(GarmentSheet, SheetFallsOnItsColliderAndKeepsItsPins) {
  ClothSceneSpec spec;
  spec.sheet.columns = spec.sheet.rows = 12;
  spec.sheet.width = spec.sheet.height = 0.6f;
  spec.sheet.center = {0.0f, 0.5f, 0.0f};
  spec.fabric = fabricPreset("cotton");
  spec.pinnedVertices = {0};
  spec.colliders.push_back(PrimitiveCollider::sphere({0.0f, 0.25f, 0.0f}, 0.15f));
  const GarmentMesh mesh = sheetGarmentMesh(spec);
  EXPECT_EQ(mesh.vertexCount(), 144u);
  auto sim = makeSheetSimulation(spec, {}, {});
  EXPECT_TRUE(sim->welded());  // nothing to sew
  for (int f = 0; f < 24; ++f) sim->step(1.0f / 24.0f);
  const std::vector<float> x = sim->positions();
  EXPECT_NEAR(x[1], 0.5f, 1e-4f);  // pinned corner
  float lowest = INFINITY, inside = 0.0f;
  for (size_t v = 0; v < x.size() / 3; ++v) {
    const glm::vec3 p(x[3 * v], x[3 * v + 1], x[3 * v + 2]);
    lowest = std::min(lowest, p.y);
    inside = std::max(inside, 0.15f - glm::length(p - glm::vec3(0.0f, 0.25f, 0.0f)));
  }
  EXPECT_LT(lowest, 0.4f);    // it fell
  EXPECT_LT(inside, 0.005f);  // around the sphere, not through it
}

// A collider moved while the cloth runs (the editor's drag): the running
// simulation collides with it where it is now.
TEST(GarmentSheet, SetCollidersMovesTheColliderOfARunningSimulation) {
  ClothSceneSpec spec;
  spec.sheet.columns = spec.sheet.rows = 12;
  spec.sheet.width = spec.sheet.height = 0.6f;
  spec.sheet.center = {0.0f, 0.5f, 0.0f};
  spec.fabric = fabricPreset("cotton");
  spec.colliders.push_back(PrimitiveCollider::sphere({0.0f, -1.0f, 0.0f}, 0.15f));  // far below: nothing to hit
  auto sim = makeSheetSimulation(spec, {}, {});
  for (int f = 0; f < 4; ++f) sim->step(1.0f / 24.0f);
  const glm::vec3 centre(0.0f, 0.2f, 0.0f);  // moved under the falling sheet
  sim->setColliders({PrimitiveCollider::sphere(centre, 0.15f)});
  EXPECT_EQ(sim->simulator().colliders().size(), 1u);
  for (int f = 0; f < 24; ++f) sim->step(1.0f / 24.0f);
  const std::vector<float> x = sim->positions();
  float inside = 0.0f, overTop = -INFINITY;
  for (size_t v = 0; v < x.size() / 3; ++v) {
    const glm::vec3 p(x[3 * v], x[3 * v + 1], x[3 * v + 2]);
    inside = std::max(inside, 0.15f - glm::length(p - centre));
    if (std::abs(p.x) < 0.04f && std::abs(p.z) < 0.04f) overTop = std::max(overTop, p.y);
  }
  EXPECT_LT(inside, 0.005f);
  EXPECT_GT(overTop, centre.y + 0.15f - 0.01f);  // resting on the moved sphere, not fallen past it
  EXPECT_LT(overTop, centre.y + 0.15f + 0.04f);
}

}  // namespace
}  // namespace mq

namespace mq {
namespace {

TEST(GarmentSheet, ExampleSheetAndCollidersSceneParses) {
  const SceneDocument doc =
      loadSceneDocument(std::string(MANNEQUIN_SOURCE_DIR) + "/resources/scenes/cloth_sheet_colliders.json");
  EXPECT_FALSE(doc.hasCharacter());
  const cloth::ClothSceneSpec spec = cloth::parseClothScene(doc.cloth, doc.colliders, "cloth_sheet_colliders.json");
  EXPECT_TRUE(spec.hasSheet);
  ASSERT_EQ(spec.colliders.size(), 3u);
  EXPECT_EQ(spec.colliders[0].shape, cloth::PrimitiveCollider::Shape::Sphere);
  EXPECT_EQ(spec.colliders[1].shape, cloth::PrimitiveCollider::Shape::Capsule);
  EXPECT_EQ(spec.colliders[2].shape, cloth::PrimitiveCollider::Shape::Plane);
  EXPECT_FLOAT_EQ(spec.colliders[2].friction, 0.6f);
}

}  // namespace
}  // namespace mq
