#include "core/garment/fabric_json.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/util/error.h"

namespace mq {

namespace {

using nlohmann::json;

std::string presetList() {
  std::string names;
  for (const std::string& n : fabricPresetNames()) names += (names.empty() ? "" : ", ") + n;
  return "(known: " + names + ")";
}

std::string presetFrom(const json& name, const std::string& path) {
  if (!name.is_string()) throw Error(path + ": must be a preset name " + presetList());
  const std::string preset = name.get<std::string>();
  if (!hasFabricPreset(preset)) throw Error(path + ": unknown fabric preset '" + preset + "' " + presetList());
  return preset;
}

// Reads o[key] into `value` when present: a finite number, > 0 or >= 0.
void readValue(const json& o, const std::string& path, const char* key, bool positive, float& value) {
  auto it = o.find(key);
  if (it == o.end() || it->is_null()) return;
  const std::string at = path + "." + key;
  if (!it->is_number()) throw Error(at + ": must be a number");
  const double d = it->get<double>();
  if (!std::isfinite(d) || std::abs(d) > 3.0e38) throw Error(at + ": must be a finite number");
  if (positive && !(d > 0.0)) throw Error(at + ": must be positive");
  if (!positive && d < 0.0) throw Error(at + ": must not be negative");
  value = float(d);
}

}  // namespace

Fabric fabricFromJson(const json& j, const std::string& path, std::string& preset) {
  if (j.is_string()) {
    preset = presetFrom(j, path);
    return fabricPreset(preset);
  }
  if (!j.is_object()) throw Error(path + ": must be a preset name or an object");
  Fabric fabric;
  preset.clear();
  auto it = j.find("preset");
  if (it != j.end() && !it->is_null() && !(it->is_string() && it->get<std::string>().empty())) {
    preset = presetFrom(*it, path + ".preset");
    fabric = fabricPreset(preset);
  }
  for (auto entry = j.begin(); entry != j.end(); ++entry) {
    static const char* known[] = {"preset", "mass_per_area", "stretch",  "shear",
                                  "bend",   "damping",       "friction", "thickness"};
    bool isKnown = false;
    for (const char* k : known) isKnown = isKnown || entry.key() == k;
    if (!isKnown) throw Error(path + "." + entry.key() + ": unknown fabric key");
  }
  readValue(j, path, "mass_per_area", true, fabric.massPerArea);
  readValue(j, path, "stretch", true, fabric.stretchStiffness);
  readValue(j, path, "shear", false, fabric.shearStiffness);
  readValue(j, path, "bend", false, fabric.bendStiffness);
  readValue(j, path, "damping", false, fabric.damping);
  readValue(j, path, "friction", false, fabric.friction);
  readValue(j, path, "thickness", false, fabric.thickness);
  if (preset.empty()) fabric.name = "custom";
  try {
    fabric.validate();
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
  return fabric;
}

json fabricToJson(const Fabric& f, const std::string& preset) {
  json out = {{"mass_per_area", f.massPerArea}, {"stretch", f.stretchStiffness}, {"shear", f.shearStiffness},
              {"bend", f.bendStiffness},        {"damping", f.damping},          {"friction", f.friction},
              {"thickness", f.thickness}};
  if (!preset.empty()) out["preset"] = preset;
  return out;
}

bool sameFabricValues(const Fabric& a, const Fabric& b) {
  return a.massPerArea == b.massPerArea && a.stretchStiffness == b.stretchStiffness &&
         a.shearStiffness == b.shearStiffness && a.bendStiffness == b.bendStiffness && a.damping == b.damping &&
         a.friction == b.friction && a.thickness == b.thickness;
}

}  // namespace mq
