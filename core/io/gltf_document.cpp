#include "core/io/gltf_document.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "core/io/file_bytes.h"
#include "core/io/json_fields.h"
#include "core/util/error.h"

namespace mq::gltf {

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;     // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A;    // "JSON"
constexpr uint32_t kChunkBinary = 0x004E4942;  // "BIN\0"

uint32_t readU32(const uint8_t* p) {
  uint32_t v;
  std::memcpy(&v, p, 4);
  return v;  // glTF is little-endian, like every machine we build for
}

int componentsOf(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4" || type == "MAT2") return 4;
  if (type == "MAT3") return 9;
  if (type == "MAT4") return 16;
  return 0;
}

int sizeOfComponent(int componentType) {
  switch (componentType) {
    case 5120:
    case 5121:
      return 1;
    case 5122:
    case 5123:
      return 2;
    case 5125:
    case 5126:
      return 4;
    default:
      return 0;
  }
}

// One component as a double; normalised integers per the glTF spec.
double readComponent(const uint8_t* p, int componentType, bool normalized) {
  switch (componentType) {
    case 5120: {
      int8_t v;
      std::memcpy(&v, p, 1);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case 5121: {
      uint8_t v = *p;
      return normalized ? v / 255.0 : v;
    }
    case 5122: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case 5123: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0 : v;
    }
    case 5125: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

int base64Value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+' || c == '-') return 62;
  if (c == '/' || c == '_') return 63;
  return -1;
}

bool decodeBase64(const std::string& text, size_t begin, std::vector<uint8_t>& out) {
  uint32_t accumulator = 0;
  int bits = 0;
  for (size_t i = begin; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '=') break;
    if (c == ' ' || c == '\n' || c == '\r') continue;
    const int v = base64Value(c);
    if (v < 0) return false;
    accumulator = (accumulator << 6) | uint32_t(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(uint8_t((accumulator >> bits) & 0xFF));
    }
  }
  return true;
}

std::string percentDecode(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(uint8_t(uri[i + 1])) &&
        std::isxdigit(uint8_t(uri[i + 2]))) {
      out.push_back(char(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
      i += 2;
    } else {
      out.push_back(uri[i]);
    }
  }
  return out;
}

}  // namespace

struct Document::RawAccessor {
  const uint8_t* data = nullptr;  // null: all zeros (no bufferView)
  size_t count = 0;
  size_t stride = 0;
  int components = 0;
  int componentType = 0;
  bool normalized = false;
};

void Document::fail(const std::string& problem) const { throw FileError(path_, problem); }

const nlohmann::json& Document::element(const char* array, int index) const {
  if (!json_.contains(array) || !json_[array].is_array() || index < 0 || index >= static_cast<int>(json_[array].size()))
    fail(std::string("refers to missing ") + array + "[" + std::to_string(index) + "]");
  return json_[array][index];
}

Document Document::load(const std::string& path) {
  Document doc;
  doc.path_ = path;
  const std::vector<uint8_t> bytes = readFileBytes(path);
  if (bytes.size() >= 4 && readU32(bytes.data()) == kGlbMagic) {
    doc.parseGlb(bytes);
  } else {
    doc.json_ = parseJsonText(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path);
  }
  if (!doc.json_.is_object()) doc.fail("not a glTF document (top level is not a JSON object)");
  try {
    const std::string version = doc.json_.at("asset").at("version").get<std::string>();
    if (version.rfind("2.", 0) != 0) doc.fail("glTF version " + version + " is not supported (only 2.x)");
    doc.loadBuffers();
  } catch (const nlohmann::json::exception& e) {
    doc.fail("malformed glTF: " + jsonProblem(e));
  }
  return doc;
}

void Document::parseGlb(const std::vector<uint8_t>& bytes) {
  if (bytes.size() < 20) fail("truncated GLB header");
  if (readU32(bytes.data() + 4) != 2)
    fail("GLB container version " + std::to_string(readU32(bytes.data() + 4)) + " is not 2");
  const size_t length = readU32(bytes.data() + 8);
  if (length > bytes.size())
    fail("truncated GLB: header says " + std::to_string(length) + " bytes, file has " + std::to_string(bytes.size()));
  size_t offset = 12;
  bool haveJson = false;
  while (offset + 8 <= length) {
    const size_t chunkLength = readU32(bytes.data() + offset);
    const uint32_t chunkType = readU32(bytes.data() + offset + 4);
    offset += 8;
    if (offset + chunkLength > length) fail("truncated GLB chunk");
    if (chunkType == kChunkJson && !haveJson) {
      try {
        json_ = nlohmann::json::parse(bytes.begin() + offset, bytes.begin() + offset + chunkLength);
      } catch (const nlohmann::json::exception& e) {
        fail("GLB JSON chunk is not valid JSON: " + jsonProblem(e));
      }
      haveJson = true;
    } else if (chunkType == kChunkBinary && glbBinary_.empty()) {
      glbBinary_.assign(bytes.begin() + offset, bytes.begin() + offset + chunkLength);
    }
    offset += (chunkLength + 3) & ~size_t(3);
  }
  if (!haveJson) fail("GLB has no JSON chunk");
}

std::vector<uint8_t> Document::dataUriBytes(const std::string& uri) const {
  std::vector<uint8_t> out;
  const size_t comma = uri.find(',');
  if (comma == std::string::npos || uri.rfind(";base64", comma) == std::string::npos) fail("data URI is not base64");
  if (!decodeBase64(uri, comma + 1, out)) fail("data URI holds invalid base64");
  return out;
}

std::string Document::resolveUri(const std::string& uri) const {
  return (std::filesystem::path(path_).parent_path() / percentDecode(uri)).string();
}

std::vector<uint8_t> Document::bufferViewBytes(int viewIndex) const {
  const nlohmann::json& view = element("bufferViews", viewIndex);
  const int bufferIndex = view.at("buffer").get<int>();
  if (bufferIndex < 0 || bufferIndex >= static_cast<int>(buffers_.size()))
    fail("bufferView " + std::to_string(viewIndex) + " refers to a missing buffer");
  const std::vector<uint8_t>& buffer = buffers_[bufferIndex];
  const size_t offset = view.value("byteOffset", size_t(0));
  const size_t length = view.at("byteLength").get<size_t>();
  if (offset > buffer.size() || length > buffer.size() - offset)
    fail("bufferView " + std::to_string(viewIndex) + " runs past its buffer");
  return {buffer.begin() + static_cast<std::ptrdiff_t>(offset),
          buffer.begin() + static_cast<std::ptrdiff_t>(offset + length)};
}

std::vector<uint8_t> Document::loadUri(const std::string& uri) const {
  if (uri.rfind("data:", 0) == 0) return dataUriBytes(uri);
  const std::filesystem::path file = resolveUri(uri);
  try {
    return readFileBytes(file.string());
  } catch (const FileError& e) {
    fail("buffer '" + uri + "': " + e.problem());
  }
}

void Document::loadBuffers() {
  if (!json_.contains("buffers")) return;
  const nlohmann::json& buffers = json_["buffers"];
  for (size_t i = 0; i < buffers.size(); ++i) {
    const nlohmann::json& b = buffers[i];
    const size_t byteLength = b.at("byteLength").get<size_t>();
    std::vector<uint8_t> data;
    if (b.contains("uri"))
      data = loadUri(b["uri"].get<std::string>());
    else if (i == 0)
      data = glbBinary_;
    else
      fail("buffer " + std::to_string(i) + " has no uri");
    if (data.size() < byteLength)
      fail("buffer " + std::to_string(i) + " is truncated: " + std::to_string(data.size()) + " of " +
           std::to_string(byteLength) + " bytes");
    buffers_.push_back(std::move(data));
  }
}

Document::RawAccessor Document::describe(int accessor) const {
  const nlohmann::json& a = element("accessors", accessor);
  RawAccessor raw;
  raw.count = a.at("count").get<size_t>();
  raw.components = componentsOf(a.at("type").get<std::string>());
  raw.componentType = a.at("componentType").get<int>();
  raw.normalized = a.value("normalized", false);
  const int componentSize = sizeOfComponent(raw.componentType);
  if (raw.components == 0 || componentSize == 0)
    fail("accessor " + std::to_string(accessor) + " has an unknown type or component type");
  const size_t elementSize = size_t(raw.components) * componentSize;
  raw.stride = elementSize;
  constexpr size_t kMaxElements = size_t(1) << 28;  // far beyond any real asset; guards the allocation
  if (raw.count > kMaxElements) fail("accessor " + std::to_string(accessor) + " has an implausible count");
  if (!a.contains("bufferView")) return raw;

  const int viewIndex = a["bufferView"].get<int>();
  const nlohmann::json& view = element("bufferViews", viewIndex);
  const int bufferIndex = view.at("buffer").get<int>();
  if (bufferIndex < 0 || bufferIndex >= static_cast<int>(buffers_.size()))
    fail("bufferView " + std::to_string(viewIndex) + " refers to a missing buffer");
  const std::vector<uint8_t>& buffer = buffers_[bufferIndex];
  const size_t viewOffset = view.value("byteOffset", size_t(0));
  const size_t viewLength = view.at("byteLength").get<size_t>();
  // Compared without sums that a hostile file could wrap around.
  if (viewOffset > buffer.size() || viewLength > buffer.size() - viewOffset)
    fail("bufferView " + std::to_string(viewIndex) + " runs past its buffer");
  raw.stride = view.value("byteStride", size_t(0));
  if (raw.stride == 0) raw.stride = elementSize;
  const size_t offset = a.value("byteOffset", size_t(0));
  if (raw.count > 0 && (offset > viewLength || elementSize > viewLength - offset ||
                        raw.count - 1 > (viewLength - offset - elementSize) / raw.stride))
    fail("accessor " + std::to_string(accessor) + " runs past its bufferView");
  raw.data = buffer.data() + viewOffset + offset;
  return raw;
}

std::vector<double> Document::readDoubles(int accessor, int* components) const {
  RawAccessor raw;
  std::vector<double> out;
  try {
    raw = describe(accessor);
    const int componentSize = sizeOfComponent(raw.componentType);
    out.assign(raw.count * raw.components, 0.0);
    if (raw.data)
      for (size_t i = 0; i < raw.count; ++i)
        for (int c = 0; c < raw.components; ++c)
          out[i * raw.components + c] =
              readComponent(raw.data + i * raw.stride + c * componentSize, raw.componentType, raw.normalized);

    const nlohmann::json& a = json_["accessors"][accessor];
    if (a.contains("sparse")) {
      const nlohmann::json& sparse = a["sparse"];
      const size_t n = sparse.at("count").get<size_t>();
      const nlohmann::json& idx = sparse.at("indices");
      const nlohmann::json& val = sparse.at("values");
      auto viewData = [&](const nlohmann::json& ref, size_t bytes) {
        const nlohmann::json& view = element("bufferViews", ref.at("bufferView").get<int>());
        const int b = view.at("buffer").get<int>();
        if (b < 0 || b >= static_cast<int>(buffers_.size())) fail("sparse accessor refers to a missing buffer");
        const size_t size = buffers_[b].size();
        const size_t viewStart = view.value("byteOffset", size_t(0)), refStart = ref.value("byteOffset", size_t(0));
        if (viewStart > size || refStart > size - viewStart || bytes > size - viewStart - refStart)
          fail("sparse accessor runs past its buffer");
        const size_t start = viewStart + refStart;
        return buffers_[b].data() + start;
      };
      if (n > raw.count) fail("sparse accessor has more values than its accessor");
      const int indexType = idx.at("componentType").get<int>();
      const int indexSize = sizeOfComponent(indexType);
      if (indexSize == 0) fail("sparse accessor has an unknown index type");
      const uint8_t* indices = viewData(idx, n * indexSize);
      const uint8_t* values = viewData(val, n * raw.components * componentSize);
      for (size_t k = 0; k < n; ++k) {
        const size_t i = size_t(readComponent(indices + k * indexSize, indexType, false));
        if (i >= raw.count) fail("sparse accessor index out of range");
        for (int c = 0; c < raw.components; ++c)
          out[i * raw.components + c] =
              readComponent(values + (k * raw.components + c) * componentSize, raw.componentType, raw.normalized);
      }
    }
  } catch (const nlohmann::json::exception& e) {
    fail("malformed accessor " + std::to_string(accessor) + ": " + jsonProblem(e));
  }
  if (components) *components = raw.components;
  return out;
}

std::vector<float> Document::readFloats(int accessor, int* components) const {
  const std::vector<double> d = readDoubles(accessor, components);
  std::vector<float> out(d.size());
  for (size_t i = 0; i < d.size(); ++i) {
    out[i] = static_cast<float>(d[i]);
    if (!std::isfinite(out[i])) fail("accessor " + std::to_string(accessor) + " holds a non-finite value");
  }
  return out;
}

std::vector<uint32_t> Document::readUints(int accessor, int* components) const {
  const std::vector<double> d = readDoubles(accessor, components);
  std::vector<uint32_t> out(d.size());
  for (size_t i = 0; i < d.size(); ++i) {
    if (!(d[i] >= 0.0) || d[i] > 4294967295.0 || d[i] != std::floor(d[i]))
      fail("accessor " + std::to_string(accessor) + " should hold non-negative integers");
    out[i] = static_cast<uint32_t>(d[i]);
  }
  return out;
}

}  // namespace mq::gltf
