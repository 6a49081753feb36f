#include "core/io/gltf_materials.h"

#include <filesystem>

namespace mq::gltf {
namespace {

using nlohmann::json;

TextureWrap wrapOf(int glEnum) {
  switch (glEnum) {
    case 33071:
      return TextureWrap::ClampToEdge;
    case 33648:
      return TextureWrap::MirroredRepeat;
    default:
      return TextureWrap::Repeat;  // 10497, and the spec's default
  }
}

TextureSampler readSampler(const json& s) {
  TextureSampler sampler;
  sampler.wrapS = wrapOf(s.value("wrapS", 10497));
  sampler.wrapT = wrapOf(s.value("wrapT", 10497));
  sampler.linear = s.value("magFilter", 9729) != 9728;
  const int minFilter = s.value("minFilter", 9987);
  sampler.mipmaps = minFilter != 9728 && minFilter != 9729;
  return sampler;
}

glm::vec2 readVec2(const json& j, const char* key, glm::vec2 fallback) {
  if (!j.contains(key)) return fallback;
  const auto v = j[key].get<std::vector<float>>();
  return v.size() == 2 ? glm::vec2(v[0], v[1]) : fallback;
}

// A textureInfo object ({"index", "texCoord", "extensions"}); `role` names
// the slot in messages.
TextureRef readTextureInfo(const Document& doc, const json& info, Character& character, const std::string& role) {
  TextureRef ref;
  const int index = info.at("index").get<int>();
  const json& texture = doc.element("textures", index);
  ref.texCoord = info.value("texCoord", 0);
  if (texture.contains("sampler")) ref.sampler = readSampler(doc.element("samplers", texture["sampler"].get<int>()));
  if (info.contains("extensions") && info["extensions"].contains("KHR_texture_transform")) {
    const json& t = info["extensions"]["KHR_texture_transform"];
    ref.transform.offset = readVec2(t, "offset", glm::vec2(0.0f));
    ref.transform.rotation = t.value("rotation", 0.0f);
    ref.transform.scale = readVec2(t, "scale", glm::vec2(1.0f));
    ref.texCoord = t.value("texCoord", ref.texCoord);
  }
  if (ref.texCoord < 0 || ref.texCoord > 1) {
    character.loadWarnings.push_back(doc.path() + ": " + role + " texture uses texture coordinate set " +
                                     std::to_string(ref.texCoord) + "; only sets 0 and 1 are read, it is ignored");
    return TextureRef{};
  }
  if (!texture.contains("source")) {
    character.loadWarnings.push_back(doc.path() + ": texture " + std::to_string(index) +
                                     " has no PNG or JPEG source (an extension's image format?); " + role +
                                     " falls back to its factors");
    return TextureRef{};
  }
  ref.image = texture["source"].get<int>();
  doc.element("images", ref.image);  // fails clearly when absent
  return ref;
}

void readTextureSlot(const Document& doc, const json& owner, const char* key, TextureRef& ref, Character& character,
                     const std::string& materialName) {
  if (owner.contains(key)) ref = readTextureInfo(doc, owner[key], character, "material '" + materialName + "' " + key);
}

glm::vec4 readColor4(const json& j, const char* key, glm::vec4 fallback) {
  if (!j.contains(key)) return fallback;
  const auto v = j[key].get<std::vector<float>>();
  return v.size() == 4 ? glm::vec4(v[0], v[1], v[2], v[3]) : fallback;
}

Material readMaterial(const Document& doc, const json& m, int index, Character& character) {
  Material material;
  material.name = m.value("name", "material" + std::to_string(index));
  if (m.contains("pbrMetallicRoughness")) {
    const json& pbr = m["pbrMetallicRoughness"];
    material.baseColorFactor = readColor4(pbr, "baseColorFactor", material.baseColorFactor);
    material.metallicFactor = pbr.value("metallicFactor", 1.0f);
    material.roughnessFactor = pbr.value("roughnessFactor", 1.0f);
    readTextureSlot(doc, pbr, "baseColorTexture", material.baseColorTexture, character, material.name);
    readTextureSlot(doc, pbr, "metallicRoughnessTexture", material.metallicRoughnessTexture, character, material.name);
  }
  readTextureSlot(doc, m, "normalTexture", material.normalTexture, character, material.name);
  if (m.contains("normalTexture")) material.normalScale = m["normalTexture"].value("scale", 1.0f);
  readTextureSlot(doc, m, "occlusionTexture", material.occlusionTexture, character, material.name);
  if (m.contains("occlusionTexture")) material.occlusionStrength = m["occlusionTexture"].value("strength", 1.0f);
  readTextureSlot(doc, m, "emissiveTexture", material.emissiveTexture, character, material.name);
  if (m.contains("emissiveFactor")) {
    const auto e = m["emissiveFactor"].get<std::vector<float>>();
    if (e.size() == 3) material.emissiveFactor = {e[0], e[1], e[2]};
  }
  if (m.contains("extensions") && m["extensions"].contains("KHR_materials_emissive_strength"))
    material.emissiveStrength = m["extensions"]["KHR_materials_emissive_strength"].value("emissiveStrength", 1.0f);
  const std::string alphaMode = m.value("alphaMode", std::string("OPAQUE"));
  if (!parseAlphaMode(alphaMode, material.alphaMode))
    doc.fail("material '" + material.name + "' has an unknown alphaMode '" + alphaMode + "'");
  material.alphaCutoff = m.value("alphaCutoff", 0.5f);
  material.doubleSided = m.value("doubleSided", false);
  // Our own export marks the surfaces it shaded as skin.
  if (m.contains("extras") && m["extras"].is_object()) {
    const json& flag = m["extras"].value("mannequin_skin", json());
    material.skin = flag.is_boolean() && flag.get<bool>();
  }
  return material;
}

ImageSource readImage(const Document& doc, const json& image, int index, Character& character) {
  ImageSource source;
  source.mimeType = image.value("mimeType", std::string());
  if (image.contains("uri")) {
    const std::string uri = image["uri"].get<std::string>();
    if (uri.rfind("data:", 0) == 0) {
      source.name = image.value("name", "image " + std::to_string(index) + " (data URI)");
      source.encoded = doc.dataUriBytes(uri);
      if (source.mimeType.empty()) source.mimeType = uri.substr(5, uri.find_first_of(";,") - 5);
    } else {
      source.name = uri;
      source.path = doc.resolveUri(uri);
      std::error_code ec;
      if (!std::filesystem::is_regular_file(source.path, ec))
        character.loadWarnings.push_back(doc.path() + ": image '" + uri + "' not found (" + source.path +
                                         "); its materials fall back to their factors");
    }
  } else if (image.contains("bufferView")) {
    source.name = image.value("name", "image " + std::to_string(index));
    source.encoded = doc.bufferViewBytes(image["bufferView"].get<int>());
  } else {
    doc.fail("image " + std::to_string(index) + " has neither a uri nor a bufferView");
  }
  return source;
}

}  // namespace

void readMaterials(const Document& doc, Character& character) {
  const json& j = doc.json();
  const json images = j.value("images", json::array());
  for (size_t i = 0; i < images.size(); ++i)
    character.images.push_back(readImage(doc, images[i], static_cast<int>(i), character));
  const json materials = j.value("materials", json::array());
  for (size_t i = 0; i < materials.size(); ++i)
    character.materials.push_back(readMaterial(doc, materials[i], static_cast<int>(i), character));
}

}  // namespace mq::gltf
