#pragma once
// Surface materials as files describe them: glTF 2.0 metallic-roughness
// (the common ground of glTF, FBX and Collada), with the textures they
// sample. Images stay encoded here; the render layer decodes them.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace mq {

// Where an image's bytes come from: embedded (GLB buffer view, data: URI,
// FBX embedded texture) or a file beside the model.
struct ImageSource {
  std::string name;              // for messages: the URI, file name or "image N"
  std::string path;              // absolute path of an external file, or empty
  std::vector<uint8_t> encoded;  // embedded PNG/JPEG bytes, or empty
  std::string mimeType;          // "image/png", "image/jpeg" or empty (guess)
};

enum class TextureWrap : uint8_t { Repeat, ClampToEdge, MirroredRepeat };

struct TextureSampler {
  TextureWrap wrapS = TextureWrap::Repeat;
  TextureWrap wrapT = TextureWrap::Repeat;
  bool linear = true;   // magnification filter (false: nearest)
  bool mipmaps = true;  // minification filter uses mipmaps
};

// KHR_texture_transform: uv' = T(offset) * R(rotation) * S(scale) * uv.
struct TextureTransform {
  glm::vec2 offset{0.0f};
  float rotation = 0.0f;  // radians, counter-clockwise in uv space
  glm::vec2 scale{1.0f};
  bool identity() const { return offset == glm::vec2(0.0f) && rotation == 0.0f && scale == glm::vec2(1.0f); }
  glm::vec2 apply(const glm::vec2& uv) const;
};

struct TextureRef {
  int image = -1;    // index into Character::images; -1 = no texture
  int texCoord = 0;  // which uv set (0 or 1)
  TextureSampler sampler;
  TextureTransform transform;
  bool present() const { return image >= 0; }
};

enum class AlphaMode : uint8_t { Opaque, Mask, Blend };

// One texture of a material with its role: `key` as in JSON output
// ("base_color"), `label` for people ("base colour").
struct TextureSlot {
  const char* key;
  const char* label;
  const TextureRef* ref;
};

struct Material {
  std::string name;
  glm::vec4 baseColorFactor{1.0f};  // linear RGBA
  TextureRef baseColorTexture;      // sRGB
  float metallicFactor = 1.0f;
  float roughnessFactor = 1.0f;
  TextureRef metallicRoughnessTexture;  // G roughness, B metallic (linear)
  TextureRef normalTexture;
  float normalScale = 1.0f;
  TextureRef occlusionTexture;  // R channel
  float occlusionStrength = 1.0f;
  glm::vec3 emissiveFactor{0.0f};
  float emissiveStrength = 1.0f;  // KHR_materials_emissive_strength
  TextureRef emissiveTexture;     // sRGB
  TextureRef specularTexture;     // FBX/Collada specular map (not in glTF core)
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
  bool skin = false;  // shaded by the skin model, base colour as albedo

  bool textured() const;
  // Every texture reference with its role, for code that walks them all.
  std::vector<TextureSlot> textureSlots() const;
};

const char* alphaModeName(AlphaMode mode);
// "OPAQUE", "MASK" or "BLEND" (glTF spelling, any case); false if unknown.
bool parseAlphaMode(const std::string& text, AlphaMode& mode);

// sRGB <-> linear for one channel (the base colour factor is linear, a user
// picks colours in sRGB).
float srgbToLinear(float c);
float linearToSrgb(float c);

}  // namespace mq
