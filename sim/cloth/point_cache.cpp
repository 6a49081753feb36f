#include "sim/cloth/point_cache.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <ostream>

#include "core/io/file_bytes.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace mq::cloth {

namespace {

constexpr char kSignature[12] = {'P', 'O', 'I', 'N', 'T', 'C', 'A', 'C', 'H', 'E', '2', '\0'};
constexpr int32_t kVersion = 1;
constexpr size_t kHeaderBytes = sizeof kSignature + 4 * 5;

template <typename T>
void put(std::ostream& out, T value) {
  static_assert(sizeof(T) == 4);
  unsigned char bytes[4];
  std::memcpy(bytes, &value, 4);  // the hosts Debian builds for are little-endian, as PC2
  out.write(reinterpret_cast<const char*>(bytes), 4);
}

template <typename T>
T get(const std::vector<uint8_t>& bytes, size_t at) {
  T value;
  std::memcpy(&value, bytes.data() + at, 4);
  return value;
}

}  // namespace

void writePointCache(const std::string& path, const PointCache& cache) {
  for (size_t s = 0; s < cache.samples.size(); ++s)
    if (cache.samples[s].size() != 3 * cache.pointCount)
      throw Error("point cache sample " + std::to_string(s) + " has " + std::to_string(cache.samples[s].size()) +
                  " values for " + std::to_string(cache.pointCount) + " points");
  if (cache.pointCount > size_t(INT32_MAX) || cache.samples.size() > size_t(INT32_MAX))
    throw Error("point cache too large for PC2's 32-bit counts");
  writeFileAtomically(
      path,
      [&](std::ostream& out) {
        out.write(kSignature, sizeof kSignature);
        put<int32_t>(out, kVersion);
        put<int32_t>(out, int32_t(cache.pointCount));
        put<float>(out, cache.startFrame);
        put<float>(out, cache.sampleRate);
        put<int32_t>(out, int32_t(cache.samples.size()));
        for (const std::vector<float>& sample : cache.samples)
          out.write(reinterpret_cast<const char*>(sample.data()), std::streamsize(sample.size() * sizeof(float)));
      },
      /*binary=*/true);
}

PointCache readPointCache(const std::string& path) {
  const std::vector<uint8_t> bytes = readFileBytes(path);
  if (bytes.size() < kHeaderBytes || std::memcmp(bytes.data(), kSignature, sizeof kSignature) != 0)
    throw FileError(path, "not a Point Cache 2 file (no POINTCACHE2 signature)");
  const int32_t version = get<int32_t>(bytes, 12);
  if (version != kVersion) throw FileError(path, "unsupported PC2 version " + std::to_string(version));
  const int32_t points = get<int32_t>(bytes, 16);
  PointCache cache;
  cache.startFrame = get<float>(bytes, 20);
  cache.sampleRate = get<float>(bytes, 24);
  const int32_t samples = get<int32_t>(bytes, 28);
  if (points < 0 || samples < 0) throw FileError(path, "negative point or sample count");
  if (!std::isfinite(cache.startFrame) || !std::isfinite(cache.sampleRate))
    throw FileError(path, "the start frame and sample rate must be finite");
  // Compared by division: two corrupt counts cannot overflow the product.
  const size_t body = bytes.size() - kHeaderBytes, perSample = 12 * size_t(points);
  if (perSample > 0 ? body / perSample != size_t(samples) || body % perSample != 0 : body != 0)
    throw FileError(path, "holds " + std::to_string(body) + " bytes of positions; " + std::to_string(samples) +
                              " samples of " + std::to_string(points) + " points need " +
                              std::to_string(perSample * size_t(samples)));
  cache.pointCount = size_t(points);
  cache.samples.resize(size_t(samples), std::vector<float>(3 * size_t(points)));
  for (int32_t s = 0; s < samples; ++s) {
    std::vector<float>& sample = cache.samples[size_t(s)];
    std::memcpy(sample.data(), bytes.data() + kHeaderBytes + size_t(s) * perSample, perSample);
    for (float v : sample)
      if (!std::isfinite(v)) throw FileError(path, "sample " + std::to_string(s) + " has a non-finite position");
  }
  return cache;
}

}  // namespace mq::cloth
