#pragma once
// Writing glTF 2.0 through tinygltf (Debian's libtinygltf): callers fill a
// tinygltf::Model; this adds the binary side (one buffer with 4-byte aligned
// views and accessors over them) and serializes it, as .gltf (the buffer as
// a data URI) or .glb (a binary chunk).

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace mq {

class GltfWriter {
 public:
  explicit GltfWriter(const char* generator);

  tinygltf::Model& model() { return model_; }
  // One accessor over a new bufferView holding `count` elements of `type`
  // (TINYGLTF_TYPE_*) in `componentType` (TINYGLTF_COMPONENT_TYPE_*); returns
  // its index. target 0: no bufferView target (animation and skin data).
  int addAccessor(const void* data, size_t count, int type, int componentType, int target = 0);
  // A float VEC3 vertex attribute with its bounds (the spec requires them for
  // POSITION, morph targets' too).
  int addPositionAccessor(const std::vector<float>& positions);
  // A float VEC3/VEC2/VEC4 vertex attribute.
  int addVertexAttribute(const std::vector<float>& values, int type);
  // Triangle or line indices.
  int addIndices(const uint32_t* indices, size_t count);
  // A new bufferView over `bytes` bytes (an embedded image); returns its index.
  int addBufferView(const void* data, size_t bytes, int target = 0);
  // A node, listed among the scene's roots when `root`; returns its index.
  int addNode(tinygltf::Node node, bool root);
  // Names an extension in extensionsUsed (once).
  void useExtension(const std::string& name);

  // Throws mq::Error when tinygltf cannot serialize the model.
  void write(std::ostream& out, bool binary);

 private:
  void repairNames();

  tinygltf::Model model_;
};

}  // namespace mq
