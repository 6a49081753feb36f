#pragma once
// How a garment gets from its pattern placement onto a posed, animated body
// (the editor's Simulate and Bake, and `mannequin-cli render`): the panels
// start around the body in its rest pose, so the body stays there while the
// seams sew (at least kMinSewingSeconds, until they weld or the sewing time
// runs out), then moves to the wanted pose over kBlendSeconds, slowly enough
// for the cloth to follow the limbs instead of the limbs leaving it behind.

#include <algorithm>
#include <vector>

#include "sim/garment/garment_simulation.h"

namespace mq::cloth {

class DrapeSchedule {
 public:
  static constexpr float kMinSewingSeconds = 0.5f;
  static constexpr float kBlendSeconds = 1.0f;
  // Seams that never weld are called sewn this long after the sewing time limit.
  static constexpr float kSewingGraceSeconds = 0.25f;

  explicit DrapeSchedule(float maxSewingSeconds = GarmentSimulationSettings{}.maxSewingSeconds)
      : maxSewing_(maxSewingSeconds) {}

  // The weight of the wanted pose (0 = rest) for the next step of dt seconds.
  float advance(const GarmentSimulation& simulation, float dt) {
    const bool sewn = simulation.welded() || sewing_ >= maxSewing_ + kSewingGraceSeconds;
    if (blending_ == 0.0f && (!sewn || sewing_ < kMinSewingSeconds)) {
      sewing_ += dt;
      return 0.0f;
    }
    blending_ += dt;
    return std::min(1.0f, blending_ / kBlendSeconds);
  }
  // The sewing part is over: the next advance() starts moving the body.
  bool sewingDone(const GarmentSimulation& simulation) const {
    const bool sewn = simulation.welded() || sewing_ >= maxSewing_ + kSewingGraceSeconds;
    return blending_ > 0.0f || (sewn && sewing_ >= kMinSewingSeconds);
  }
  // For a simulation restored from a sewn state (GarmentSimulation::restore):
  // the body starts moving with the next step.
  void skipSewing() { sewing_ = std::max(sewing_, kMinSewingSeconds); }
  // For a simulation started from a drape on the wanted pose
  // (GarmentSimulation::startFromDrape): it follows the clip at once.
  void skipToPose() {
    skipSewing();
    blending_ = kBlendSeconds;
  }
  // On the wanted pose: the body follows the clip from here on.
  bool draped() const { return blending_ >= kBlendSeconds; }
  // Upper bound of the steps of dt before draped().
  int maxSteps(float dt) const { return int((maxSewing_ + kSewingGraceSeconds + kBlendSeconds) / dt) + 2; }

 private:
  float maxSewing_;
  float sewing_ = 0.0f;
  float blending_ = 0.0f;
};

// rest + weight * (target - rest), per coordinate (rest when the sizes differ).
inline void blendBody(const std::vector<float>& rest, const std::vector<float>& target, float weight,
                      std::vector<float>& out) {
  if (target.size() != rest.size() || weight <= 0.0f) {
    out = rest;
    return;
  }
  out.resize(rest.size());
  for (size_t i = 0; i < rest.size(); ++i) out[i] = rest[i] + weight * (target[i] - rest[i]);
}

}  // namespace mq::cloth
