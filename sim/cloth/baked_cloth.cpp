#include "sim/cloth/baked_cloth.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/util/error.h"
#include "sim/cloth/point_cache.h"

namespace mq::cloth {

const std::vector<float>& BakedCloth::frameAt(double seconds) const {
  if (frames_.empty()) throw Error("the baked cloth has no frames");
  const double f = std::floor(seconds * fps_ + 1e-6);
  const size_t i = f <= 0.0 ? 0 : std::min(frames_.size() - 1, size_t(f));
  return frames_[i];
}

std::string objFrameName(const std::string& stem, size_t frameNumber) {
  char name[32];
  std::snprintf(name, sizeof name, "_%04zu.obj", frameNumber);
  return stem + name;
}

std::string garmentFileStem(const std::string& name, size_t index) {
  std::string stem = "garment" + std::to_string(index);
  if (!name.empty()) stem += "_";
  for (char c : name) stem += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
  return stem;
}

void writeObj(const std::string& path, const std::vector<float>& positions, const std::vector<uint32_t>& triangles) {
  std::ofstream out(path);
  if (!out) throw FileError(path, "cannot open for writing");
  char line[96];
  for (size_t i = 0; i + 2 < positions.size(); i += 3) {
    std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n", positions[i], positions[i + 1], positions[i + 2]);
    out << line;
  }
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
    out << "f " << triangles[t] + 1 << ' ' << triangles[t + 1] + 1 << ' ' << triangles[t + 2] + 1 << '\n';
  if (!out) throw FileError(path, "write failed");
}

void BakedCloth::exportObjSequence(const std::string& dir, const std::string& stem) const {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw FileError(dir, "cannot create the directory: " + ec.message());
  for (size_t i = 0; i < frames_.size(); ++i)
    writeObj((std::filesystem::path(dir) / objFrameName(stem, i + 1)).string(), frames_[i], triangles_);
}

void BakedCloth::exportPointCache(const std::string& dir, const std::string& stem) const {
  if (frames_.empty()) throw Error("the baked cloth has no frames to export");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw FileError(dir, "cannot create the directory: " + ec.message());
  PointCache cache;
  cache.pointCount = frames_[0].size() / 3;
  cache.samples = frames_;
  writePointCache((std::filesystem::path(dir) / (stem + ".pc2")).string(), cache);
  writeObj((std::filesystem::path(dir) / (stem + ".obj")).string(), frames_[0], triangles_);
}

}  // namespace mq::cloth
