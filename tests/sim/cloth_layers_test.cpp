// Layering: an outer cloth against the surface of an inner one (one-way).
// A sheet dropped onto a sheet lying on a floor comes to rest on it, not
// through it; a vertex behind the inner sheet is pushed to the side its
// triangles face, one beyond its edge is left alone; the layer order.
#include <gtest/gtest.h>

#include <algorithm>

#include "cloth_test_scenes.h"
#include "sim/cloth/collision/cloth_surface_collider.h"
#include "sim/garment/garment_layers.h"
#include "sim/garment/garment_simulation.h"

namespace mq::cloth {
namespace {

// A horizontal sheet as a one-panel garment mesh, its triangles facing up
// (the side outer cloth belongs on).
GarmentMesh sheetFacingUp(int n, float size, glm::vec3 centre) {
  const Sheet s = makeSheet(horizontalSheet(n, size, centre));
  GarmentMesh mesh;
  mesh.positions = s.positions;
  mesh.triangles = s.triangles;
  const glm::vec3 a = vec3At(s.positions, s.triangles[0]), b = vec3At(s.positions, s.triangles[1]),
                  c = vec3At(s.positions, s.triangles[2]);
  if (glm::cross(b - a, c - a).y < 0.0f)
    for (size_t t = 0; t < mesh.triangles.size(); t += 3) std::swap(mesh.triangles[t + 1], mesh.triangles[t + 2]);
  mesh.restUvs.resize(s.uvs.size());
  for (size_t i = 0; i < s.uvs.size(); ++i) mesh.restUvs[i] = s.uvs[i] * size;
  mesh.panelIds.assign(s.vertexCount(), 0);
  mesh.panelFirstVertex = {0};
  return mesh;
}

GarmentSimulationSettings sheetSettings(glm::vec3 gravity = {0.0f, -9.81f, 0.0f}) {
  GarmentSimulationSettings settings;
  settings.fabric = fabricPreset("cotton");
  settings.cloth.gravity = gravity;
  return settings;
}

float minY(const std::vector<float>& flat) {
  float y = 1e30f;
  for (size_t i = 1; i < flat.size(); i += 3) y = std::min(y, flat[i]);
  return y;
}

float maxY(const std::vector<float>& flat) {
  float y = -1e30f;
  for (size_t i = 1; i < flat.size(); i += 3) y = std::max(y, flat[i]);
  return y;
}

// A sheet 2 cm above the floor and a smaller one dropped onto it from 15 cm,
// both colliding with the floor.
struct SheetDroppedOnASheet {
  GarmentSimulation inner{sheetFacingUp(16, 0.6f, {0, 0.02f, 0}), sheetSettings(), {}, {}};
  GarmentSimulation outer{sheetFacingUp(12, 0.4f, {0.02f, 0.15f, 0.01f}), sheetSettings(), {}, {}};

  SheetDroppedOnASheet() {
    const PrimitiveCollider floor = PrimitiveCollider::plane({0, 0, 0}, {0, 1, 0});
    inner.addCollider(floor);
    outer.addCollider(floor);
  }
};

TEST(ClothLayers, ASheetDroppedOnASheetOnTheFloorRestsOnIt) {
  SheetDroppedOnASheet scene;
  GarmentSimulation &inner = scene.inner, &outer = scene.outer;
  const std::vector<GarmentSimulation*> sims = {&outer, &inner};
  wearInLayers(sims, layerOrder(std::vector<int>{1, 0}));  // the first on layer 1: over the second
  const float dt = 1.0f / 30.0f;
  for (int frame = 0; frame < 45; ++frame) {
    inner.step(dt);
    outer.step(dt);
    EXPECT_EQ(verticesInside(outer, {&inner}), 0) << "frame " << frame;
  }
  const float thickness = sheetSettings().cloth.collisionThickness;
  const std::vector<float> innerNow = inner.positions(), outerNow = outer.positions();
  EXPECT_LT(maxY(innerNow), 2.0f * thickness);                   // the inner sheet lies on the floor
  EXPECT_GT(minY(outerNow), maxY(innerNow) + 0.5f * thickness);  // the outer one on it, not through it
  EXPECT_LT(maxY(outerNow), maxY(innerNow) + 3.0f * thickness);  // and has come to rest there
}

TEST(ClothLayers, WithoutLayersTheDroppedSheetFallsThrough) {
  SheetDroppedOnASheet scene;
  GarmentSimulation &inner = scene.inner, &outer = scene.outer;
  for (int frame = 0; frame < 45; ++frame) inner.step(1.0f / 30.0f), outer.step(1.0f / 30.0f);
  // On the floor beside the inner sheet: what the layering test guards against.
  EXPECT_LT(minY(outer.positions()), maxY(inner.positions()) + 0.5f * sheetSettings().cloth.collisionThickness);
}

// Still cloth (no gravity) placed 3 mm under the inner sheet, half of it
// under the sheet and half beyond its edge at x = 0.2.
TEST(ClothLayers, VerticesBehindTheSurfaceArePushedThroughThoseBeyondItsEdgeAreLeftAlone) {
  const glm::vec3 noGravity(0.0f);
  GarmentSimulation inner(sheetFacingUp(11, 0.4f, {0, 0, 0}), sheetSettings(noGravity), {}, {});
  GarmentSimulation outer(sheetFacingUp(11, 0.2f, {0.2f, -0.003f, 0}), sheetSettings(noGravity), {}, {});
  outer.setInnerGarments({&inner});
  const std::vector<float> start = outer.positions();
  inner.step(1.0f / 30.0f);
  outer.step(1.0f / 30.0f);
  const std::vector<float> now = outer.positions();
  int under = 0, beyond = 0;
  for (size_t i = 0; i < now.size() / 3; ++i) {
    const float x = start[3 * i];
    if (x < 0.19f && x > 0.12f) {  // under the sheet, away from its edge: now above it
      ++under;
      EXPECT_GT(now[3 * i + 1], 0.0f) << "vertex " << i;
    } else if (x > 0.21f && x < 0.28f) {  // beyond the edge: not moved (springs aside)
      ++beyond;
      EXPECT_LT(now[3 * i + 1], -0.002f) << "vertex " << i;
    }
  }
  EXPECT_GT(under, 10);
  EXPECT_GT(beyond, 10);
}

TEST(ClothLayers, TheColliderSaysNothingBeyondABoundaryEdge) {
  const GarmentMesh mesh = sheetFacingUp(5, 0.4f, {0, 0, 0});
  std::vector<glm::vec3> x(mesh.vertexCount());
  for (size_t i = 0; i < x.size(); ++i) x[i] = vec3At(mesh.positions, i);
  ClothSurfaceCollider surface;
  surface.setMesh(x, mesh.triangles);
  SurfaceContact contact;
  ASSERT_TRUE(surface.nearestContact({0.05f, -0.004f, 0.03f}, 0.02f, contact));  // behind the middle
  EXPECT_NEAR(contact.signedDistance, -0.004f, 1e-5f);
  EXPECT_NEAR(contact.normal.y, 1.0f, 1e-4f);                                   // out is up, through the sheet
  ASSERT_TRUE(surface.nearestContact({0.05f, 0.003f, 0.03f}, 0.02f, contact));  // in front
  EXPECT_NEAR(contact.signedDistance, 0.003f, 1e-5f);
  EXPECT_FALSE(surface.nearestContact({0.21f, -0.002f, 0.03f}, 0.02f, contact));  // beyond the edge x = 0.2
  EXPECT_FALSE(surface.nearestContact({0.21f, -0.002f, 0.21f}, 0.02f, contact));  // beyond the corner
  // Beyond the edge on the front side: only kept off the edge, outwards.
  ASSERT_TRUE(surface.nearestContact({0.203f, 0.001f, 0.03f}, 0.02f, contact));
  EXPECT_GT(contact.signedDistance, 0.0f);
  EXPECT_GT(contact.normal.x, 0.9f);
  ASSERT_TRUE(surface.nearestContact({0.2f, -0.004f, 0.03f}, 0.02f, contact));  // right under the edge
  EXPECT_LT(contact.signedDistance, 0.0f);
  // Moving: the contact has the surface's velocity.
  for (glm::vec3& p : x) p.y += 0.01f;
  surface.setTarget(x, 0.1f);
  surface.moveTo(0.5f);
  ASSERT_TRUE(surface.nearestContact({0.05f, 0.0f, 0.03f}, 0.02f, contact));
  EXPECT_NEAR(contact.point.y, 0.005f, 1e-5f);
  EXPECT_NEAR(contact.velocity.y, 0.1f, 1e-4f);
}

TEST(ClothLayers, LayerOrderIsByLayerThenByListOrder) {
  EXPECT_EQ(layerOrder(std::vector<int>{0, 0, 0}), (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(layerOrder(std::vector<int>{2, 0, 1, 0}), (std::vector<size_t>{1, 3, 2, 0}));
}

}  // namespace
}  // namespace mq::cloth
