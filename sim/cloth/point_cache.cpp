#include "sim/cloth/point_cache.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <ostream>

#include "core/io/byte_stream.h"
#include "core/io/file_bytes.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace mq::cloth {

namespace {

constexpr char kSignature[12] = {'P', 'O', 'I', 'N', 'T', 'C', 'A', 'C', 'H', 'E', '2', '\0'};
constexpr int32_t kVersion = 1;

void checkSamples(const PointCache& cache) {
  for (size_t s = 0; s < cache.samples.size(); ++s)
    if (cache.samples[s].size() != 3 * cache.pointCount)
      throw Error("point cache sample " + std::to_string(s) + " has " + std::to_string(cache.samples[s].size()) +
                  " values for " + std::to_string(cache.pointCount) + " points");
  if (cache.pointCount > size_t(INT32_MAX) || cache.samples.size() > size_t(INT32_MAX))
    throw Error("point cache too large for 32-bit counts");
}

// MDD is big-endian.
void putBigEndian(std::string& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(char((v >> shift) & 0xFF));
}

uint32_t bigEndianAt(const std::vector<uint8_t>& bytes, size_t offset) {
  return uint32_t(bytes[offset]) << 24 | uint32_t(bytes[offset + 1]) << 16 | uint32_t(bytes[offset + 2]) << 8 |
         uint32_t(bytes[offset + 3]);
}

}  // namespace

void writePointCache(const std::string& path, const PointCache& cache) {
  checkSamples(cache);
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
  // Samples of no points take no bytes: the size check below cannot bound
  // their count.
  if (points == 0 && samples != 0) in.fail(std::to_string(samples) + " samples of no points");
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

void writeMdd(const std::string& path, const PointCache& cache, float fps) {
  checkSamples(cache);
  if (!(fps > 0.0f) || !std::isfinite(fps)) throw Error("an MDD file needs a positive frame rate");
  std::string out;
  out.reserve(8 + 4 * cache.samples.size() * (1 + 3 * cache.pointCount));
  putBigEndian(out, uint32_t(cache.samples.size()));
  putBigEndian(out, uint32_t(cache.pointCount));
  for (size_t f = 0; f < cache.samples.size(); ++f) putBigEndian(out, std::bit_cast<uint32_t>(float(f) / fps));
  for (const std::vector<float>& sample : cache.samples)
    for (float v : sample) putBigEndian(out, std::bit_cast<uint32_t>(v));
  writeFileAtomically(
      path, [&](std::ostream& stream) { stream.write(out.data(), std::streamsize(out.size())); }, /*binary=*/true);
}

PointCache readMdd(const std::string& path) {
  const std::vector<uint8_t> bytes = readFileBytes(path);
  if (bytes.size() < 8) throw FileError(path, "truncated: an MDD file starts with two 4-byte counts");
  const uint64_t frames = bigEndianAt(bytes, 0), points = bigEndianAt(bytes, 4);
  // Compared by division: two corrupt counts cannot overflow the product.
  const uint64_t perFrame = 4 + 12 * points;
  if ((bytes.size() - 8) / perFrame != frames || (bytes.size() - 8) % perFrame != 0)
    throw FileError(path, "holds " + std::to_string(bytes.size() - 8) + " bytes after its counts; " +
                              std::to_string(frames) + " frames of " + std::to_string(points) + " points need " +
                              std::to_string(perFrame * frames));
  PointCache cache;
  cache.pointCount = size_t(points);
  float lastTime = -INFINITY;
  for (uint64_t f = 0; f < frames; ++f) {
    const float time = std::bit_cast<float>(bigEndianAt(bytes, 8 + 4 * f));
    if (!(time > lastTime) || !std::isfinite(time)) throw FileError(path, "frame times must be finite and increase");
    lastTime = time;
  }
  size_t offset = 8 + 4 * frames;
  for (uint64_t f = 0; f < frames; ++f) {
    std::vector<float>& sample = cache.samples.emplace_back(3 * points);
    for (float& v : sample) {
      v = std::bit_cast<float>(bigEndianAt(bytes, offset));
      offset += 4;
      if (!std::isfinite(v)) throw FileError(path, "frame " + std::to_string(f) + " has a non-finite position");
    }
  }
  return cache;
}

std::vector<std::string> writeSurfacePointCaches(const std::vector<BakedSurface>& surfaces, const std::string& path,
                                                 float fps) {
  const std::filesystem::path target(path);
  const std::string ext = fileExtension(path);
  if (ext != "pc2" && ext != "mdd") throw Error("a point cache is a .pc2 or .mdd file: " + path);
  std::error_code ec;
  if (!target.parent_path().empty()) std::filesystem::create_directories(target.parent_path(), ec);
  if (ec) throw FileError(target.parent_path().string(), "cannot create the directory: " + ec.message());
  std::vector<std::string> written;
  for (const BakedSurface& s : surfaces) {
    const std::filesystem::path stem = target.parent_path() / (target.stem().string() + "_" + surfaceFileStem(s.name));
    PointCache cache;
    cache.pointCount = s.frames.front().size() / 3;
    cache.samples = s.frames;
    if (ext == "pc2")
      writePointCache(stem.string() + ".pc2", cache);
    else
      writeMdd(stem.string() + ".mdd", cache, fps);
    writeSurfaceObj(s, stem.string() + ".obj");
    written.push_back(stem.string());
  }
  return written;
}

}  // namespace mq::cloth
