#include "core/io/gltf_writer.h"

#include <cstring>
#include <string>

namespace mq {
namespace {

template <typename T>
void put(std::ostream& out, T value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);  // little-endian hosts only
}

std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t n = (uint32_t(bytes[i]) << 16) | (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0u) |
                       (i + 2 < bytes.size() ? uint32_t(bytes[i + 2]) : 0u);
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[n & 63] : '=';
  }
  return out;
}

}  // namespace

GltfWriter::GltfWriter(const char* generator)
    : gltf_({{"asset", {{"version", "2.0"}, {"generator", generator}}},
             {"scene", 0},
             {"scenes", {{{"nodes", nlohmann::json::array()}}}},
             {"nodes", nlohmann::json::array()},
             {"meshes", nlohmann::json::array()},
             {"accessors", nlohmann::json::array()},
             {"bufferViews", nlohmann::json::array()}}) {}

int GltfWriter::addAccessor(const void* data, size_t count, const char* type, int components, int componentType,
                            int target) {
  const size_t componentSize = componentType == kFloat || componentType == kUnsignedInt ? 4 : 2;
  const int view = addBufferView(data, count * components * componentSize, target);
  gltf_["accessors"].push_back(
      {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}});
  return static_cast<int>(gltf_["accessors"].size()) - 1;
}

int GltfWriter::addBufferView(const void* data, size_t bytes, int target) {
  const size_t offset = buffer_.size();
  buffer_.resize(offset + bytes);
  if (bytes) std::memcpy(buffer_.data() + offset, data, bytes);
  while (buffer_.size() % 4) buffer_.push_back(0);
  nlohmann::json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}};
  if (target) view["target"] = target;
  gltf_["bufferViews"].push_back(view);
  return static_cast<int>(gltf_["bufferViews"].size()) - 1;
}

void GltfWriter::useExtension(const char* name) {
  nlohmann::json& used = gltf_["extensionsUsed"];
  for (const auto& e : used)
    if (e == name) return;
  used.push_back(name);
}

void GltfWriter::writeGltf(std::ostream& out) {
  gltf_["buffers"] = {
      {{"byteLength", buffer_.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer_)}}};
  out << gltf_.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
}

void GltfWriter::writeGlb(std::ostream& out) {
  gltf_["buffers"] = {{{"byteLength", buffer_.size()}}};
  std::string text = gltf_.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  while (text.size() % 4) text += ' ';
  const uint32_t total = 12 + 8 + uint32_t(text.size()) + 8 + uint32_t(buffer_.size());
  put(out, uint32_t(0x46546C67));  // "glTF"
  put(out, uint32_t(2));
  put(out, total);
  put(out, uint32_t(text.size()));
  put(out, uint32_t(0x4E4F534A));  // "JSON"
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  put(out, uint32_t(buffer_.size()));
  put(out, uint32_t(0x004E4942));  // "BIN"
  out.write(reinterpret_cast<const char*>(buffer_.data()), static_cast<std::streamsize>(buffer_.size()));
}

}  // namespace mq
