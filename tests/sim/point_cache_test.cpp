// Point Cache 2 and MDD files (sim/cloth/point_cache.h) and the bake's export as one.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/util/error.h"
#include "sim/cloth/baked_cloth.h"
#include "sim/cloth/point_cache.h"

namespace mq::cloth {
namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path = fs::temp_directory_path() /
                  ("mannequin_pc2_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
};

std::vector<char> bytesOf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const fs::path& p, const std::vector<char>& bytes) {
  std::ofstream(p, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

PointCache twoFrames() {
  PointCache cache;
  cache.pointCount = 3;
  cache.samples = {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, -0.5f, 0, 1, -0.5f, 0, 0.25f, 0.5f, 1e-30f}};
  return cache;
}

TEST(PointCache, RoundTripIsExactAndTheHeaderIsPc2s) {
  TempDir dir;
  const fs::path file = dir.path / "cloth.pc2";
  writePointCache(file.string(), twoFrames());
  const std::vector<char> bytes = bytesOf(file);
  ASSERT_EQ(bytes.size(), 32u + 2 * 3 * 12);
  EXPECT_EQ(std::memcmp(bytes.data(), "POINTCACHE2\0", 12), 0);
  int32_t header[2];
  std::memcpy(header, bytes.data() + 12, 8);
  EXPECT_EQ(header[0], 1);  // version
  EXPECT_EQ(header[1], 3);  // points
  const PointCache back = readPointCache(file.string());
  EXPECT_EQ(back.pointCount, 3u);
  EXPECT_EQ(back.startFrame, 1.0f);
  EXPECT_EQ(back.sampleRate, 1.0f);
  EXPECT_EQ(back.samples, twoFrames().samples);
}

TEST(PointCache, DamagedFilesAreRefusedWithTheirProblem) {
  TempDir dir;
  const fs::path good = dir.path / "good.pc2", bad = dir.path / "bad.pc2";
  writePointCache(good.string(), twoFrames());
  const std::vector<char> bytes = bytesOf(good);
  auto problem = [&](const std::vector<char>& damaged) {
    writeBytes(bad, damaged);
    try {
      readPointCache(bad.string());
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find("bad.pc2"), std::string::npos) << e.what();
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  for (size_t length = 0; length < bytes.size(); ++length)
    EXPECT_NE(problem({bytes.begin(), bytes.begin() + long(length)}), "accepted") << "cut at " << length;
  std::vector<char> damaged = bytes;
  damaged[0] = 'X';
  EXPECT_NE(problem(damaged).find("not a Point Cache 2"), std::string::npos);
  damaged = bytes;
  const int32_t huge = 0x7fffffff;
  std::memcpy(damaged.data() + 16, &huge, 4);  // points
  EXPECT_NE(problem(damaged).find("need"), std::string::npos);
  damaged = bytes;
  const float nan = NAN;
  std::memcpy(damaged.data() + 32 + 8, &nan, 4);
  EXPECT_NE(problem(damaged).find("non-finite"), std::string::npos);
  damaged = bytes;
  damaged.push_back(0);
  EXPECT_NE(problem(damaged), "accepted");
  // No points and a billion samples (found by fuzzing): the samples take no
  // bytes, so the size check cannot bound them; refused before allocating.
  damaged.assign(bytes.begin(), bytes.begin() + 32);
  const int32_t none = 0, billion = 1000000000;
  std::memcpy(damaged.data() + 16, &none, 4);
  std::memcpy(damaged.data() + 28, &billion, 4);
  EXPECT_NE(problem(damaged).find("1000000000 samples of no points"), std::string::npos);
}

TEST(PointCache, MddRoundTripIsExactAndBigEndian) {
  TempDir dir;
  const fs::path file = dir.path / "cloth.mdd";
  writeMdd(file.string(), twoFrames(), 24.0f);
  const std::vector<char> bytes = bytesOf(file);
  ASSERT_EQ(bytes.size(), 8u + 2 * 4 + 2 * 3 * 12);
  EXPECT_EQ(bytes[3], 2);  // frames, big-endian
  EXPECT_EQ(bytes[7], 3);  // points
  uint32_t secondTime = 0;
  for (int k = 0; k < 4; ++k) secondTime = secondTime << 8 | uint8_t(bytes[12 + k]);
  EXPECT_EQ(std::bit_cast<float>(secondTime), 1.0f / 24.0f);
  const PointCache back = readMdd(file.string());
  EXPECT_EQ(back.pointCount, 3u);
  EXPECT_EQ(back.samples, twoFrames().samples);
  for (size_t length : {size_t(0), size_t(7), size_t(12), bytes.size() - 1}) {
    writeBytes(dir.path / "cut.mdd", {bytes.begin(), bytes.begin() + long(length)});
    EXPECT_THROW(readMdd((dir.path / "cut.mdd").string()), FileError) << "cut at " << length;
  }
  std::vector<char> damaged = bytes;
  damaged[4] = 0x7f;  // a huge point count
  writeBytes(dir.path / "huge.mdd", damaged);
  EXPECT_THROW(readMdd((dir.path / "huge.mdd").string()), FileError);
}

TEST(PointCache, SampleOfTheWrongSizeIsNotWritten) {
  TempDir dir;
  PointCache cache = twoFrames();
  cache.samples[1].pop_back();
  EXPECT_THROW(writePointCache((dir.path / "x.pc2").string(), cache), Error);
  EXPECT_FALSE(fs::exists(dir.path / "x.pc2"));
}

TEST(PointCache, BakeExportsTheCacheAndTheMeshItDeforms) {
  TempDir dir;
  BakedCloth baked({0, 1, 2}, 24.0f);
  for (const std::vector<float>& frame : twoFrames().samples) baked.addFrame(frame);
  baked.exportPointCache((dir.path / "out").string(), "garment0_T-shirt");
  const PointCache cache = readPointCache((dir.path / "out" / "garment0_T-shirt.pc2").string());
  EXPECT_EQ(cache.samples, twoFrames().samples);
  EXPECT_EQ(cache.startFrame, 1.0f);
  std::ifstream obj(dir.path / "out" / "garment0_T-shirt.obj");
  std::string text((std::istreambuf_iterator<char>(obj)), {});
  EXPECT_NE(text.find("v 0.000000 0.000000 0.000000\nv 1.000000 0.000000 0.000000"), std::string::npos);  // frame 1
  EXPECT_NE(text.find("f 1 2 3"), std::string::npos);
}

}  // namespace
}  // namespace mq::cloth
