#pragma once
// A rigger's report on a skinning method: the skin metrics (skin_metrics.h)
// on standard test poses of a humanoid (bones found by role, so any humanoid
// rig works) and over each clip. The poses bend the left limbs about world
// axes through their joints (children follow); a character that is not a
// humanoid gets the clip measures alone and a note saying why.

#include <string>
#include <vector>

#include "core/character/character.h"

namespace mq {

class ThreadPool;

struct PoseMeasure {
  std::string name;            // "elbow 120", "wrist twist 180", ...
  double thickness = -1.0;     // M1 outer thickness ratio (-1: not measured)
  double halfArea = -1.0;      // M1 outer half-section area ratio
  double twistSection = -1.0;  // M2 least section ratio in the twist band
  double localVolume = -1.0;   // M3
  long intersections = -1;     // M4 pairs (-1: not measured)
  double deviationRms = -1.0;  // M6 RMS distance to the posed implicit body, metres (-1: not measured)
  double deviationMean = 0.0;  // M6 mean (negative: sunk in)
};

struct ClipMeasure {
  std::string name;
  int frames = 0;
  long worstIntersections = 0;  // M4 over the frames
  double meanIntersections = 0.0;
  float worstTime = 0.0f;
  double minVolume = 1.0, maxVolume = 1.0;  // M3': whole-body volume / rest
};

struct SkinReport {
  std::string method;
  size_t vertices = 0, triangles = 0;  // of the welded body
  double restError = 0.0;              // largest |rest pose - rest mesh| / bounding-box diagonal
  std::vector<PoseMeasure> poses;
  std::vector<ClipMeasure> clips;
  std::vector<std::string> notes;  // what could not be measured, and why
};

struct SkinReportOptions {
  static constexpr int kEveryClip = -2;
  bool poses = true;
  bool clips = true;
  // Which clip "clips" measures: every one, one clip's index, or -1 for the
  // rest pose with `edits` (one frame, reported as the clip "rest").
  int clip = kEveryClip;
  const PoseEdits* edits = nullptr;
  bool intersections = true;  // M4 (the slowest measure)
  float clipFps = 30.0f;
};

// Measures `character` with its own skinning method.
SkinReport measureSkinning(const Character& character, const SkinReportOptions& options, ThreadPool* pool);

// The local pose with `bone` turned by `degrees` about the world axis through
// its joint (its children follow): local' = local * (W^-1 q W), W the bone's
// world rotation in `pose`.
void rotateBoneAboutWorldAxis(const Skeleton& skeleton, Pose& pose, int bone, const glm::vec3& worldAxis,
                              float degrees);

}  // namespace mq
