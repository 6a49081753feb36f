#include "core/material/material_override.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <nlohmann/json.hpp>

#include "core/util/error.h"

namespace mq {
namespace {

using nlohmann::json;

float readNumber(const json& j, const char* key, const std::string& where, float min, float max) {
  const json& v = j[key];
  if (!v.is_number()) throw Error(where + "." + key + " must be a number");
  const float x = v.get<float>();
  if (!std::isfinite(x) || x < min || x > max)
    throw Error(where + "." + key + " must be between " + std::to_string(min) + " and " + std::to_string(max));
  return x;
}

template <int N>
glm::vec<N, float> readVector(const json& j, const char* key, const std::string& where, float max) {
  const json& v = j[key];
  if (!v.is_array() || v.size() != N)
    throw Error(where + "." + key + " must be an array of " + std::to_string(N) + " numbers");
  glm::vec<N, float> out;
  for (int i = 0; i < N; ++i) {
    if (!v[i].is_number() || !std::isfinite(v[i].get<float>()) || v[i].get<float>() < 0.0f || v[i].get<float>() > max)
      throw Error(where + "." + key + " holds a value outside 0.." + std::to_string(max));
    out[i] = v[i].get<float>();
  }
  return out;
}

bool readBool(const json& j, const char* key, const std::string& where) {
  if (!j[key].is_boolean()) throw Error(where + "." + key + " must be true or false");
  return j[key].get<bool>();
}

template <typename T>
void setIfDifferent(std::optional<T>& field, const T& original, const T& edited) {
  if (!(original == edited)) field = edited;
}

}  // namespace

bool MaterialOverride::empty() const {
  return !baseColor && !metallic && !roughness && !normalScale && !occlusionStrength && !emissive &&
         !emissiveStrength && !alphaMode && !alphaCutoff && !doubleSided && !skin;
}

void MaterialOverride::applyTo(Material& m) const {
  if (baseColor) m.baseColorFactor = *baseColor;
  if (metallic) m.metallicFactor = *metallic;
  if (roughness) m.roughnessFactor = *roughness;
  if (normalScale) m.normalScale = *normalScale;
  if (occlusionStrength) m.occlusionStrength = *occlusionStrength;
  if (emissive) m.emissiveFactor = *emissive;
  if (emissiveStrength) m.emissiveStrength = *emissiveStrength;
  if (alphaMode) m.alphaMode = *alphaMode;
  if (alphaCutoff) m.alphaCutoff = *alphaCutoff;
  if (doubleSided) m.doubleSided = *doubleSided;
  if (skin) m.skin = *skin;
}

MaterialOverride MaterialOverride::between(const Material& original, const Material& edited) {
  MaterialOverride o;
  setIfDifferent(o.baseColor, original.baseColorFactor, edited.baseColorFactor);
  setIfDifferent(o.metallic, original.metallicFactor, edited.metallicFactor);
  setIfDifferent(o.roughness, original.roughnessFactor, edited.roughnessFactor);
  setIfDifferent(o.normalScale, original.normalScale, edited.normalScale);
  setIfDifferent(o.occlusionStrength, original.occlusionStrength, edited.occlusionStrength);
  setIfDifferent(o.emissive, original.emissiveFactor, edited.emissiveFactor);
  setIfDifferent(o.emissiveStrength, original.emissiveStrength, edited.emissiveStrength);
  setIfDifferent(o.alphaMode, original.alphaMode, edited.alphaMode);
  setIfDifferent(o.alphaCutoff, original.alphaCutoff, edited.alphaCutoff);
  setIfDifferent(o.doubleSided, original.doubleSided, edited.doubleSided);
  setIfDifferent(o.skin, original.skin, edited.skin);
  return o;
}

json MaterialOverride::toJson() const {
  json j = json::object();
  if (baseColor) j["base_color"] = {baseColor->x, baseColor->y, baseColor->z, baseColor->w};
  if (metallic) j["metallic"] = *metallic;
  if (roughness) j["roughness"] = *roughness;
  if (normalScale) j["normal_scale"] = *normalScale;
  if (occlusionStrength) j["occlusion_strength"] = *occlusionStrength;
  if (emissive) j["emissive"] = {emissive->x, emissive->y, emissive->z};
  if (emissiveStrength) j["emissive_strength"] = *emissiveStrength;
  if (alphaMode) j["alpha_mode"] = alphaModeName(*alphaMode);
  if (alphaCutoff) j["alpha_cutoff"] = *alphaCutoff;
  if (doubleSided) j["double_sided"] = *doubleSided;
  if (skin) j["skin"] = *skin;
  return j;
}

MaterialOverride MaterialOverride::fromJson(const json& j, const std::string& where) {
  if (!j.is_object()) throw Error(where + " must be an object");
  static const char* known[] = {"base_color", "metallic",          "roughness",  "normal_scale", "occlusion_strength",
                                "emissive",   "emissive_strength", "alpha_mode", "alpha_cutoff", "double_sided",
                                "skin"};
  for (const auto& [key, value] : j.items())
    if (std::find(std::begin(known), std::end(known), key) == std::end(known))
      throw Error(where + ": unknown field '" + key + "'");
  MaterialOverride o;
  if (j.contains("base_color")) o.baseColor = readVector<4>(j, "base_color", where, 1.0f);
  if (j.contains("metallic")) o.metallic = readNumber(j, "metallic", where, 0.0f, 1.0f);
  if (j.contains("roughness")) o.roughness = readNumber(j, "roughness", where, 0.0f, 1.0f);
  if (j.contains("normal_scale")) o.normalScale = readNumber(j, "normal_scale", where, 0.0f, 10.0f);
  if (j.contains("occlusion_strength")) o.occlusionStrength = readNumber(j, "occlusion_strength", where, 0.0f, 1.0f);
  if (j.contains("emissive")) o.emissive = readVector<3>(j, "emissive", where, 1.0f);
  if (j.contains("emissive_strength")) o.emissiveStrength = readNumber(j, "emissive_strength", where, 0.0f, 1000.0f);
  if (j.contains("alpha_mode")) {
    AlphaMode mode = AlphaMode::Opaque;
    if (!j["alpha_mode"].is_string() || !parseAlphaMode(j["alpha_mode"].get<std::string>(), mode))
      throw Error(where + ".alpha_mode must be \"OPAQUE\", \"MASK\" or \"BLEND\"");
    o.alphaMode = mode;
  }
  if (j.contains("alpha_cutoff")) o.alphaCutoff = readNumber(j, "alpha_cutoff", where, 0.0f, 1.0f);
  if (j.contains("double_sided")) o.doubleSided = readBool(j, "double_sided", where);
  if (j.contains("skin")) o.skin = readBool(j, "skin", where);
  return o;
}

}  // namespace mq
