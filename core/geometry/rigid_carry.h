#pragma once
// Points carried along by a deforming point set: a draped garment by its
// body when the pose changes without simulating (the editor's preview while
// scrubbing). Each point follows the best rigid motion (Kabsch) of its k
// nearest points of the set, so a sleeve turns with the forearm instead of
// shearing off it as a per-vertex translation would make it.
//
//   RigidCarry carry(garmentPositions, bodyInPoseA);
//   std::vector<float> inPoseB = carry.carry(bodyInPoseB);

#include <cstdint>
#include <vector>

namespace mq {

class RigidCarry {
 public:
  // points and from: 3 floats per point. k is clamped to the set's size.
  RigidCarry(std::vector<float> points, std::vector<float> from, int k = 8);

  // The points moved as the set moved from `from` to `to` (same point
  // count); the points unchanged when `to` does not fit or equals `from`.
  // The first carry finds the neighbourhoods (not thread-safe then).
  std::vector<float> carry(const std::vector<float>& to) const;
  const std::vector<float>& points() const { return points_; }
  const std::vector<float>& from() const { return from_; }

 private:
  std::vector<float> points_, from_;
  int k_;
  mutable std::vector<uint32_t> neighbours_;  // k per point, indices into the set; found when first needed
};

}  // namespace mq
