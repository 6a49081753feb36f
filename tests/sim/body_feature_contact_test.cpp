// Body vertices against cloth triangles: a thin spike rising into a coarse
// sheet between its vertices (no cloth vertex ever near the spike) must tent
// the sheet over its tip rather than pass through it; cloth beyond a thin
// body part must not be pulled through it.
#include <gtest/gtest.h>

#include <optional>

#include "cloth_test_scenes.h"
#include "core/character/posed_character.h"
#include "core/garment/garment_json.h"
#include "core/scene/open_scene.h"
#include "garment_test_garments.h"
#include "sim/cloth/cloth_scene_io.h"
#include "sim/cloth/collision/body_feature_contact.h"
#include "sim/garment/garment_scene.h"

namespace mq::cloth {
namespace {

// A closed square pyramid, outward triangles: base centred at (x, base, z)
// with half-width `halfWidth`, apex `height` above it.
void spike(float x, float z, float base, float halfWidth, float height, std::vector<float>& positions,
           std::vector<uint32_t>& triangles) {
  positions = {x - halfWidth,
               base,
               z - halfWidth,
               x + halfWidth,
               base,
               z - halfWidth,
               x + halfWidth,
               base,
               z + halfWidth,
               x - halfWidth,
               base,
               z + halfWidth,
               x,
               base + height,
               z};
  triangles = {0, 1, 2, 0, 2, 3,                     // base, facing down
               0, 4, 1, 1, 4, 2, 2, 4, 3, 3, 4, 0};  // sides
}

// A closed box, outward triangles, from corner `lo` to corner `hi`.
void box(glm::vec3 lo, glm::vec3 hi, std::vector<float>& positions, std::vector<uint32_t>& triangles) {
  positions.clear();
  for (int k = 0; k < 8; ++k)
    positions.insert(positions.end(), {k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
  triangles = {0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3,   // y = lo, y = hi
               0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5,   // x = lo, x = hi
               0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};  // z = lo, z = hi
}

std::vector<float> raised(std::vector<float> positions, float dy) {
  for (size_t i = 1; i < positions.size(); i += 3) positions[i] += dy;
  return positions;
}

// Height of the cloth over (x, z): the triangle whose footprint holds it.
std::optional<float> clothHeightAt(const ClothSimulator& sim, float x, float z) {
  const auto& p = sim.positions();
  const auto& t = sim.triangles();
  for (size_t k = 0; k < t.size(); k += 3) {
    const glm::vec2 a(p[t[k]].x, p[t[k]].z), b(p[t[k + 1]].x, p[t[k + 1]].z), c(p[t[k + 2]].x, p[t[k + 2]].z);
    const glm::vec2 q(x, z);
    const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (area == 0.0f) continue;
    const float wb = ((q.x - a.x) * (c.y - a.y) - (q.y - a.y) * (c.x - a.x)) / area;
    const float wc = ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x)) / area;
    const float wa = 1.0f - wb - wc;
    if (wa < 0.0f || wb < 0.0f || wc < 0.0f) continue;
    return wa * p[t[k]].y + wb * p[t[k + 1]].y + wc * p[t[k + 2]].y;
  }
  return std::nullopt;
}

// A 5 x 5 sheet (25 cm cells) pinned along its border at y = 0.5; a spike
// 2 cm wide rises from below into the middle of one triangle, 13 cm from
// the nearest cloth vertex, up to 4 cm above the pinned border.
TEST(BodyFeatureContact, ASpikeBetweenClothVerticesTentsTheSheetInsteadOfPiercingIt) {
  const int n = 5;
  const float top = 0.5f;
  ClothSettings settings;
  settings.maxRefinement = 1;
  ClothSimulator sim(test::horizontalSheetMesh(n, 1.0f, {0, top, 0}), fabricPreset("cotton"), settings);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      if (r == 0 || c == 0 || r == n - 1 || c == n - 1) sim.pinVertex(uint32_t(r * n + c));
  const float tipX = 0.075f, tipZ = 0.1125f;  // inside a triangle of the cell [0, 0.25]^2 whichever its diagonal
  for (const glm::vec3& x : sim.positions()) ASSERT_GT(glm::length(glm::vec2(x.x - tipX, x.z - tipZ)), 0.12f);
  std::vector<float> rest;
  std::vector<uint32_t> triangles;
  const float height = 0.3f, startTip = top - 0.15f, endTip = top + 0.04f;
  spike(tipX, tipZ, startTip - height, 0.01f, height, rest, triangles);
  sim.setBody(rest, triangles);
  const int rising = 48;
  int contacts = 0;
  for (int frame = 0; frame < rising + 24; ++frame) {
    const float tip = startTip + (endTip - startTip) * float(std::min(frame + 1, rising)) / float(rising);
    sim.updateBody(raised(rest, tip - startTip));
    sim.step(1.0f / 24.0f);
    contacts += sim.stats().bodyFeatureContacts;
  }
  EXPECT_TRUE(test::allFinite(sim));
  EXPECT_GT(contacts, 0);
  const std::optional<float> cloth = clothHeightAt(sim, tipX, tipZ);
  ASSERT_TRUE(cloth.has_value());
  // Over the tip by about half the thickness (the gap kept at a body vertex).
  EXPECT_GT(*cloth, endTip);
  EXPECT_LT(*cloth, endTip + 0.01f);
  EXPECT_EQ(sim.countPenetrating(), 0);
  EXPECT_LE(sim.stats().maxStretchEver, 1.1f + 1e-3f);
}

// Cloth lying on a floor under a thin plate (8 mm thick, 7 mm above the
// cloth): the plate's top corners are 1.5 cm over the cloth with their normals
// away from it, but the plate is between them, so the cloth stays where it is
// rather than being pulled up through the plate.
TEST(BodyFeatureContact, ClothBeyondAThinBodyPartIsLeftAlone) {
  ClothSettings settings;
  settings.maxRefinement = 1;
  ClothSimulator sim(test::horizontalSheetMesh(5, 0.4f, {0, 0.005f, 0}), fabricPreset("cotton"), settings);
  sim.addCollider(PrimitiveCollider::plane({0, 0, 0}, {0, 1, 0}));
  std::vector<float> plate;
  std::vector<uint32_t> triangles;
  const float bottom = 0.012f;
  box({-0.03f, bottom, -0.04f}, {0.07f, bottom + 0.008f, 0.06f}, plate, triangles);
  sim.setBody(plate, triangles);
  for (int frame = 0; frame < 24; ++frame) sim.step(1.0f / 24.0f);
  EXPECT_TRUE(test::allFinite(sim));
  for (const glm::vec3& x : sim.positions()) EXPECT_LT(x.y, bottom);
  const std::optional<float> cloth = clothHeightAt(sim, 0.07f, 0.06f);  // under a top corner
  ASSERT_TRUE(cloth.has_value());
  EXPECT_LT(*cloth, bottom);
}

// The trousers of the app test's scene, their panels as placed around the
// default mannequin before sewing (flat, so the walking legs cross them),
// swaying a little from frame to frame (and once widened), against the legs
// over 24 frames of the walk: the tree search (a four-wide tree, refitted and
// rebuilt; four body vertices tested at once) finds exactly the pairs of
// testing every body vertex against every cloth triangle one at a time, in
// the same order.
TEST(BodyFeatureContact, TheTreeFindsThePairsOfTestingEveryTriangle) {
  const mq::test::TrousersWalk walk;
  const auto& [file, scene, garments, spec] = walk;
  ASSERT_TRUE(walk.hasOneGarmentAndAClip());
  PosedCharacter posed;
  posed.evaluate(scene.character, -1, 0.0f, &scene.edits, nullptr);
  const std::vector<float> rest = concatenatedPositions(posed.meshes());
  const std::vector<uint32_t> bodyTriangles = concatenatedTriangles(scene.character);
  const auto garment = makeGarmentSimulation(garments[0], spec, rest, bodyTriangles, "garments[0]");
  const ClothState placed = garment->simulator().state();
  const std::vector<uint32_t>& triangles = garment->simulator().triangles();
  const float thickness = garment->simulator().settings().collisionThickness, dt = 1.0f / spec.fps;

  BodyFeatureContact tree(triangles, placed.x),
      everyTriangle(triangles, placed.x, BodyFeatureContact::Search::EveryTriangle);
  BodyCollider body;
  body.setMesh(rest, bodyTriangles, 0.02f);
  ClothState cloth = placed;
  std::vector<uint8_t> touched(cloth.size(), 0), touchedToo(cloth.size(), 0);
  size_t pairs = 0, pierced = 0;
  for (int frame = 0; frame < 24; ++frame) {
    posed.evaluate(scene.character, scene.clipIndex, float(frame) * dt, &scene.edits, nullptr);
    body.setTarget(concatenatedPositions(posed.meshes()), dt);
    body.moveTo(1.0f);
    for (size_t i = 0; i < cloth.size(); ++i)
      cloth.x[i] += 0.003f * glm::vec3(std::sin(0.7f * float(frame) + 0.01f * float(i)), 0.0f,
                                       std::cos(0.5f * float(frame) + 0.02f * float(i)));
    // Once the cloth 40% wider: its tree is rebuilt.
    if (frame == 12)
      for (glm::vec3& x : cloth.x) x *= glm::vec3(1.4f, 1.0f, 1.4f);
    ClothState clothToo = cloth;
    const int found = tree.resolve(cloth, body, thickness, touched, 1, 2);
    EXPECT_EQ(found, everyTriangle.resolve(clothToo, body, thickness, touchedToo, 1, 2)) << "frame " << frame;
    const std::vector<BodyFeatureContact::Pair> got = tree.lastPairs();
    ASSERT_TRUE(got == everyTriangle.lastPairs()) << "frame " << frame;
    EXPECT_TRUE(cloth.x == clothToo.x) << "frame " << frame;
    pairs += got.size();
    for (const auto& p : got) pierced += p.pierced ? 1 : 0;
  }
  // Not a vacuous comparison: pairs in front of body vertices and pierced ones.
  EXPECT_GT(pairs - pierced, 100u);
  EXPECT_GT(pierced, 20u);
  std::printf("%zu pairs, %zu pierced\n", pairs, pierced);
}

}  // namespace
}  // namespace mq::cloth
