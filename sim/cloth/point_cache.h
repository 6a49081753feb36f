#pragma once
// Point caches: every frame's vertex positions of one mesh, the
// format Blender's Mesh Cache modifier, 3ds Max and Maya read to play a
// simulated cloth on the mesh it was exported with.
//
// Layout, little-endian: "POINTCACHE2\0", int32 version (1), int32 point
// count, float32 start frame, float32 sample rate (frames between samples),
// int32 sample count, then sample count x point count x (x, y, z) float32.

#include <string>
#include <vector>

#include "core/io/baked_surface.h"

namespace mq::cloth {

struct PointCache {
  float startFrame = 1.0f;
  float sampleRate = 1.0f;
  size_t pointCount = 0;
  std::vector<std::vector<float>> samples;  // 3 floats per point each
};

// Atomic (temporary file, then rename). Throws FileError naming the path,
// or Error when a sample's size does not fit the point count.
void writePointCache(const std::string& path, const PointCache& cache);
// Strict: throws FileError naming the path and the problem (not a PC2 file,
// another version, counts the file is too short for, non-finite values,
// trailing bytes).
PointCache readPointCache(const std::string& path);

// MDD, LightWave's point cache, which Blender's Mesh Cache modifier also
// reads. Big-endian: int32 frame count, int32 point count, float32 time of
// each frame (seconds, frame f at f / fps), then frames x points x (x, y, z)
// float32. Atomic; throws as writePointCache does.
void writeMdd(const std::string& path, const PointCache& cache, float fps);
// Strict like readPointCache; the frame times are checked to increase.
PointCache readMdd(const std::string& path);

// Baked surfaces (a take's garments and hair) as point caches: for `path`
// DIR/NAME.pc2 or DIR/NAME.mdd, per surface DIR/NAME_<surface>.pc2 (or .mdd)
// with every frame, and DIR/NAME_<surface>.obj, the mesh it deforms. Creates
// DIR. Returns the path of each cache written, without its extension.
// Throws Error for another extension, FileError for a file or folder that
// cannot be written.
std::vector<std::string> writeSurfacePointCaches(const std::vector<BakedSurface>& surfaces, const std::string& path,
                                                 float fps);

}  // namespace mq::cloth
