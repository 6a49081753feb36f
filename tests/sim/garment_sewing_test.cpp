// A T-shirt sewn on the default mannequin: seam springs close the seams, the
// seams are welded, and the settled shirt has no vertex inside the body.
#include <gtest/gtest.h>

#include <cmath>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/garment/parametric_garments.h"
#include "sim/garment/garment_sewing.h"

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
  // Two squares side by side, sewn along the shared side.
  Garment g;
  g.name = "pair";
  g.targetEdgeLength = 0.05f;
  for (const char* name : {"left", "right"}) {
    Panel p;
    p.name = name;
    p.addLine("bottom", {0, 0});
    p.addLine("east", {0.2f, 0});
    p.addLine("top", {0.2f, 0.2f});
    p.addLine("west", {0, 0.2f});
    p.placement.center = {std::string(name) == "left" ? -0.2f : 0.05f, 0, 0};  // a 5 cm gap
    g.panels.push_back(p);
  }
  g.seams.push_back({"left", "east", "right", "west", true});
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

// DISABLED: with the current solver (implicit Euler, one step per frame) the
// stiff zero-length seam springs close the 0.4 m shoulder gap in one or two
// steps, the body contact pushes the shoulder seams up and the elongation
// limit drags the whole shirt after them: the shirt rides up to the head
// (bounds y 1.41..1.75 m here; 2.2..2.9 m, above the head, for 4 cm edges
// after 40 frames) instead of settling on the shoulders.
// Seams do close and weld, and nothing penetrates, but only because the shirt
// has left the body, which the bounds checks below catch. Zeroing velocities
// after every sewing frame does not help (the jump happens inside a step);
// rate-limited seam pulling is too slow against the stretch limit. Enable
// once sewing is gentle (ramped seam stiffness or seams in the constraint
// solve).
TEST(GarmentSewing, DISABLED_TShirtOnMannequinClosesSeamsWeldsAndSettlesOutsideTheBody) {
  const Character body = makeDefaultMannequin();
  PosedCharacter rest;
  rest.evaluate(body, -1, 0.0f, nullptr, nullptr);
  const std::vector<float>& bodyPositions = rest.meshes()[0].positions;
  const std::vector<uint32_t>& bodyTriangles = body.meshes[0].triangles;

  Garment shirt = makeParametricGarment("tshirt", body);
  shirt.targetEdgeLength = 0.035f;
  ClothMesh mesh = clothMeshFromGarment(buildGarmentMesh(shirt));
  const Fabric fabric = fabricPreset("cotton");
  ClothSettings settings;
  settings.collisionThickness = 0.004f;
  auto sim = std::make_unique<ClothSimulator>(mesh, fabric, settings);
  sim->setBody(bodyPositions, bodyTriangles);

  const float dt = 1.0f / 30.0f;
  const float initialGap = maxSeamGap(sim->positions(), mesh.seams);
  int frame = 0;
  for (; frame < 120 && maxSeamGap(sim->positions(), mesh.seams) > 0.004f; ++frame) sim->step(dt);
  const float sewnGap = maxSeamGap(sim->positions(), mesh.seams);
  std::printf("T-shirt: %zu vertices, seam gap %.3f m -> %.4f m after %d frames\n", mesh.vertexCount(), initialGap,
              sewnGap, frame);
  EXPECT_GT(initialGap, 0.05f);  // the panels really started apart
  EXPECT_LT(sewnGap, 0.01f);     // the seam springs pulled them together

  WeldedCloth welded = weldClothSeams(mesh, buildClothTopology(mesh));
  sim = continueWelded(*sim, welded, fabric);
  sim->setBody(bodyPositions, bodyTriangles);
  // Welded vertices coincide: every seam pair is one vertex now.
  for (auto [a, b] : mesh.seams) ASSERT_EQ(welded.weld.newIndex[a], welded.weld.newIndex[b]);
  for (int settle = 0; settle < 60; ++settle) sim->step(dt);

  EXPECT_EQ(sim->countPenetrating(), 0);
  const std::vector<glm::vec3>& x = sim->positions();
  int inside = 0;
  for (const glm::vec3& p : x) inside += insideClosedMesh(bodyPositions, bodyTriangles, p) ? 1 : 0;
  EXPECT_EQ(inside, 0) << "settled shirt vertices inside the body mesh";
  EXPECT_LE(sim->stats().maxStretch, 1.1f + 1e-3f);
  // The shirt hangs on the shoulders: it neither fell to the floor nor rode
  // up over the head, and it still covers the waist.
  Aabb bounds = boundsOf(sim->flatPositions());
  EXPECT_GT(bounds.min.y, 0.6f);
  EXPECT_LT(bounds.min.y, 1.0f);
  EXPECT_LT(bounds.max.y, 1.6f);
}

}  // namespace
}  // namespace mq
