// The bake cache file (sim/cloth/bake_cache.h): bit-exact round trips, and
// a strict reader that names the file and the problem for every damaged file.
#include <gtest/gtest.h>

#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "core/import_test_util.h"
#include "core/util/error.h"
#include "sim/cloth/bake_cache.h"

namespace mq {
namespace {

using namespace mq::cloth;
namespace fs = std::filesystem;

fs::path scratch(const std::string& name) { return test::scratchDir("mq_bake_cache_test") / name; }

std::vector<uint8_t> fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeBytes(const fs::path& path, const std::vector<uint8_t>& bytes, size_t length) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(length));
}
void writeBytes(const fs::path& path, const std::vector<uint8_t>& bytes) { writeBytes(path, bytes, bytes.size()); }

void putU32(std::vector<uint8_t>& bytes, size_t offset, uint32_t v) {
  for (int i = 0; i < 4; ++i) bytes.at(offset + i) = uint8_t(v >> (8 * i));
}
void putF32(std::vector<uint8_t>& bytes, size_t offset, float v) { putU32(bytes, offset, std::bit_cast<uint32_t>(v)); }

// The message of the FileError readBakeCache throws, or "(no error)".
std::string readError(const fs::path& path) {
  try {
    readBakeCache(path.string());
  } catch (const FileError& e) {
    return e.what();
  }
  return "(no error)";
}

std::vector<uint32_t> bits(const std::vector<float>& values) {
  std::vector<uint32_t> out;
  for (float v : values) out.push_back(std::bit_cast<uint32_t>(v));
  return out;
}

// A garment of `vertexCount` vertices and `frameCount` frames whose values
// include the awkward ones (negative zero, a subnormal, the largest float).
void addGarment(BakeCache& cache, size_t vertexCount, size_t frameCount, float fps, std::vector<uint32_t> triangles) {
  BakedCloth cloth(std::move(triangles), fps);
  std::vector<std::vector<float>> stretch;
  for (size_t f = 0; f < frameCount; ++f) {
    std::vector<float> x(3 * vertexCount), s(vertexCount);
    for (size_t i = 0; i < x.size(); ++i) x[i] = 0.1f * float(i) - 0.37f * float(f) + 1e-3f * float(vertexCount);
    for (size_t i = 0; i < s.size(); ++i) s[i] = 1.0f + 0.01f * float(i + f);
    x[0] = -0.0f;
    x[1] = 1e-40f;
    x.back() = std::numeric_limits<float>::max();
    cloth.addFrame(std::move(x));
    stretch.push_back(std::move(s));
  }
  cache.garments.push_back(std::move(cloth));
  cache.stretch.push_back(std::move(stretch));
}

BakeCache twoGarments() {
  BakeCache cache;
  cache.key = std::string("scene\0state #7", 14);  // bytes, not a C string
  cache.clip = 3;
  cache.start = 1.25f;
  addGarment(cache, 4, 3, 30.0f, {0, 1, 2, 0, 2, 3});
  addGarment(cache, 7, 3, 30.0f, {4, 5, 6, 0, 1, 6, 2, 3, 5});
  return cache;
}

// One garment, 3 vertices, 2 frames, key "k1". Its layout, by byte offset:
// magic 0, version 6, key length 10, key 14, clip 16, start 20, garment
// count 24, fps 28, triangle index count 32, indices 36, vertex count 48,
// frame count 52, frames 56 (2 x 9 floats), stretch 128 (2 x 3), end 152.
BakeCache small() {
  BakeCache cache;
  cache.key = "k1";
  cache.clip = -1;
  addGarment(cache, 3, 2, 24.0f, {0, 1, 2});
  return cache;
}
constexpr size_t kSmallSize = 152;

std::vector<uint8_t> smallBytes() {
  const fs::path path = scratch("small.mqbake");
  writeBakeCache(path.string(), small());
  return fileBytes(path);
}

void expectSame(const BakeCache& a, const BakeCache& b) {
  EXPECT_EQ(a.key, b.key);
  EXPECT_EQ(a.clip, b.clip);
  EXPECT_EQ(std::bit_cast<uint32_t>(a.start), std::bit_cast<uint32_t>(b.start));
  ASSERT_EQ(a.garments.size(), b.garments.size());
  ASSERT_EQ(a.stretch.size(), b.stretch.size());
  for (size_t g = 0; g < a.garments.size(); ++g) {
    EXPECT_EQ(a.garments[g].fps(), b.garments[g].fps());
    EXPECT_EQ(a.garments[g].triangles(), b.garments[g].triangles());
    ASSERT_EQ(a.garments[g].frameCount(), b.garments[g].frameCount());
    ASSERT_EQ(a.stretch[g].size(), b.stretch[g].size());
    for (size_t f = 0; f < a.garments[g].frameCount(); ++f) {
      EXPECT_EQ(bits(a.garments[g].frame(f)), bits(b.garments[g].frame(f))) << "garment " << g << " frame " << f;
      EXPECT_EQ(bits(a.stretch[g][f]), bits(b.stretch[g][f])) << "garment " << g << " frame " << f;
    }
  }
}

TEST(BakeCache, RoundTripIsBitExact) {
  const BakeCache cache = twoGarments();
  const fs::path path = scratch("two.mqbake");
  writeBakeCache(path.string(), cache);
  const BakeCache back = readBakeCache(path.string());
  EXPECT_EQ(back.key, cache.key);
  EXPECT_EQ(back.clip, 3);
  EXPECT_EQ(back.start, 1.25f);
  ASSERT_EQ(back.garments.size(), 2u);
  EXPECT_EQ(back.garments[1].frame(0).size(), 21u);  // 7 vertices kept apart from the first garment's 4
  EXPECT_TRUE(std::signbit(back.garments[0].frame(0)[0]));
  expectSame(back, cache);
}

TEST(BakeCache, EmptyCacheAndGarmentWithoutFramesRoundTrip) {
  const fs::path path = scratch("empty.mqbake");
  BakeCache empty;
  writeBakeCache(path.string(), empty);
  expectSame(readBakeCache(path.string()), empty);

  BakeCache unbaked;
  unbaked.key = "k";
  addGarment(unbaked, 3, 0, 24.0f, {0, 1, 2});
  writeBakeCache(path.string(), unbaked);
  expectSame(readBakeCache(path.string()), unbaked);
}

TEST(BakeCache, FileIsLittleEndianInTheDocumentedLayout) {
  const std::vector<uint8_t> bytes = smallBytes();
  ASSERT_EQ(bytes.size(), kSmallSize);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 6), "MQBAKE");
  EXPECT_EQ(std::vector<uint8_t>(bytes.begin() + 6, bytes.begin() + 14),
            (std::vector<uint8_t>{1, 0, 0, 0, 2, 0, 0, 0}));
  EXPECT_EQ(std::vector<uint8_t>(bytes.begin() + 16, bytes.begin() + 20),
            (std::vector<uint8_t>{0xFF, 0xFF, 0xFF, 0xFF}));
  EXPECT_EQ(bytes[48], 3);  // vertex count
  EXPECT_EQ(bytes[52], 2);  // frame count
}

TEST(BakeCache, EveryTruncationThrowsAClearError) {
  const std::vector<uint8_t> bytes = smallBytes();
  ASSERT_EQ(bytes.size(), kSmallSize);
  const fs::path path = scratch("truncated.mqbake");
  for (size_t length = 0; length < bytes.size(); ++length) {
    writeBytes(path, bytes, length);
    const std::string message = readError(path);
    EXPECT_NE(message.find(path.string()), std::string::npos) << length << ": " << message;
    EXPECT_NE(message.find("truncated"), std::string::npos) << length << ": " << message;
  }
  writeBytes(path, bytes);
  EXPECT_EQ(readError(path), "(no error)");
}

TEST(BakeCache, TruncationInsideTheFramesNamesTheGarment) {
  const fs::path path = scratch("cut.mqbake");
  writeBakeCache(path.string(), twoGarments());
  std::vector<uint8_t> bytes = fileBytes(path);
  writeBytes(path, bytes, bytes.size() - 10);
  EXPECT_NE(readError(path).find("garment 1 frames"), std::string::npos) << readError(path);
}

TEST(BakeCache, OtherFilesAreNotBakeCaches) {
  std::vector<uint8_t> bytes = smallBytes();
  bytes[0] = 'X';
  const fs::path path = scratch("magic.mqbake");
  writeBytes(path, bytes);
  EXPECT_NE(readError(path).find("not a Mannequin bake cache"), std::string::npos) << readError(path);
  writeBytes(path, {'{', '}'});
  EXPECT_NE(readError(path).find("not a Mannequin bake cache"), std::string::npos) << readError(path);
  EXPECT_NE(readError(scratch("missing.mqbake")).find("no such file"), std::string::npos);
}

TEST(BakeCache, NewerVersionIsRefused) {
  std::vector<uint8_t> bytes = smallBytes();
  putU32(bytes, 6, 2);
  const fs::path path = scratch("version.mqbake");
  writeBytes(path, bytes);
  EXPECT_NE(readError(path).find("unsupported bake cache version 2"), std::string::npos) << readError(path);
}

TEST(BakeCache, HugeCountsThrowBeforeAllocating) {
  const std::vector<uint8_t> good = smallBytes();
  const fs::path path = scratch("huge.mqbake");
  // Key length, garment count, triangle index count, vertex count, frame count.
  for (size_t offset : {10u, 24u, 32u, 48u, 52u}) {
    std::vector<uint8_t> bytes = good;
    putU32(bytes, offset, 0xFFFFFFFFu);
    writeBytes(path, bytes);
    const auto begin = std::chrono::steady_clock::now();
    const std::string message = readError(path);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    EXPECT_NE(message.find("truncated or corrupt"), std::string::npos) << offset << ": " << message;
    EXPECT_NE(message.find("4294967295"), std::string::npos) << offset << ": " << message;
    EXPECT_LT(seconds, 1.0) << offset;
  }
}

TEST(BakeCache, FramesWithoutVerticesAreRefused) {
  // Zero vertices would make each frame zero bytes long: the size check
  // could not bound a corrupt frame count.
  std::vector<uint8_t> bytes = smallBytes();
  putU32(bytes, 32, 0);  // no triangles, so no index is out of range
  putU32(bytes, 48, 0);
  bytes.erase(bytes.begin() + 36, bytes.begin() + 48);
  putU32(bytes, 52 - 12, 0xFFFFFFFFu);
  const fs::path path = scratch("novertices.mqbake");
  writeBytes(path, bytes);
  EXPECT_NE(readError(path).find("garment 0 has frames but no vertices"), std::string::npos) << readError(path);
}

TEST(BakeCache, TriangleIndexOutOfRangeIsRefused) {
  std::vector<uint8_t> bytes = smallBytes();
  putU32(bytes, 44, 3);  // the third index of the only triangle; 3 vertices
  const fs::path path = scratch("index.mqbake");
  writeBytes(path, bytes);
  EXPECT_NE(readError(path).find("garment 0: triangle index 3 is out of range (3 vertices)"), std::string::npos)
      << readError(path);

  BakeCache cache = small();
  cache.garments[0] = BakedCloth({0, 1, 5}, 24.0f);
  for (size_t f = 0; f < 2; ++f) cache.garments[0].addFrame(small().garments[0].frame(f));
  EXPECT_THROW(writeBakeCache(scratch("index-write.mqbake").string(), cache), Error);
}

TEST(BakeCache, NonFiniteValuesAreRefused) {
  const fs::path path = scratch("nan.mqbake");
  std::vector<uint8_t> bytes = smallBytes();
  putF32(bytes, 56 + 4 * (9 + 4), std::nanf(""));  // frame 1, vertex 1, y
  writeBytes(path, bytes);
  EXPECT_NE(readError(path).find("garment 0 frame 1: a position is not finite"), std::string::npos) << readError(path);

  bytes = smallBytes();
  putF32(bytes, 128, INFINITY);  // stretch frame 0, vertex 0
  writeBytes(path, bytes);
  EXPECT_NE(readError(path).find("garment 0 frame 0: a stretch value is not finite"), std::string::npos)
      << readError(path);

  bytes = smallBytes();
  putF32(bytes, 28, std::nanf(""));  // fps
  writeBytes(path, bytes);
  EXPECT_NE(readError(path).find("garment 0: fps"), std::string::npos) << readError(path);
}

TEST(BakeCache, TrailingBytesAreRefused) {
  std::vector<uint8_t> bytes = smallBytes();
  bytes.push_back(0);
  const fs::path path = scratch("trailing.mqbake");
  writeBytes(path, bytes);
  EXPECT_NE(readError(path).find("1 unexpected bytes after the last garment"), std::string::npos) << readError(path);
}

// Each inconsistency the writer must refuse, with what its message says.
TEST(BakeCache, WriterRefusesInconsistentCaches) {
  const fs::path path = scratch("invalid.mqbake");
  const auto refusal = [&](const BakeCache& cache) -> std::string {
    try {
      writeBakeCache(path.string(), cache);
    } catch (const Error& e) {
      return e.what();
    }
    return "(no error)";
  };
  EXPECT_EQ(refusal(small()), "(no error)");

  BakeCache c = small();
  std::vector<float> shortFrame = c.garments[0].frame(0);
  shortFrame.pop_back();
  c.garments[0].addFrame(shortFrame);
  c.stretch[0].push_back(c.stretch[0][0]);
  EXPECT_NE(refusal(c).find("garment 0 frame 2: 8 position floats, expected 3 x 3 vertices"), std::string::npos)
      << refusal(c);

  c = small();
  c.stretch[0].pop_back();
  EXPECT_NE(refusal(c).find("garment 0: 1 stretch frames for 2 frames"), std::string::npos) << refusal(c);

  c = small();
  c.stretch[0][1].push_back(1.0f);
  EXPECT_NE(refusal(c).find("garment 0 frame 1: 4 stretch values"), std::string::npos) << refusal(c);

  c = small();
  c.stretch.clear();
  EXPECT_NE(refusal(c).find("0 stretch lists for 1 garments"), std::string::npos) << refusal(c);

  c = small();
  c.garments[0] = BakedCloth({0, 1, 2}, NAN);
  c.stretch[0].clear();
  EXPECT_NE(refusal(c).find("garment 0: fps nan is not a positive finite number"), std::string::npos) << refusal(c);

  c = small();
  c.start = INFINITY;
  EXPECT_NE(refusal(c).find("the start time is not finite"), std::string::npos) << refusal(c);
}

TEST(BakeCache, FailedWriteKeepsTheOldFile) {
  const fs::path dir = scratch("keep");
  fs::create_directories(dir);
  const fs::path path = dir / "shirt.mqbake";
  writeBakeCache(path.string(), twoGarments());
  const std::vector<uint8_t> before = fileBytes(path);

  BakeCache invalid = small();
  invalid.stretch[0].pop_back();
  EXPECT_THROW(writeBakeCache(path.string(), invalid), Error);
  EXPECT_EQ(fileBytes(path), before);
  expectSame(readBakeCache(path.string()), twoGarments());
  // Nothing left beside it (writeFileAtomically's temporary file).
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);

  // A folder that does not exist: the write itself fails and names the file.
  const std::string nowhere = (dir / "no-such-folder" / "shirt.mqbake").string();
  try {
    writeBakeCache(nowhere, small());
    ADD_FAILURE() << "wrote into a missing folder";
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), nowhere);
  }
}

TEST(BakeCache, PathIsBesideTheDocument) {
  EXPECT_EQ(bakeCachePath("a/b/shirt.mqscene"), "a/b/shirt.mqbake");
  EXPECT_EQ(bakeCachePath("/home/me/shirt.v2.mqscene"), "/home/me/shirt.v2.mqbake");
  EXPECT_EQ(bakeCachePath("a/b/shirt"), "a/b/shirt.mqbake");
  EXPECT_EQ(bakeCachePath("a.d/shirt"), "a.d/shirt.mqbake");  // a dot in a folder is no extension
  EXPECT_EQ(bakeCachePath("shirt.mqscene"), "shirt.mqbake");
}

}  // namespace
}  // namespace mq
