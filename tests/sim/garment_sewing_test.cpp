// A T-shirt sewn on the default mannequin: seam springs close the seams, the
// seams are welded, and the settled shirt has no vertex inside the body.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/garment/body_measurements.h"
#include "core/garment/parametric_garments.h"
#include "core/io/character_import.h"
#include "garment_test_garments.h"
#include "sim/garment/garment_sewing.h"
#include "sim/garment/garment_simulation.h"

namespace mq {
namespace {

using namespace mq::cloth;

// Ray parity: is p inside the closed triangle mesh? (a +X ray, Moller-Trumbore)
bool insideClosedMesh(const std::vector<float>& positions, const std::vector<uint32_t>& triangles, glm::vec3 p) {
  const glm::vec3 dir = glm::normalize(glm::vec3(1.0f, 0.0123f, 0.0217f));  // avoids grazing edges
  int crossings = 0;
  for (size_t t = 0; t < triangles.size(); t += 3) {
    glm::vec3 a = vec3At(positions, triangles[t]), b = vec3At(positions, triangles[t + 1]),
              c = vec3At(positions, triangles[t + 2]);
    glm::vec3 e1 = b - a, e2 = c - a, q = glm::cross(dir, e2);
    float det = glm::dot(e1, q);
    if (std::abs(det) < 1e-12f) continue;
    glm::vec3 s = p - a;
    float u = glm::dot(s, q) / det;
    if (u < 0.0f || u > 1.0f) continue;
    glm::vec3 r = glm::cross(s, e1);
    float v = glm::dot(dir, r) / det;
    if (v < 0.0f || u + v > 1.0f) continue;
    if (glm::dot(e2, r) / det > 0.0f) ++crossings;
  }
  return crossings % 2 == 1;
}

TEST(GarmentSewing, WeldRemapsSpringsAndKeepsRestLengths) {
  // Two squares side by side, 5 cm apart, sewn along the shared side.
  const Garment g = test::twoSewnSquares(0.0f);
  ClothMesh mesh = clothMeshFromGarment(buildGarmentMesh(g));
  ClothTopology topology = buildClothTopology(mesh);
  WeldedCloth welded = weldClothSeams(mesh, topology);
  EXPECT_EQ(welded.mesh.vertexCount(), mesh.vertexCount() - mesh.seams.size());
  EXPECT_TRUE(welded.mesh.seams.empty());
  EXPECT_EQ(welded.mesh.triangles.size(), mesh.triangles.size());
  // The seam's edge springs from both panels became one each, with both areas.
  EXPECT_EQ(welded.topology.structural.size(), topology.structural.size() - (mesh.seams.size() - 1));
  float area = 0.0f;
  for (const SpringTopology& s : welded.topology.structural) area += s.area;
  float before = 0.0f;
  for (const SpringTopology& s : topology.structural) before += s.area;
  EXPECT_NEAR(area, before, 1e-6f);
  // Rest lengths are the pattern's, not the 5 cm gap's.
  for (const SpringTopology& s : welded.topology.structural) EXPECT_LE(s.restLength, 0.05f * 1.0001f);
}

// A garment sewn on the default mannequin in its rest pose through
// GarmentSimulation (seams closing at a limited speed, velocities damped
// while sewing, then the weld) and left to settle.
struct SewnGarment {
  size_t vertices = 0;
  float initialGap = 0.0f;
  bool welded = false;
  int sewingFrames = 0;
  float gapAtWeld = 0.0f;  // widest seam gap just before the weld snapped it shut
  float finalStretch = 0.0f;
  int penetrating = 0;
  int startInsideBody = 0;  // placed panel vertices inside the body before sewing
  int insideBody = 0;
  Aabb bounds;
};

SewnGarment sewOn(const Character& body, const std::string& type, float edge, int settleFrames,
                  CgPreconditioner preconditioner = ClothSettings{}.cgPreconditioner) {
  PosedCharacter rest;
  rest.evaluate(body, -1, 0.0f, nullptr, nullptr);
  std::vector<float> bodyPositions;  // every mesh of the body, as one
  std::vector<uint32_t> bodyTriangles;
  for (size_t m = 0; m < body.meshes.size(); ++m) {
    const uint32_t first = uint32_t(bodyPositions.size() / 3);
    for (uint32_t i : body.meshes[m].triangles) bodyTriangles.push_back(first + i);
    bodyPositions.insert(bodyPositions.end(), rest.meshes()[m].positions.begin(), rest.meshes()[m].positions.end());
  }
  Garment garment = makeParametricGarment(type, body);
  garment.targetEdgeLength = edge;
  GarmentSimulationSettings settings;
  settings.fabric = fabricPreset("cotton");
  settings.cloth.collisionThickness = 0.004f;
  settings.cloth.cgPreconditioner = preconditioner;
  const GarmentMesh placed = buildGarmentMesh(garment);
  GarmentSimulation sim(placed, settings, bodyPositions, bodyTriangles);
  SewnGarment out;
  for (size_t i = 0; i < placed.vertexCount(); ++i)
    out.startInsideBody += insideClosedMesh(bodyPositions, bodyTriangles, placed.position(i)) ? 1 : 0;
  out.vertices = sim.vertexCount();
  out.initialGap = sim.seamGap();
  const float dt = 1.0f / 30.0f;
  for (; out.sewingFrames < 120 && !sim.welded(); ++out.sewingFrames) {
    out.gapAtWeld = sim.seamGap();
    sim.step(dt);
  }
  out.welded = sim.welded();
  for (int f = 0; f < settleFrames; ++f) sim.step(dt);
  const std::vector<float> x = sim.positions();
  for (size_t i = 0; i < sim.vertexCount(); ++i)
    out.insideBody += insideClosedMesh(bodyPositions, bodyTriangles, vec3At(x, i)) ? 1 : 0;
  out.penetrating = sim.simulator().penetratingVertices();
  out.finalStretch = sim.stats().maxStretch;
  out.bounds = boundsOf(x);
  std::printf(
      "%s on %s: %zu vertices, seam gap %.3f m, welded after %d frames (gap %.4f m), bounds y %.3f..%.3f, stretch "
      "%.3f, "
      "%d inside the body (%d by the solver's test)\n",
      type.c_str(), body.name.c_str(), out.vertices, out.initialGap, out.sewingFrames, out.gapAtWeld, out.bounds.min.y,
      out.bounds.max.y, out.finalStretch, out.insideBody, out.penetrating);
  return out;
}

SewnGarment sewOnMannequin(const std::string& type, float edge, int settleFrames) {
  return sewOn(makeDefaultMannequin(), type, edge, settleFrames);
}

// Seams that close too fast (stiff zero-length springs close the shoulder
// gap in one or two implicit steps) let body contact push the shoulder seams
// up and the elongation limit drag the shirt after them, up to the head.
TEST(GarmentSewing, TShirtOnMannequinClosesSeamsWeldsAndSettlesOutsideTheBody) {
  const SewnGarment shirt = sewOnMannequin("tshirt", 0.035f, 60);
  EXPECT_GT(shirt.initialGap, 0.05f);  // the panels really started apart
  EXPECT_TRUE(shirt.welded);
  // The seams closed (or stalled within a centimetre, held by the body)
  // within the sewing time: the weld only snaps a small gap shut. When they
  // close is chaotic (one rounding in the body queries moves it by ten
  // frames), so the gap is asserted, not the frame.
  EXPECT_LE(shirt.sewingFrames, 61);
  EXPECT_LT(shirt.gapAtWeld, 0.01f);
  EXPECT_EQ(shirt.penetrating, 0);
  EXPECT_EQ(shirt.insideBody, 0) << "settled shirt vertices inside the body mesh";
  EXPECT_LE(shirt.finalStretch, 1.1f + 1e-3f);
  // The shirt hangs on the shoulders: it neither fell to the floor nor rode
  // up over the head, and it still covers the waist.
  EXPECT_GT(shirt.bounds.min.y, 0.6f);
  EXPECT_LT(shirt.bounds.min.y, 1.0f);
  EXPECT_LT(shirt.bounds.max.y, 1.6f);
}

// A skirt and trousers stay where they are worn: the waistband between the
// hips and a little above the waist joint, nothing inside the body.
void expectWornAtTheWaist(const SewnGarment& g) {
  const BodyMeasurements body = measureBody(makeDefaultMannequin());
  EXPECT_GT(g.initialGap, 0.05f);
  EXPECT_TRUE(g.welded);
  EXPECT_LT(g.sewingFrames, 60);
  EXPECT_EQ(g.penetrating, 0);
  EXPECT_EQ(g.insideBody, 0);
  EXPECT_LE(g.finalStretch, 1.1f + 1e-3f);
  EXPECT_GT(g.bounds.max.y, std::min(body.hip[0].y, body.hip[1].y));
  EXPECT_LT(g.bounds.max.y, body.waist.y + 0.1f);
  EXPECT_GT(g.bounds.min.y, 0.05f);  // not down on the floor
}

TEST(GarmentSewing, SkirtSettlesOnTheHips) {
  const SewnGarment skirt = sewOnMannequin("skirt", 0.035f, 40);
  expectWornAtTheWaist(skirt);
}

TEST(GarmentSewing, TrousersSettleOnTheWaistWithTheCrotchSewnBelowTheBody) {
  const SewnGarment trousers = sewOnMannequin("trousers", 0.035f, 40);
  expectWornAtTheWaist(trousers);
  const BodyMeasurements body = measureBody(makeDefaultMannequin());
  EXPECT_LT(trousers.bounds.min.y, std::min(body.knee[0].y, body.knee[1].y));  // the legs cover the knees
}

// The built-in garments on an imported character whose bones no alias names
// (CesiumMan, about 1.5 units tall): sized from its skeleton's structure and
// skin, sewn on its rest pose, nothing inside the body after settling.
// CesiumMan's arms leave the torso high and nearly level, and its left upper
// arm's bone also drives the skin of the shoulder: a sleeve sized and placed
// by that bone's capsule stood out like a wing, and its cap closed through
// the arm's root (21 of the shirt's 1269 vertices inside the body, all at
// the left armpit). The sleeves now follow the arm's measured girth.
class GarmentOnCesiumMan : public ::testing::TestWithParam<std::string> {};

TEST_P(GarmentOnCesiumMan, SewsWeldsAndSettlesOutsideTheBody) {
  const Character body =
      importCharacter(std::string(MANNEQUIN_SHARED_DIR) + "/assets/characters/CesiumMan/glTF/CesiumMan.gltf");
  const BodyMeasurements m = measureBody(body);
  const SewnGarment g = sewOn(body, GetParam(), 0.035f, 40);
  EXPECT_GT(g.initialGap, 0.05f);
  EXPECT_TRUE(g.welded);
  EXPECT_LT(g.sewingFrames, 70);
  EXPECT_LE(g.finalStretch, 1.1f + 1e-3f);
  EXPECT_GT(g.bounds.min.y, 0.05f);  // not down on the floor
  EXPECT_EQ(g.startInsideBody, 0) << "panels placed inside the body";
  // The T-shirt: 0 inside with vertex contacts alone; the body-vertex
  // contacts against cloth triangles (which keep a limb from passing between
  // cloth vertices) leave 4 of its 1220 vertices inside where the arms meet
  // the torso. Bounded at 0.5% (21 inside, 1.7%, before the sleeves followed
  // the arm's girth).
  const int allowedInside = GetParam() == "tshirt" ? int(g.vertices / 200) : 0;
  EXPECT_LE(g.penetrating, allowedInside);
  EXPECT_LE(g.insideBody, allowedInside) << "settled vertices inside the body mesh";
  if (GetParam() == "tshirt") {
    EXPECT_LT(g.bounds.max.y, m.neck.y + 0.1f);  // hangs on the shoulders, not over the head
    EXPECT_GT(g.bounds.max.y, m.shoulder[0].y);
    EXPECT_LT(g.bounds.min.y, m.waist.y);  // and covers the waist
  } else {
    EXPECT_GT(g.bounds.max.y, std::min(m.hip[0].y, m.hip[1].y));  // worn at the waist, not slid up or down
    EXPECT_LT(g.bounds.max.y, m.waist.y + 0.1f);
  }
}

INSTANTIATE_TEST_SUITE_P(Types, GarmentOnCesiumMan, ::testing::Values("tshirt", "skirt", "trousers"));

// Settled with the two-level solve, which carries a tight waistband's
// tension around the hips: held by resting contacts on the upward-facing
// surfaces alone, the band was squeezed up (0.5 m, 13 vertices into the body).
TEST(GarmentSewing, TrousersOnCesiumManStayAtTheWaistWithTheTwoLevelSolve) {
  const Character body =
      importCharacter(std::string(MANNEQUIN_SHARED_DIR) + "/assets/characters/CesiumMan/glTF/CesiumMan.gltf");
  const BodyMeasurements m = measureBody(body);
  const SewnGarment g = sewOn(body, "trousers", 0.035f, 40, CgPreconditioner::TwoLevel);
  EXPECT_TRUE(g.welded);
  EXPECT_EQ(g.insideBody, 0) << "settled vertices inside the body mesh";
  EXPECT_GT(g.bounds.max.y, std::min(m.hip[0].y, m.hip[1].y));
  EXPECT_LT(g.bounds.max.y, m.waist.y + 0.1f);
  EXPECT_GT(g.bounds.min.y, 0.05f);
}

// The editor's warm start: a shirt sewn and settled on the mannequin, then
// simulated again from that drape with many pins chosen on it (every
// seventh vertex, following the body): the pins hold it where it is, and
// nothing is pulled past the elongation limit.
TEST(GarmentSewing, ShirtStartedFromItsDrapeWithPinsChosenOnItKeepsItsShape) {
  const Character body = makeDefaultMannequin();
  PosedCharacter rest;
  rest.evaluate(body, -1, 0.0f, nullptr, nullptr);
  const std::vector<float> bodyPositions = concatenatedPositions(rest.meshes());
  const std::vector<uint32_t> bodyTriangles = concatenatedTriangles(body);
  Garment garment = makeParametricGarment("tshirt", body);
  garment.targetEdgeLength = 0.045f;
  GarmentSimulationSettings settings;
  settings.fabric = fabricPreset("cotton");
  const GarmentMesh mesh = buildGarmentMesh(garment);
  const float dt = 1.0f / 30.0f;
  GarmentSimulation sewn(mesh, settings, bodyPositions, bodyTriangles);
  for (int f = 0; f < 150 && !sewn.welded(); ++f) sewn.step(dt);
  ASSERT_TRUE(sewn.welded());
  for (int f = 0; f < 30; ++f) sewn.step(dt);
  const std::vector<float> drape = sewn.positions();
  auto largest = [](const std::vector<float>& v) { return *std::max_element(v.begin(), v.end()); };
  const float settled = largest(sewn.vertexStretch());

  for (const int every : {0, 7}) {
    GarmentSimulation warm(mesh, settings, bodyPositions, bodyTriangles);
    std::vector<uint32_t> pins;
    for (uint32_t v = 0; every > 0 && v < mesh.vertexCount(); v += every) warm.pinToBody(v), pins.push_back(v);
    warm.startFromDrape(drape, bodyPositions);
    const float atStart = largest(warm.vertexStretch());
    for (int f = 0; f < 5; ++f) warm.step(dt);
    const std::vector<float> x = warm.positions();
    float pinMoved = 0.0f;
    for (uint32_t v : pins) pinMoved = std::max(pinMoved, glm::length(vec3At(x, v) - vec3At(drape, v)));
    std::printf("every %d: settled %.3f, at start %.3f, after 5 steps %.3f, pins moved %.4f m\n", every, settled,
                atStart, largest(warm.vertexStretch()), pinMoved);
    EXPECT_LT(largest(warm.vertexStretch()), std::max(settled, 1.1f) + 0.005f) << "pins every " << every;
    EXPECT_LT(pinMoved, 1e-3f);
  }
}

}  // namespace
}  // namespace mq
