#pragma once
// A baked cloth animation: the cloth's positions at every frame, for
// scrubbing in the editor and for export as an OBJ sequence (what Blender
// and other tools import as a mesh cache).

#include <cstdint>
#include <string>
#include <vector>

namespace mq::cloth {

class BakedCloth {
 public:
  BakedCloth() = default;
  BakedCloth(std::vector<uint32_t> triangles, float fps) : triangles_(std::move(triangles)), fps_(fps) {}

  void addFrame(std::vector<float> positions) { frames_.push_back(std::move(positions)); }
  size_t frameCount() const { return frames_.size(); }
  const std::vector<float>& frame(size_t i) const { return frames_.at(i); }
  // The frame shown at time t (nearest earlier frame, clamped).
  const std::vector<float>& frameAt(double seconds) const;
  const std::vector<uint32_t>& triangles() const { return triangles_; }
  float fps() const { return fps_; }

  // Writes <dir>/<stem>_0001.obj ... one per frame; creates dir. Throws FileError.
  void exportObjSequence(const std::string& dir, const std::string& stem = "cloth") const;
  // Writes every frame as one Point Cache 2 file, <dir>/<stem>.pc2 (frame 1
  // first, one sample a frame), and the mesh it deforms as <dir>/<stem>.obj
  // (frame 1): in Blender, import the OBJ and give it a Mesh Cache modifier
  // reading the PC2. Creates dir. Throws FileError.
  void exportPointCache(const std::string& dir, const std::string& stem = "cloth") const;

 private:
  std::vector<uint32_t> triangles_;
  std::vector<std::vector<float>> frames_;
  float fps_ = 24.0f;
};

// One OBJ file of a triangle mesh (positions only). Throws FileError.
void writeObj(const std::string& path, const std::vector<float>& positions, const std::vector<uint32_t>& triangles);
std::string objFrameName(const std::string& stem, size_t frameNumber);  // "cloth_0001.obj"
// The file stem of garment `index` named `name` in an exported sequence:
// "garment0_T-shirt" (characters other than letters, digits and '-' become '_').
std::string garmentFileStem(const std::string& name, size_t index);

}  // namespace mq::cloth
