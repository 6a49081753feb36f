#pragma once
// Little-endian binary files, written and read whatever the machine's byte
// order (the bake cache, point caches). The reader works on a whole file in
// memory and checks what remains before every read, so a truncated or
// corrupt file fails with a FileError naming the file and what was being
// read, never by reading past the end or allocating for a count the file
// cannot hold.

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "core/util/error.h"

namespace mq {

// Appends little-endian values whatever the machine's byte order.
class ByteWriter {
 public:
  void u32(uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes_.push_back(char((v >> (8 * i)) & 0xFFu));
  }
  void i32(int32_t v) { u32(std::bit_cast<uint32_t>(v)); }
  void f32(float v) { u32(std::bit_cast<uint32_t>(v)); }
  void floats(const std::vector<float>& values) {
    for (float v : values) f32(v);
  }
  void raw(const char* data, size_t n) { bytes_.append(data, n); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

// Reads a whole file held in memory (`bytes` and `path` must outlive it).
class ByteReader {
 public:
  ByteReader(const std::vector<uint8_t>& bytes, const std::string& path) : bytes_(bytes), path_(path) {}

  [[noreturn]] void fail(const std::string& problem) const { throw FileError(path_, problem); }

  uint64_t remaining() const { return bytes_.size() - offset_; }

  void need(uint64_t n, const std::string& what) const {
    if (n > remaining())
      fail("truncated: the file ends after " + std::to_string(bytes_.size()) + " bytes, expected " +
           std::to_string(n - remaining()) + " more for " + what);
  }

  // Checks that `count` items of `itemBytes` each fit in what remains.
  // Divides rather than multiplies: the product of two corrupt counts can overflow.
  void fits(uint64_t count, uint64_t itemBytes, const std::string& what) const {
    if (itemBytes > 0 && count > remaining() / itemBytes)
      fail("truncated or corrupt: " + what + ": " + std::to_string(count) + " of " + std::to_string(itemBytes) +
           " bytes each, but only " + std::to_string(remaining()) + " bytes remain (the file has " +
           std::to_string(bytes_.size()) + ")");
  }

  uint32_t u32(const std::string& what) {
    need(4, what);
    const uint8_t* p = bytes_.data() + offset_;
    offset_ += 4;
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
  }
  int32_t i32(const std::string& what) { return std::bit_cast<int32_t>(u32(what)); }
  float f32(const std::string& what) { return std::bit_cast<float>(u32(what)); }

  // A count of items of `itemBytes` each that must follow in the file.
  uint32_t count(const std::string& what, uint64_t itemBytes) {
    const uint32_t n = u32(what + " count");
    fits(n, itemBytes, what);
    return n;
  }

  std::vector<float> floats(uint64_t n, const std::string& what) {
    need(4 * n, what);
    std::vector<float> out(n);
    for (float& v : out) v = f32(what);
    return out;
  }
  std::vector<uint32_t> u32s(uint64_t n, const std::string& what) {
    need(4 * n, what);
    std::vector<uint32_t> out(n);
    for (uint32_t& v : out) v = u32(what);
    return out;
  }
  std::string text(uint64_t n, const std::string& what) {
    need(n, what);
    std::string out(reinterpret_cast<const char*>(bytes_.data() + offset_), n);
    offset_ += n;
    return out;
  }

 private:
  const std::vector<uint8_t>& bytes_;
  const std::string& path_;
  size_t offset_ = 0;
};

}  // namespace mq
