#pragma once
// Sewing a garment with the cloth solver: its panels start apart around the
// body with seams as zero-length springs (ClothMesh::seams) that pull the
// paired edges together during the first frames; once they are closed, the
// seam vertices are welded and the simulation continues on the welded mesh
// with the springs remapped (rest lengths kept from the pattern).
//
//   GarmentMesh garment = buildGarmentMesh(makeParametricGarment("tshirt", body));
//   ClothMesh mesh = clothMeshFromGarment(garment);
//   auto sim = std::make_unique<ClothSimulator>(mesh, fabric, settings);
//   ... step until maxSeamGap(sim->positions(), mesh.seams) is small ...
//   WeldedCloth welded = weldClothSeams(mesh, buildClothTopology(mesh));
//   sim = continueWelded(*sim, welded, fabric);  // then setBody() again

#include <memory>
#include <vector>

#include "core/garment/garment.h"
#include "core/garment/seam_weld.h"
#include "sim/cloth/cloth_simulator.h"

namespace mq::cloth {

// The solver's input for a garment: placed positions, triangles, seam pairs.
ClothMesh clothMeshFromGarment(const GarmentMesh& garment);

// Largest distance between the two vertices of a seam pair (0 without seams).
float maxSeamGap(const std::vector<glm::vec3>& x, const std::vector<std::pair<uint32_t, uint32_t>>& seams);

struct WeldedCloth {
  ClothMesh mesh;          // welded triangles, no seams; positions averaged
  ClothTopology topology;  // springs and bend lines remapped
  SeamWeld weld;           // old vertex -> new vertex
};

// Welds the seam pairs of `mesh`. Springs whose ends merged are dropped;
// springs that became the same (the two panels' edge springs along a seam)
// are merged into one standing for both areas. Rest lengths stay those of
// `topology`, i.e. of the pattern, not of the sewn shape.
WeldedCloth weldClothSeams(const ClothMesh& mesh, const ClothTopology& topology);

// A simulator over the welded cloth that continues `sewing`: positions and
// velocities averaged over each welded group, masses summed, colliders
// copied. The body and pins are not carried over: set them again. The
// welded cloth gets `settings` when given, else the sewing one's.
std::unique_ptr<ClothSimulator> continueWelded(const ClothSimulator& sewing, const WeldedCloth& welded,
                                               const Fabric& fabric, const ClothSettings* settings = nullptr);

}  // namespace mq::cloth
