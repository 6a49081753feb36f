#include "sim/cloth/bake_cache.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <ostream>

#include "core/io/byte_stream.h"
#include "core/io/file_bytes.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace mq::cloth {

namespace {

constexpr char kMagic[] = {'M', 'Q', 'B', 'A', 'K', 'E'};
constexpr uint32_t kVersion = 1;
// The fewest bytes a garment takes (fps, triangle, vertex and frame counts),
// so a garment count can be checked against the file's size.
constexpr uint64_t kMinGarmentBytes = 16;
// Per vertex and frame: three position floats and one stretch float.
constexpr uint64_t kBytesPerVertexFrame = 16;

bool allFinite(const std::vector<float>& values) {
  return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
}

// The rules a garment must follow, checked before writing and after reading
// so that the reader accepts exactly what the writer writes. Returns the
// first rule broken, naming `garment` ("garment 2"), or "" when none is.
std::string garmentProblem(const BakedCloth& cloth, const std::vector<std::vector<float>>& stretch,
                           uint64_t vertexCount, const std::string& garment) {
  if (!std::isfinite(cloth.fps()) || cloth.fps() <= 0.0f)
    return garment + ": fps " + std::to_string(cloth.fps()) + " is not a positive finite number";
  const std::vector<uint32_t>& triangles = cloth.triangles();
  if (triangles.size() % 3 != 0)
    return garment + ": " + std::to_string(triangles.size()) + " triangle indices, not a multiple of 3";
  for (uint32_t index : triangles) {
    if (index >= vertexCount)
      return garment + ": triangle index " + std::to_string(index) + " is out of range (" +
             std::to_string(vertexCount) + " vertices)";
  }
  if (cloth.frameCount() > 0 && vertexCount == 0) return garment + " has frames but no vertices";
  if (stretch.size() != cloth.frameCount())
    return garment + ": " + std::to_string(stretch.size()) + " stretch frames for " +
           std::to_string(cloth.frameCount()) + " frames";
  for (size_t f = 0; f < cloth.frameCount(); ++f) {
    const std::string frame = garment + " frame " + std::to_string(f);
    if (cloth.frame(f).size() != 3 * vertexCount)
      return frame + ": " + std::to_string(cloth.frame(f).size()) + " position floats, expected 3 x " +
             std::to_string(vertexCount) + " vertices";
    if (stretch[f].size() != vertexCount)
      return frame + ": " + std::to_string(stretch[f].size()) + " stretch values, expected one per vertex (" +
             std::to_string(vertexCount) + ")";
    if (!allFinite(cloth.frame(f))) return frame + ": a position is not finite";
    if (!allFinite(stretch[f])) return frame + ": a stretch value is not finite";
  }
  return "";
}

// The vertex count the file records. A garment without frames has no
// positions to count, so its triangles say how many vertices they need.
uint64_t vertexCountOf(const BakedCloth& cloth) {
  if (cloth.frameCount() > 0) return cloth.frame(0).size() / 3;
  const std::vector<uint32_t>& t = cloth.triangles();
  return t.empty() ? 0 : uint64_t(*std::max_element(t.begin(), t.end())) + 1;
}

BakedCloth readGarment(ByteReader& in, const std::string& garment, std::vector<std::vector<float>>& stretch) {
  const float fps = in.f32(garment + " fps");
  const uint32_t indexCount = in.count(garment + " triangle index", 4);
  BakedCloth cloth(in.u32s(indexCount, garment + " triangles"), fps);
  const uint32_t vertexCount = in.u32(garment + " vertex count");
  const uint32_t frameCount = in.u32(garment + " frame count");
  // Without vertices a frame takes no bytes, so the size check below could
  // not bound the frame count.
  if (frameCount > 0 && vertexCount == 0) in.fail(garment + " has frames but no vertices");
  in.fits(frameCount, kBytesPerVertexFrame * vertexCount,
          garment + " frames (" + std::to_string(vertexCount) + " vertices each)");
  for (uint32_t f = 0; f < frameCount; ++f)
    cloth.addFrame(in.floats(3ull * vertexCount, garment + " frame " + std::to_string(f)));
  stretch.reserve(frameCount);
  for (uint32_t f = 0; f < frameCount; ++f)
    stretch.push_back(in.floats(vertexCount, garment + " stretch frame " + std::to_string(f)));
  const std::string problem = garmentProblem(cloth, stretch, vertexCount, garment);
  if (!problem.empty()) in.fail(problem);
  return cloth;
}

}  // namespace

void writeBakeCache(const std::string& path, const BakeCache& cache) {
  const auto refuse = [&](const std::string& problem) {
    throw FileError(path, "cannot save the bake cache: " + problem);
  };
  // The file stores counts as uint32.
  const auto count = [&](uint64_t n, const std::string& what) {
    if (n > std::numeric_limits<uint32_t>::max())
      refuse(what + " " + std::to_string(n) + " exceeds the format's limit");
    return uint32_t(n);
  };
  if (cache.stretch.size() != cache.garments.size())
    refuse(std::to_string(cache.stretch.size()) + " stretch lists for " + std::to_string(cache.garments.size()) +
           " garments");
  if (!std::isfinite(cache.start)) refuse("the start time is not finite");

  ByteWriter out;
  out.raw(kMagic, sizeof kMagic);
  out.u32(kVersion);
  out.u32(count(cache.key.size(), "key length"));
  out.raw(cache.key.data(), cache.key.size());
  out.i32(cache.clip);
  out.f32(cache.start);
  out.u32(count(cache.garments.size(), "garment count"));
  for (size_t g = 0; g < cache.garments.size(); ++g) {
    const BakedCloth& cloth = cache.garments[g];
    const std::string garment = "garment " + std::to_string(g);
    const uint64_t vertexCount = vertexCountOf(cloth);
    const std::string problem = garmentProblem(cloth, cache.stretch[g], vertexCount, garment);
    if (!problem.empty()) refuse(problem);
    out.f32(cloth.fps());
    out.u32(count(cloth.triangles().size(), garment + " triangle index count"));
    for (uint32_t index : cloth.triangles()) out.u32(index);
    out.u32(count(vertexCount, garment + " vertex count"));
    out.u32(count(cloth.frameCount(), garment + " frame count"));
    for (size_t f = 0; f < cloth.frameCount(); ++f) out.floats(cloth.frame(f));
    for (const std::vector<float>& frame : cache.stretch[g]) out.floats(frame);
  }
  writeFileAtomically(
      path, [&](std::ostream& stream) { stream.write(out.bytes().data(), std::streamsize(out.bytes().size())); },
      /*binary=*/true);
}

BakeCache readBakeCache(const std::string& path) {
  const std::vector<uint8_t> bytes = readFileBytes(path);
  ByteReader in(bytes, path);
  // A file that starts otherwise is something else; one that stops inside
  // the magic is a truncated cache.
  if (!std::equal(bytes.begin(), bytes.begin() + std::min(bytes.size(), sizeof kMagic), kMagic))
    in.fail("not a Mannequin bake cache (the file does not start with \"MQBAKE\")");
  in.text(sizeof kMagic, "the magic \"MQBAKE\"");
  const uint32_t version = in.u32("the version");
  if (version != kVersion)
    in.fail("unsupported bake cache version " + std::to_string(version) + " (this Mannequin reads version " +
            std::to_string(kVersion) + ")");

  BakeCache cache;
  cache.key = in.text(in.count("key", 1), "the key");
  cache.clip = in.i32("the clip");
  cache.start = in.f32("the start time");
  if (!std::isfinite(cache.start)) in.fail("the start time is not finite");
  const uint32_t garmentCount = in.count("garment", kMinGarmentBytes);
  cache.garments.reserve(garmentCount);
  cache.stretch.resize(garmentCount);
  for (uint32_t g = 0; g < garmentCount; ++g)
    cache.garments.push_back(readGarment(in, "garment " + std::to_string(g), cache.stretch[g]));
  if (in.remaining() > 0) in.fail(std::to_string(in.remaining()) + " unexpected bytes after the last garment");
  return cache;
}

std::string bakeCachePath(const std::string& documentPath) {
  return std::filesystem::path(documentPath).replace_extension(".mqbake").string();
}

}  // namespace mq::cloth
