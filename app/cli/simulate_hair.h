#pragma once
// The hair part of `mannequin-cli simulate`: when the scene document has a
// "hair" section, its guides are simulated as the character plays its clip
// (roots on the skinned scalp, collisions with the body proxies, children
// following), alongside the cloth or alone.

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "app/cli/command.h"
#include "core/scene/open_scene.h"

namespace mq::cli {

// simulate's hair options: --hair-volume V and --hair-friction F override the
// style's dynamics (0 .. 1), --hair-wisps adaptive|all its adaptive wisps;
// --hair-crossings counts, every frame, the pairs
// of guide segments of different strands closer than half the guides' root
// spacing, into hair_close_guide_pairs_* (beside the groom's own count:
// what the motion adds is hair pressed into hair).
struct HairRunOptions {
  float volume = -1.0f, friction = -1.0f;  // < 0: the document's
  bool countCrossings = false;
  int adaptiveWisps = -1;  // --hair-wisps adaptive (1) or all (0); -1: the document's
};
HairRunOptions hairRunOptions(const Args& args);

// Steps the hair for `frames` frames of 1/fps from the document's time (after
// settling at that pose), adds the hair_* keys to `stats`, writes
// hair_NNNN.ply polylines into exportDir (when not empty) and prints a line.
void simulateSceneHair(const LoadedScene& scene, int frames, float fps, const std::string& exportDir,
                       const HairRunOptions& options, nlohmann::json& stats);

// `simulate` for a scene with hair and no cloth: the same options (--fps,
// default 60), the same stats file with the scene keys and the hair keys.
int simulateHairOnly(const LoadedScene& scene, const std::string& path, int frames, const Args& args);

}  // namespace mq::cli
