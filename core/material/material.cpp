#include "core/material/material.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace mq {

glm::vec2 TextureTransform::apply(const glm::vec2& uv) const {
  const float c = std::cos(rotation), s = std::sin(rotation);
  const glm::vec2 scaled = uv * scale;
  // The extension's matrix: rotation by -rotation in its row-major layout,
  // i.e. [c s; -s c] applied to the column (u, v).
  return offset + glm::vec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y);
}

bool Material::textured() const {
  for (const TextureSlot& slot : textureSlots())
    if (slot.ref->present()) return true;
  return false;
}

std::vector<TextureSlot> Material::textureSlots() const {
  return {{"base_color", "base colour", &baseColorTexture},
          {"metallic_roughness", "metallic-roughness", &metallicRoughnessTexture},
          {"normal", "normal", &normalTexture},
          {"occlusion", "occlusion", &occlusionTexture},
          {"emissive", "emissive", &emissiveTexture},
          {"specular", "specular", &specularTexture}};
}

const char* alphaModeName(AlphaMode mode) {
  switch (mode) {
    case AlphaMode::Mask:
      return "MASK";
    case AlphaMode::Blend:
      return "BLEND";
    case AlphaMode::Opaque:
      break;
  }
  return "OPAQUE";
}

bool parseAlphaMode(const std::string& text, AlphaMode& mode) {
  std::string upper = text;
  std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
  for (AlphaMode m : {AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend})
    if (upper == alphaModeName(m)) {
      mode = m;
      return true;
    }
  return false;
}

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

float linearToSrgb(float c) { return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

}  // namespace mq
