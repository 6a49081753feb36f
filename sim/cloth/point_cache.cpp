#include "sim/cloth/point_cache.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <ostream>

#include "core/io/byte_stream.h"
#include "core/io/file_bytes.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace mq::cloth {

namespace {

constexpr char kSignature[12] = {'P', 'O', 'I', 'N', 'T', 'C', 'A', 'C', 'H', 'E', '2', '\0'};
constexpr int32_t kVersion = 1;

}  // namespace

void writePointCache(const std::string& path, const PointCache& cache) {
  for (size_t s = 0; s < cache.samples.size(); ++s)
    if (cache.samples[s].size() != 3 * cache.pointCount)
      throw Error("point cache sample " + std::to_string(s) + " has " + std::to_string(cache.samples[s].size()) +
                  " values for " + std::to_string(cache.pointCount) + " points");
  if (cache.pointCount > size_t(INT32_MAX) || cache.samples.size() > size_t(INT32_MAX))
    throw Error("point cache too large for PC2's 32-bit counts");
  ByteWriter out;
  out.raw(kSignature, sizeof kSignature);
  out.i32(kVersion);
  out.i32(int32_t(cache.pointCount));
  out.f32(cache.startFrame);
  out.f32(cache.sampleRate);
  out.i32(int32_t(cache.samples.size()));
  for (const std::vector<float>& sample : cache.samples) out.floats(sample);
  writeFileAtomically(
      path, [&](std::ostream& stream) { stream.write(out.bytes().data(), std::streamsize(out.bytes().size())); },
      /*binary=*/true);
}

PointCache readPointCache(const std::string& path) {
  const std::vector<uint8_t> bytes = readFileBytes(path);
  ByteReader in(bytes, path);
  if (bytes.size() < sizeof kSignature || std::memcmp(bytes.data(), kSignature, sizeof kSignature) != 0)
    in.fail("not a Point Cache 2 file (no POINTCACHE2 signature)");
  in.text(sizeof kSignature, "the signature");
  const int32_t version = in.i32("the version");
  if (version != kVersion) in.fail("unsupported PC2 version " + std::to_string(version));
  const int32_t points = in.i32("the point count");
  PointCache cache;
  cache.startFrame = in.f32("the start frame");
  cache.sampleRate = in.f32("the sample rate");
  const int32_t samples = in.i32("the sample count");
  if (points < 0 || samples < 0) in.fail("negative point or sample count");
  if (!std::isfinite(cache.startFrame) || !std::isfinite(cache.sampleRate))
    in.fail("the start frame and sample rate must be finite");
  // Compared by division: two corrupt counts cannot overflow the product.
  const uint64_t perSample = 12 * uint64_t(points);
  if (perSample > 0 ? in.remaining() / perSample != uint64_t(samples) || in.remaining() % perSample != 0
                    : in.remaining() != 0)
    in.fail("holds " + std::to_string(in.remaining()) + " bytes of positions; " + std::to_string(samples) +
            " samples of " + std::to_string(points) + " points need " + std::to_string(perSample * uint64_t(samples)));
  cache.pointCount = size_t(points);
  cache.samples.reserve(size_t(samples));
  for (int32_t s = 0; s < samples; ++s) {
    cache.samples.push_back(in.floats(3 * uint64_t(points), "sample " + std::to_string(s)));
    for (float v : cache.samples.back())
      if (!std::isfinite(v)) in.fail("sample " + std::to_string(s) + " has a non-finite position");
  }
  return cache;
}

}  // namespace mq::cloth
