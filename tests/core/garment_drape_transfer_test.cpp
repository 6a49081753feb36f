// A drape carried across a rebuild of the garment's mesh (core/garment/drape_transfer.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/character/default_mannequin.h"
#include "core/garment/drape_transfer.h"
#include "core/garment/parametric_garments.h"
#include "core/util/error.h"

namespace mq {
namespace {

const Character& mannequin() {
  static const Character character = makeDefaultMannequin();
  return character;
}

// A smooth made-up drape: the placed panels bent and shifted.
glm::vec3 bent(glm::vec3 p) {
  return {p.x + 0.05f * p.y * p.y, p.y - 0.1f + 0.03f * std::sin(6.0f * p.x), p.z + 0.02f * p.x};
}

std::vector<float> bentDrape(const GarmentMesh& mesh) {
  std::vector<float> out;
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    const glm::vec3 p = bent(mesh.position(v));
    out.insert(out.end(), {p.x, p.y, p.z});
  }
  return out;
}

float largestError(const GarmentMesh& mesh, const std::vector<float>& drape) {
  float worst = 0.0f;
  for (size_t v = 0; v < mesh.vertexCount(); ++v)
    worst = std::max(worst,
                     glm::length(glm::vec3(drape[3 * v], drape[3 * v + 1], drape[3 * v + 2]) - bent(mesh.position(v))));
  return worst;
}

TEST(GarmentDrapeTransfer, SameMeshKeepsTheDrape) {
  const GarmentMesh mesh = buildGarmentMesh(makeParametricGarment("tshirt", mannequin()));
  EXPECT_LT(largestError(mesh, transferDrape(mesh, bentDrape(mesh), mesh)), 1e-5f);
}

TEST(GarmentDrapeTransfer, FinerMeshInterpolatesTheDrape) {
  Garment coarse = makeParametricGarment("tshirt", mannequin());
  coarse.targetEdgeLength = 0.04f;
  Garment fine = coarse;
  fine.targetEdgeLength = 0.02f;
  const GarmentMesh before = buildGarmentMesh(coarse), after = buildGarmentMesh(fine);
  ASSERT_GT(after.vertexCount(), 2 * before.vertexCount());
  const std::vector<float> carried = transferDrape(before, bentDrape(before), after);
  ASSERT_EQ(carried.size(), 3 * after.vertexCount());
  // New vertices between the old ones lie on the old drape's triangles: a
  // few millimetres from the smooth drape at a 4 cm resolution.
  EXPECT_LT(largestError(after, carried), 0.01f);
  // Nearest-vertex copying would be off by up to half an edge.
  std::vector<float> copied;
  for (size_t v = 0; v < after.vertexCount(); ++v) {
    size_t nearest = 0;
    for (size_t w = 0; w < before.vertexCount(); ++w)
      if (glm::length(before.position(w) - after.position(v)) <
          glm::length(before.position(nearest) - after.position(v)))
        nearest = w;
    const glm::vec3 p = bent(before.position(nearest));
    copied.insert(copied.end(), {p.x, p.y, p.z});
  }
  EXPECT_GT(largestError(after, copied), 2.0f * largestError(after, carried));
}

TEST(GarmentDrapeTransfer, LongerShirtTakesTheDrapeOfTheSamePlaceInEachPanel) {
  const Garment shirt = makeParametricGarment("tshirt", mannequin());
  Garment longer = shirt;
  longer.recipe.parameters["length"] = 0.8f;
  longer = rebuildParametricGarment(longer, mannequin());
  const GarmentMesh before = buildGarmentMesh(shirt), after = buildGarmentMesh(longer);
  const std::vector<float> drape = bentDrape(before);
  const std::vector<float> carried = transferDrape(before, drape, after);
  // The hem (lowest vertex of the front panel) takes the old hem's drape.
  auto lowestOfPanel = [](const GarmentMesh& mesh, const std::vector<float>& positions) {
    float lowest = 1e9f;
    for (size_t v = 0; v < mesh.vertexCount(); ++v)
      if (mesh.panelIds[v] == 0) lowest = std::min(lowest, positions[3 * v + 1]);
    return lowest;
  };
  EXPECT_NEAR(lowestOfPanel(after, carried), lowestOfPanel(before, drape), 0.01f);
  EXPECT_LT(lowestOfPanel(after, after.positions), lowestOfPanel(before, before.positions) - 0.05f);  // it is longer
}

TEST(GarmentDrapeTransfer, DrapeOfAnotherMeshIsRefused) {
  const GarmentMesh mesh = buildGarmentMesh(makeParametricGarment("skirt", mannequin()));
  EXPECT_THROW(transferDrape(mesh, std::vector<float>(6, 0.0f), mesh), Error);
}

}  // namespace
}  // namespace mq
