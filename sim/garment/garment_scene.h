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

}  // namespace mq::cloth
