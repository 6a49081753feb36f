#pragma once
// The fabric of a scene document, shared by the "cloth" section (sheets) and
// every garment of the "garments" section:
//   "fabric": "cotton"
//   "fabric": {"preset": "cotton", "mass_per_area": 0.12, "stretch": 1e4, "shear": 50,
//              "bend": 1e-5, "damping": 0.02, "friction": 0.3, "thickness": 5e-4}
// In the object form every key is optional: values not given are the
// preset's ("preset" absent: the defaults of a custom Fabric).

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/garment/fabric.h"

namespace mq {

// Throws mq::Error "<jsonPath>[.<key>]: <problem>" (unknown preset, a value
// that is not a finite number or out of range). `preset` gets the preset
// name the fabric started from ("" = custom).
Fabric fabricFromJson(const nlohmann::json& json, const std::string& jsonPath, std::string& preset);
// The object form with every value (and "preset" unless it is "").
nlohmann::json fabricToJson(const Fabric& fabric, const std::string& preset);
bool sameFabricValues(const Fabric& a, const Fabric& b);

}  // namespace mq
