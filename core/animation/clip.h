#pragma once
// An animation clip: tracks that drive bones' translation, rotation and scale
// and meshes' morph weights, sampled on the clip's own time axis.

#include <string>
#include <vector>

#include "core/animation/track.h"
#include "core/skeleton/skeleton.h"

namespace mq {

struct BoneChannel {
  int bone = -1;
  Track translation;  // empty when not animated
  Track rotation;
  Track scale;
};

struct MorphChannel {
  int mesh = -1;  // index into Character::meshes
  Track weights;  // components = the mesh's morph target count
};

enum class WrapMode { Clamp, Loop };

class Clip {
 public:
  std::string name;
  std::vector<BoneChannel> boneChannels;
  std::vector<MorphChannel> morphChannels;
  WrapMode wrap = WrapMode::Clamp;

  // Earliest and latest key time over all tracks.
  float startTime() const;
  float endTime() const;
  float duration() const { return endTime() - startTime(); }

  // Maps a playback time onto the clip's axis (clamp, or loop over
  // [start, end)).
  float wrapTime(float t) const;
  // Overwrites the animated parts of `pose` with the clip's values at t
  // (t on the clip's own axis; each track clamps to its own keys).
  void applyToPose(float t, Pose& pose) const;
  // Overwrites morph weights of animated meshes; meshWeights[mesh][target].
  void applyToMorphWeights(float t, std::vector<std::vector<float>>& meshWeights) const;
  void validate() const;  // throws std::invalid_argument
};

}  // namespace mq
