#pragma once
// JSON (de)serialisation of garments for the scene document's "garments"
// section (an array of garment objects):
//   { "name": "T-shirt", "fabric": "cotton", "targetEdgeLength": 0.02,
//     "recipe": { "type": "tshirt", "parameters": { "length": 0.66, ... } },
//     "panels": [ { "name": "front", "corners": [[u, v], ...],
//                   "edges": [ { "name": "hem", "shape": "line" },
//                              { "name": "neck", "shape": "cubic", "controls": [[u, v], [u, v]] }, ... ],
//                   "placement": { "shape": "cylinder", "bone": "spine", "center": [x, y, z],
//                                  "axis": [x, y, z], "facing": [x, y, z], "radius": 0.2,
//                                  "anchor": [u, v] } }, ... ],
//     "seams": [ { "a": ["front", "side_l"], "b": ["back", "side_l"], "reversed": true }, ... ] }
// Pattern coordinates are metres. "recipe" is optional (hand-made panels).
// "fabric" is a preset name or an object of its own values (core/garment/
// fabric_json.h): {"preset": "cotton", "mass_per_area": .., "stretch": .., "shear": ..,
// "bend": .., "damping": .., "friction": .., "thickness": ..}.
// Optional "pins": {"vertices": [garment-mesh vertex indices], "attach": "body" | "space"}
// (body: each follows its nearest body vertex; space: fixed where it starts).
// Optional "layer": an integer 0..99 (0 when absent): garments are worn over
// those of lower layers and over those earlier in the list on the same layer.

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/garment/garment.h"

namespace mq {

nlohmann::json garmentToJson(const Garment& garment);
nlohmann::json garmentsToJson(const std::vector<Garment>& garments);

// Throw mq::Error naming the JSON path of the bad value (e.g.
// "garments[0].panels[1].corners[2]: expected [u, v]") and what was expected;
// the result is validated (Garment::validate).
Garment garmentFromJson(const nlohmann::json& json, const std::string& path = "garment");
// A null or missing section gives no garments.
std::vector<Garment> garmentsFromJson(const nlohmann::json& json, const std::string& path = "garments");

}  // namespace mq
