#pragma once
// The frames of a scene document simulated for an animated export
// (`export --with garments,hair`): the garments and the cloth sheet sewn,
// dressed and stepped as `simulate` steps them, the hair groomed, settled and
// stepped as `simulate` does; each recorded as a BakedSurface. Frame f is the
// state after f + 1 steps of 1/fps from the document's time.

#include <string>
#include <vector>

#include "core/io/rigged_export.h"
#include "core/scene/open_scene.h"

namespace mq::cli {

struct TakeRequest {
  bool cloth = false;  // the garments and the sheet
  bool hair = false;
  int frames = 1;
  float fps = 30.0f;
  long hairStrands = -1;  // strands written: -1 the guides, 0 all of them, N the first N
};

// Throws FileError naming `path` when a requested part is missing or invalid.
std::vector<BakedSurface> recordSceneTake(const LoadedScene& scene, const std::string& path,
                                          const TakeRequest& request);

// The clip time of frame f of a take (f + 1 steps after the document's
// time), computed as simulate computes it: the cloth's contacts amplify a
// rounding difference in the body's pose to centimetres within a second.
inline float takeFrameTime(const LoadedScene& scene, int f, float fps) {
  return scene.document.time + float(f + 1) / fps;
}

}  // namespace mq::cli
