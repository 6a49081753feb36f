#include "core/io/gltf_material_export.h"

#include "core/io/file_bytes.h"
#include "core/util/error.h"

namespace mq {
namespace {

using nlohmann::json;

int wrapEnum(TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::ClampToEdge:
      return 33071;
    case TextureWrap::MirroredRepeat:
      return 33648;
    default:
      return 10497;
  }
}

std::string guessMimeType(const std::vector<uint8_t>& bytes) {
  if (bytes.size() >= 4 && bytes[0] == 0x89 && bytes[1] == 'P' && bytes[2] == 'N' && bytes[3] == 'G')
    return "image/png";
  if (bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) return "image/jpeg";
  return "";
}

// The image's bytes embedded as a bufferView; -1 (with a warning) when they
// cannot be read or are neither PNG nor JPEG, the two formats glTF allows.
int addImage(GltfWriter& writer, const ImageSource& image, std::vector<std::string>& warnings) {
  std::vector<uint8_t> bytes = image.encoded;
  if (bytes.empty() && !image.path.empty()) {
    try {
      bytes = readFileBytes(image.path);
    } catch (const Error& e) {
      warnings.push_back("image '" + image.name + "' left out: " + e.what());
      return -1;
    }
  }
  const std::string mimeType = guessMimeType(bytes);
  if (mimeType.empty()) {
    warnings.push_back("image '" + image.name + "' left out: not a PNG or JPEG image");
    return -1;
  }
  const int view = writer.addBufferView(bytes.data(), bytes.size());
  json& images = writer.json()["images"];
  images.push_back({{"name", image.name}, {"bufferView", view}, {"mimeType", mimeType}});
  return static_cast<int>(images.size()) - 1;
}

int addSampler(GltfWriter& writer, const TextureSampler& sampler) {
  const int minFilter = sampler.linear ? (sampler.mipmaps ? 9987 : 9729) : (sampler.mipmaps ? 9984 : 9728);
  const json s = {{"wrapS", wrapEnum(sampler.wrapS)},
                  {"wrapT", wrapEnum(sampler.wrapT)},
                  {"magFilter", sampler.linear ? 9729 : 9728},
                  {"minFilter", minFilter}};
  json& samplers = writer.json()["samplers"];
  for (size_t i = 0; i < samplers.size(); ++i)
    if (samplers[i] == s) return static_cast<int>(i);
  samplers.push_back(s);
  return static_cast<int>(samplers.size()) - 1;
}

// A textureInfo for `ref`, or null when its image was not embedded.
json textureInfo(GltfWriter& writer, const TextureRef& ref, const std::vector<int>& imageIndex) {
  if (!ref.present() || ref.image >= int(imageIndex.size()) || imageIndex[ref.image] < 0) return nullptr;
  json& textures = writer.json()["textures"];
  textures.push_back({{"source", imageIndex[ref.image]}, {"sampler", addSampler(writer, ref.sampler)}});
  json info = {{"index", textures.size() - 1}};
  if (ref.texCoord != 0) info["texCoord"] = ref.texCoord;
  if (!ref.transform.identity()) {
    writer.useExtension("KHR_texture_transform");
    const TextureTransform& t = ref.transform;
    info["extensions"]["KHR_texture_transform"] = {
        {"offset", {t.offset.x, t.offset.y}}, {"rotation", t.rotation}, {"scale", {t.scale.x, t.scale.y}}};
  }
  return info;
}

json materialJson(GltfWriter& writer, const Material& m, const std::vector<int>& imageIndex) {
  json pbr = {{"baseColorFactor", {m.baseColorFactor.x, m.baseColorFactor.y, m.baseColorFactor.z, m.baseColorFactor.w}},
              {"metallicFactor", m.metallicFactor},
              {"roughnessFactor", m.roughnessFactor}};
  if (json t = textureInfo(writer, m.baseColorTexture, imageIndex); !t.is_null()) pbr["baseColorTexture"] = t;
  if (json t = textureInfo(writer, m.metallicRoughnessTexture, imageIndex); !t.is_null())
    pbr["metallicRoughnessTexture"] = t;
  json material = {{"name", m.name}, {"pbrMetallicRoughness", pbr}};
  if (json t = textureInfo(writer, m.normalTexture, imageIndex); !t.is_null()) {
    t["scale"] = m.normalScale;
    material["normalTexture"] = t;
  }
  if (json t = textureInfo(writer, m.occlusionTexture, imageIndex); !t.is_null()) {
    t["strength"] = m.occlusionStrength;
    material["occlusionTexture"] = t;
  }
  if (json t = textureInfo(writer, m.emissiveTexture, imageIndex); !t.is_null()) material["emissiveTexture"] = t;
  if (m.emissiveFactor != glm::vec3(0.0f))
    material["emissiveFactor"] = {m.emissiveFactor.x, m.emissiveFactor.y, m.emissiveFactor.z};
  if (m.emissiveStrength != 1.0f) {
    writer.useExtension("KHR_materials_emissive_strength");
    material["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", m.emissiveStrength}};
  }
  if (m.alphaMode != AlphaMode::Opaque) material["alphaMode"] = alphaModeName(m.alphaMode);
  if (m.alphaMode == AlphaMode::Mask) material["alphaCutoff"] = m.alphaCutoff;
  if (m.doubleSided) material["doubleSided"] = true;
  if (m.skin) material["extras"] = {{"mannequin_skin", true}};  // our skin shading, kept for a round trip
  return material;
}

}  // namespace

std::vector<std::string> addGltfMaterials(GltfWriter& writer, const Character& character) {
  std::vector<std::string> warnings;
  if (character.materials.empty()) return warnings;
  std::vector<int> imageIndex;
  for (const ImageSource& image : character.images) imageIndex.push_back(addImage(writer, image, warnings));
  json& materials = writer.json()["materials"];
  for (const Material& m : character.materials) materials.push_back(materialJson(writer, m, imageIndex));
  return warnings;
}

json gltfPrimitives(GltfWriter& writer, const Mesh& mesh, const json& attributes, size_t materialCount) {
  json primitives = json::array();
  for (const Submesh& range : mesh.drawRanges()) {
    json primitive = {{"attributes", attributes}, {"mode", 4}};
    if (range.triangleCount > 0)
      primitive["indices"] =
          writer.addAccessor(mesh.triangles.data() + 3 * size_t(range.firstTriangle), 3 * size_t(range.triangleCount),
                             "SCALAR", 1, GltfWriter::kUnsignedInt, GltfWriter::kElementArrayBuffer);
    if (range.material >= 0 && size_t(range.material) < materialCount) primitive["material"] = range.material;
    primitives.push_back(primitive);
  }
  return primitives;
}

}  // namespace mq
