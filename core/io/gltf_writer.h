#pragma once
// The binary side of writing glTF 2.0: one buffer with 4-byte aligned views,
// accessors over them, and the two containers (.gltf with the buffer as a
// data URI, .glb with a binary chunk). Callers fill the rest of the JSON.

#include <cstdint>
#include <ostream>
#include <vector>

#include <nlohmann/json.hpp>

namespace mq {

class GltfWriter {
 public:
  static constexpr int kFloat = 5126, kUnsignedInt = 5125, kUnsignedShort = 5123;
  static constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

  explicit GltfWriter(const char* generator);

  nlohmann::json& json() { return gltf_; }
  // One accessor over a new bufferView holding `count` elements of `type`
  // ("SCALAR", "VEC3", "MAT4", ...) with `components` each; returns its index.
  // target 0: no bufferView target (animation and skin data).
  int addAccessor(const void* data, size_t count, const char* type, int components, int componentType, int target = 0);
  // A new bufferView over `bytes` bytes (an embedded image); returns its index.
  int addBufferView(const void* data, size_t bytes, int target = 0);
  // Names an extension in extensionsUsed (once).
  void useExtension(const char* name);

  void writeGltf(std::ostream& out);
  void writeGlb(std::ostream& out);

 private:
  nlohmann::json gltf_;
  std::vector<uint8_t> buffer_;
};

}  // namespace mq
