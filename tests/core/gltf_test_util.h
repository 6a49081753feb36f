#pragma once
// Small glTF files written by tests: one buffer as a data: URI beside a JSON
// document the test fills in.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/import_test_util.h"

namespace mq::test {

using nlohmann::json;

inline std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t n = (uint32_t(bytes[i]) << 16) | (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0) |
                       (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[n & 63] : '=';
  }
  return out;
}

// Builds one buffer; each add* returns the byte offset (4-byte aligned).
struct Buffer {
  std::vector<uint8_t> bytes;
  template <typename T>
  size_t add(const std::vector<T>& values) {
    while (bytes.size() % 4) bytes.push_back(0);
    const size_t offset = bytes.size();
    bytes.resize(offset + values.size() * sizeof(T));
    std::memcpy(bytes.data() + offset, values.data(), values.size() * sizeof(T));
    return offset;
  }
};

inline std::string writeGltf(const std::string& name, json gltf, const Buffer& buffer) {
  gltf["asset"] = {{"version", "2.0"}};
  gltf["buffers"] = {
      {{"byteLength", buffer.bytes.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer.bytes)}}};
  const auto dir = scratchDir("mq_gltf_features");
  const std::string path = (dir / name).string();
  std::ofstream(path) << gltf.dump(1);
  return path;
}

}  // namespace mq::test
