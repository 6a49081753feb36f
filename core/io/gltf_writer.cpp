#include "core/io/gltf_writer.h"

#include <algorithm>
#include <cstring>

#include "core/mesh/mesh.h"
#include "core/util/error.h"
#include "core/util/utf8.h"

namespace mq {
namespace {

int componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
    case TINYGLTF_TYPE_MAT2:
      return 4;
    case TINYGLTF_TYPE_MAT3:
      return 9;
    default:
      return 16;  // MAT4
  }
}

size_t componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    default:
      return 4;
  }
}

}  // namespace

GltfWriter::GltfWriter(const char* generator) {
  model_.asset.version = "2.0";
  model_.asset.generator = generator;
  model_.scenes.emplace_back();
  model_.defaultScene = 0;
  model_.buffers.emplace_back();
}

int GltfWriter::addAccessor(const void* data, size_t count, int type, int componentType, int target) {
  tinygltf::Accessor accessor;
  accessor.bufferView = addBufferView(data, count * componentCount(type) * componentSize(componentType), target);
  accessor.componentType = componentType;
  accessor.count = count;
  accessor.type = type;
  model_.accessors.push_back(std::move(accessor));
  return int(model_.accessors.size()) - 1;
}

int GltfWriter::addPositionAccessor(const std::vector<float>& positions) {
  const int index = addVertexAttribute(positions, TINYGLTF_TYPE_VEC3);
  const Aabb box = boundsOf(positions);
  model_.accessors[index].minValues = {box.min.x, box.min.y, box.min.z};
  model_.accessors[index].maxValues = {box.max.x, box.max.y, box.max.z};
  return index;
}

int GltfWriter::addVertexAttribute(const std::vector<float>& values, int type) {
  return addAccessor(values.data(), values.size() / componentCount(type), type, TINYGLTF_COMPONENT_TYPE_FLOAT,
                     TINYGLTF_TARGET_ARRAY_BUFFER);
}

int GltfWriter::addIndices(const uint32_t* indices, size_t count) {
  return addAccessor(indices, count, TINYGLTF_TYPE_SCALAR, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                     TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
}

int GltfWriter::addBufferView(const void* data, size_t bytes, int target) {
  std::vector<unsigned char>& buffer = model_.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  view.target = target;
  buffer.resize(buffer.size() + bytes);
  if (bytes) std::memcpy(buffer.data() + view.byteOffset, data, bytes);
  buffer.resize((buffer.size() + 3) / 4 * 4, 0);  // the next view starts 4-byte aligned
  model_.bufferViews.push_back(std::move(view));
  return int(model_.bufferViews.size()) - 1;
}

int GltfWriter::addNode(tinygltf::Node node, bool root) {
  model_.nodes.push_back(std::move(node));
  const int index = int(model_.nodes.size()) - 1;
  if (root) model_.scenes[0].nodes.push_back(index);
  return index;
}

void GltfWriter::useExtension(const std::string& name) {
  std::vector<std::string>& used = model_.extensionsUsed;
  if (std::find(used.begin(), used.end(), name) == used.end()) used.push_back(name);
}

// Names come from the files a character was read from, checked there; JSON
// must be UTF-8 whatever happened since, so they are repaired once more.
void GltfWriter::repairNames() {
  auto repair = [](auto& objects) {
    for (auto& object : objects) object.name = repairedUtf8(object.name);
  };
  repair(model_.nodes);
  repair(model_.meshes);
  repair(model_.materials);
  repair(model_.images);
  repair(model_.animations);
  repair(model_.skins);
}

void GltfWriter::write(std::ostream& out, bool binary) {
  repairNames();
  tinygltf::TinyGLTF gltf;
  bool written = false;
  try {
    written = gltf.WriteGltfSceneToStream(&model_, out, !binary, binary);
  } catch (const std::exception& e) {
    throw Error(std::string("tinygltf could not write the glTF: ") + e.what());
  }
  if (!written) throw Error("tinygltf could not write the glTF");
}

}  // namespace mq
