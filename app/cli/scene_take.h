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

// The clip time of frame 0 of a take (one step after the document's time).
inline float takeStart(const LoadedScene& scene, float fps) { return scene.document.time + 1.0f / fps; }

}  // namespace mq::cli
