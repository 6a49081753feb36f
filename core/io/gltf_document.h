#pragma once
// Private to core/io: a loaded glTF 2.0 asset (.gltf with external or data:
// URI buffers, or .glb) and typed reads of its accessors. Every problem is
// reported as mq::FileError naming the file.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/io/json_fields.h"

namespace mq::gltf {

class Document {
 public:
  // Reads the JSON and every buffer; throws FileError.
  static Document load(const std::string& path);

  const nlohmann::json& json() const { return json_; }
  const std::string& path() const { return path_; }

  // Elements of an accessor as floats (normalised integers mapped to [0, 1]
  // or [-1, 1] as the spec says), count * components values; sparse
  // substitutions applied.
  std::vector<float> readFloats(int accessor, int* components = nullptr) const;
  // Integer accessor elements (indices, joint indices) widened to 32 bits.
  std::vector<uint32_t> readUints(int accessor, int* components = nullptr) const;
  // The bytes of a bufferView (an image embedded in a GLB).
  std::vector<uint8_t> bufferViewBytes(int view) const;
  // The bytes of a data: URI; throws FileError when it is not base64.
  std::vector<uint8_t> dataUriBytes(const std::string& uri) const;
  // A relative URI resolved beside the file (percent-decoded).
  std::string resolveUri(const std::string& uri) const;

  // The array element json()[array][index], or a FileError if absent.
  const nlohmann::json& element(const char* array, int index) const;
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  struct RawAccessor;
  RawAccessor describe(int accessor) const;
  std::vector<double> readDoubles(int accessor, int* components) const;
  std::vector<uint8_t> loadUri(const std::string& uri) const;
  void parseGlb(const std::vector<uint8_t>& bytes);
  void loadBuffers();

  std::string path_;
  nlohmann::json json_;
  std::vector<uint8_t> glbBinary_;
  std::vector<std::vector<uint8_t>> buffers_;
};

}  // namespace mq::gltf
