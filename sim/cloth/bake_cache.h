#pragma once
// A garment bake saved beside its document ("shirt.mqscene" ->
// "shirt.mqbake"), so reopening the document shows the bake without
// simulating the clip again. The cache carries the key of the scene state
// it was baked from; a reader uses it only while the key still matches.
//
// File layout, all little-endian (uint32 counts, IEEE float32 values):
//   "MQBAKE", uint32 version (1)
//   uint32 key length, key bytes
//   int32 clip, float32 start
//   uint32 garment count, then per garment:
//     float32 fps
//     uint32 triangle index count, uint32 indices
//     uint32 vertex count V, uint32 frame count F
//     F frames of 3V floats (x y z per vertex)
//     F stretch frames of V floats

#include <string>
#include <vector>

#include "sim/cloth/baked_cloth.h"

namespace mq::cloth {

struct BakeCache {
  // Opaque to the cache: the editor computes it from everything the bake
  // depends on (garment JSON, character, clip, fps) and compares it on load.
  std::string key;
  int clip = -1;    // the clip baked, -1 for none
  float start = 0;  // seconds into the clip of the first frame
  std::vector<BakedCloth> garments;
  // Per-vertex stretch of each garment at each frame: [garment][frame][vertex],
  // as many frames as the garment's BakedCloth and one value per vertex.
  std::vector<std::vector<std::vector<float>>> stretch;
};

// Writes `cache` to `path` through writeFileAtomically: the file is either
// the complete new cache or left as it was. Throws FileError naming `path`
// when the cache is inconsistent (a frame not 3 floats per vertex, stretch
// frames not matching the frames, a triangle index out of range, a value or
// fps not finite) or cannot be written.
void writeBakeCache(const std::string& path, const BakeCache& cache);

// Reads a cache written by writeBakeCache. Throws FileError naming `path`
// and the problem: missing file, not a bake cache, unsupported version,
// truncated or corrupt counts, triangle indices out of range, values not
// finite, trailing bytes. Counts are checked against the file's size before
// anything is allocated for them.
BakeCache readBakeCache(const std::string& path);

// The cache beside a document: the extension replaced by ".mqbake"
// ("a/b/shirt.mqscene" -> "a/b/shirt.mqbake"), or appended when there is none.
std::string bakeCachePath(const std::string& documentPath);

}  // namespace mq::cloth
