#pragma once
// The garments of a scene document as simulations: each garment's mesh, its
// fabric and pins, the document's solver settings ("cloth" section) and
// primitive colliders, on the character's body.
//
//   std::vector<Garment> garments = garmentsFromJson(document.garments);
//   ClothSceneSpec spec = parseClothScene(document.cloth, document.colliders, path, !garments.empty());
//   auto sim = makeGarmentSimulation(garments[0], spec, bodyPositions, bodyTriangles, "garments[0]");

#include <memory>
#include <string>
#include <vector>

#include "core/garment/garment.h"
#include "sim/cloth/cloth_scene_io.h"
#include "sim/garment/garment_simulation.h"

namespace mq::cloth {

GarmentSimulationSettings garmentSimulationSettings(const Garment& garment, const ClothSceneSpec& spec);

// Throws mq::Error "<jsonPath>.<key>: <problem>" for pins beyond the
// garment's mesh or pinned to a body that is not there, and the mesher's or
// the solver's errors.
std::unique_ptr<GarmentSimulation> makeGarmentSimulation(const Garment& garment, const ClothSceneSpec& spec,
                                                         const std::vector<float>& bodyPositions,
                                                         const std::vector<uint32_t>& bodyTriangles,
                                                         const std::string& jsonPath);

// The "cloth" section's sheet as a garment mesh (one panel, no seams; the
// sheet's row-major vertex order), for tools that show and run sheets and
// garments alike.
GarmentMesh sheetGarmentMesh(const ClothSceneSpec& spec);

// The sheet as a GarmentSimulation (nothing to sew: welded from the start)
// with the section's fabric, pins (fixed in space) and the colliders.
// mass_per_vertex becomes the fabric's mass per area (same total mass).
std::unique_ptr<GarmentSimulation> makeSheetSimulation(const ClothSceneSpec& spec,
                                                       const std::vector<float>& bodyPositions,
                                                       const std::vector<uint32_t>& bodyTriangles);

}  // namespace mq::cloth
