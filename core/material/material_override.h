#pragma once
// A user's changes to one of a file's materials, as the scene document
// stores them: only the fields the user changed, so the source file is never
// modified and a re-exported source keeps everything the user left alone.
//
//   "materials": { "<material name>": { "base_color": [r, g, b, a],  (linear)
//       "metallic": m, "roughness": r, "normal_scale": s, "occlusion_strength": o,
//       "emissive": [r, g, b], "emissive_strength": e, "alpha_mode": "MASK",
//       "alpha_cutoff": c, "double_sided": true, "skin": true } }

#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/material/material.h"

namespace mq {

struct MaterialOverride {
  std::optional<glm::vec4> baseColor;
  std::optional<float> metallic;
  std::optional<float> roughness;
  std::optional<float> normalScale;
  std::optional<float> occlusionStrength;
  std::optional<glm::vec3> emissive;
  std::optional<float> emissiveStrength;
  std::optional<AlphaMode> alphaMode;
  std::optional<float> alphaCutoff;
  std::optional<bool> doubleSided;
  std::optional<bool> skin;

  bool empty() const;
  void applyTo(Material& material) const;
  // The fields in which `edited` differs from `original`.
  static MaterialOverride between(const Material& original, const Material& edited);

  nlohmann::json toJson() const;
  // Throws mq::Error naming the field (prefixed with `where`) when a value is
  // of the wrong type or out of range.
  static MaterialOverride fromJson(const nlohmann::json& j, const std::string& where);
};

}  // namespace mq
