#include "core/io/gltf_material_export.h"

#include <initializer_list>
#include <utility>

#include "core/io/file_bytes.h"
#include "core/util/error.h"

namespace mq {
namespace {

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
  tinygltf::Image gltfImage;
  gltfImage.name = image.name;
  gltfImage.bufferView = writer.addBufferView(bytes.data(), bytes.size());
  gltfImage.mimeType = mimeType;
  writer.model().images.push_back(std::move(gltfImage));
  return int(writer.model().images.size()) - 1;
}

bool sameSampler(const tinygltf::Sampler& a, const tinygltf::Sampler& b) {
  return a.wrapS == b.wrapS && a.wrapT == b.wrapT && a.magFilter == b.magFilter && a.minFilter == b.minFilter;
}

int addSampler(GltfWriter& writer, const TextureSampler& sampler) {
  tinygltf::Sampler s;
  s.wrapS = wrapEnum(sampler.wrapS);
  s.wrapT = wrapEnum(sampler.wrapT);
  s.magFilter = sampler.linear ? TINYGLTF_TEXTURE_FILTER_LINEAR : TINYGLTF_TEXTURE_FILTER_NEAREST;
  s.minFilter =
      sampler.linear
          ? (sampler.mipmaps ? TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR : TINYGLTF_TEXTURE_FILTER_LINEAR)
          : (sampler.mipmaps ? TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST : TINYGLTF_TEXTURE_FILTER_NEAREST);
  std::vector<tinygltf::Sampler>& samplers = writer.model().samplers;
  for (size_t i = 0; i < samplers.size(); ++i)
    if (sameSampler(samplers[i], s)) return int(i);
  samplers.push_back(s);
  return int(samplers.size()) - 1;
}

tinygltf::Value numbers(std::initializer_list<float> values) {
  tinygltf::Value::Array array;
  for (float v : values) array.emplace_back(double(v));
  return tinygltf::Value(std::move(array));
}

// Fills a textureInfo (its index, texture coordinate set and transform) for
// `ref`; false, leaving it unset, when its image was not embedded.
template <typename Info>
bool fillTextureInfo(GltfWriter& writer, const TextureRef& ref, const std::vector<int>& imageIndex, Info& info) {
  if (!ref.present() || ref.image >= int(imageIndex.size()) || imageIndex[ref.image] < 0) return false;
  tinygltf::Texture texture;
  texture.source = imageIndex[ref.image];
  texture.sampler = addSampler(writer, ref.sampler);
  writer.model().textures.push_back(texture);
  info.index = int(writer.model().textures.size()) - 1;
  info.texCoord = ref.texCoord;
  if (!ref.transform.identity()) {
    writer.useExtension("KHR_texture_transform");
    const TextureTransform& t = ref.transform;
    info.extensions["KHR_texture_transform"] =
        tinygltf::Value(tinygltf::Value::Object{{"offset", numbers({t.offset.x, t.offset.y})},
                                                {"rotation", tinygltf::Value(double(t.rotation))},
                                                {"scale", numbers({t.scale.x, t.scale.y})}});
  }
  return true;
}

tinygltf::Material gltfMaterial(GltfWriter& writer, const Material& m, const std::vector<int>& imageIndex) {
  tinygltf::Material material;
  material.name = m.name;
  tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
  pbr.baseColorFactor = {m.baseColorFactor.x, m.baseColorFactor.y, m.baseColorFactor.z, m.baseColorFactor.w};
  pbr.metallicFactor = m.metallicFactor;
  pbr.roughnessFactor = m.roughnessFactor;
  fillTextureInfo(writer, m.baseColorTexture, imageIndex, pbr.baseColorTexture);
  fillTextureInfo(writer, m.metallicRoughnessTexture, imageIndex, pbr.metallicRoughnessTexture);
  if (fillTextureInfo(writer, m.normalTexture, imageIndex, material.normalTexture))
    material.normalTexture.scale = m.normalScale;
  if (fillTextureInfo(writer, m.occlusionTexture, imageIndex, material.occlusionTexture))
    material.occlusionTexture.strength = m.occlusionStrength;
  fillTextureInfo(writer, m.emissiveTexture, imageIndex, material.emissiveTexture);
  material.emissiveFactor = {m.emissiveFactor.x, m.emissiveFactor.y, m.emissiveFactor.z};
  if (m.emissiveStrength != 1.0f) {
    writer.useExtension("KHR_materials_emissive_strength");
    material.extensions["KHR_materials_emissive_strength"] =
        tinygltf::Value(tinygltf::Value::Object{{"emissiveStrength", tinygltf::Value(double(m.emissiveStrength))}});
  }
  material.alphaMode = alphaModeName(m.alphaMode);
  material.alphaCutoff = m.alphaMode == AlphaMode::Mask ? m.alphaCutoff : 0.5;  // 0.5: left out
  material.doubleSided = m.doubleSided;
  if (m.skin)  // our skin shading, kept for a round trip
    material.extras = tinygltf::Value(tinygltf::Value::Object{{"mannequin_skin", tinygltf::Value(true)}});
  return material;
}

}  // namespace

std::vector<std::string> addGltfMaterials(GltfWriter& writer, const Character& character) {
  std::vector<std::string> warnings;
  if (character.materials.empty()) return warnings;
  std::vector<int> imageIndex;
  for (const ImageSource& image : character.images) imageIndex.push_back(addImage(writer, image, warnings));
  for (const Material& m : character.materials) writer.model().materials.push_back(gltfMaterial(writer, m, imageIndex));
  return warnings;
}

std::vector<tinygltf::Primitive> gltfPrimitives(GltfWriter& writer, const Mesh& mesh,
                                                const std::map<std::string, int>& attributes, size_t materialCount) {
  std::vector<tinygltf::Primitive> primitives;
  for (const Submesh& range : mesh.drawRanges()) {
    tinygltf::Primitive primitive;
    primitive.attributes = attributes;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    if (range.triangleCount > 0)
      primitive.indices =
          writer.addIndices(mesh.triangles.data() + 3 * size_t(range.firstTriangle), 3 * size_t(range.triangleCount));
    if (range.material >= 0 && size_t(range.material) < materialCount) primitive.material = range.material;
    primitives.push_back(std::move(primitive));
  }
  return primitives;
}

}  // namespace mq
