// The sewn topology of the built-in garments: welding their seams must leave
// one piece with exactly the rims a tailor expects (a missed or doubled seam
// adds or removes a loop), and the boundary walk itself on simple meshes.
#include <gtest/gtest.h>

#include "core/character/default_mannequin.h"
#include "core/garment/parametric_garments.h"
#include "core/garment/seam_weld.h"
#include "core/mesh/boundary_loops.h"
#include "core/mesh/mesh_checks.h"
#include "core/util/error.h"

namespace mq {
namespace {

const Character& mannequin() {
  static const Character character = makeDefaultMannequin();
  return character;
}

struct Sewn {
  size_t vertices;
  std::vector<uint32_t> triangles;
};

Sewn sewnGarment(const std::string& type) {
  Garment garment = makeParametricGarment(type, mannequin());
  garment.targetEdgeLength = 0.04f;
  const GarmentMesh mesh = buildGarmentMesh(garment);
  const SeamWeld weld = computeSeamWeld(mesh.vertexCount(), mesh.seamPairs);
  return {weld.newVertexCount(), weldTriangles(weld, mesh.triangles)};
}

TEST(BoundaryLoops, SquareHasOneRimInOrderAndAClosedTetrahedronNone) {
  // 3---2
  // | / |
  // 0---1
  const std::vector<uint32_t> square = {0, 1, 2, 0, 2, 3};
  const auto loops = boundaryLoops(4, square);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0], (std::vector<uint32_t>{0, 3, 2, 1}));  // clockwise: the face is on its right
  const std::vector<uint32_t> tetrahedron = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
  EXPECT_TRUE(boundaryLoops(4, tetrahedron).empty());
}

TEST(BoundaryLoops, AnEdgeInThreeTrianglesIsRefused) {
  const std::vector<uint32_t> fin = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  EXPECT_THROW(boundaryLoops(5, fin), Error);
  EXPECT_THROW(boundaryLoops(2, {0, 1, 2}), Error);  // a vertex out of range
}

TEST(GarmentTopology, PanelsBeforeSewingAreOneRimEach) {
  Garment shirt = makeParametricGarment("tshirt", mannequin());
  shirt.targetEdgeLength = 0.04f;
  const GarmentMesh mesh = buildGarmentMesh(shirt);
  EXPECT_EQ(boundaryLoops(mesh.vertexCount(), mesh.triangles).size(), shirt.panels.size());
}

TEST(GarmentTopology, SewnTShirtHasNeckHemAndTwoCuffs) {
  const Sewn shirt = sewnGarment("tshirt");
  EXPECT_EQ(boundaryLoops(shirt.vertices, shirt.triangles).size(), 4u);
  const MeshTopologyReport report = checkTopology(shirt.vertices, shirt.triangles);
  EXPECT_EQ(report.components, 1u);
  EXPECT_EQ(report.misorientedEdges, 0u);
}

TEST(GarmentTopology, SewnSkirtHasWaistAndHem) {
  const Sewn skirt = sewnGarment("skirt");
  EXPECT_EQ(boundaryLoops(skirt.vertices, skirt.triangles).size(), 2u);
  EXPECT_EQ(checkTopology(skirt.vertices, skirt.triangles).components, 1u);
}

TEST(GarmentTopology, SewnTrousersHaveWaistAndTwoLegHems) {
  const Sewn trousers = sewnGarment("trousers");
  EXPECT_EQ(boundaryLoops(trousers.vertices, trousers.triangles).size(), 3u);
  EXPECT_EQ(checkTopology(trousers.vertices, trousers.triangles).components, 1u);
}

}  // namespace
}  // namespace mq
