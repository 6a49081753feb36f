#include "core/animation/clip.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mq {
namespace {

template <typename F>
void forEachTrack(const Clip& clip, F&& f) {
  for (const BoneChannel& c : clip.boneChannels) {
    f(c.translation);
    f(c.rotation);
    f(c.scale);
  }
  for (const MorphChannel& m : clip.morphChannels) f(m.weights);
}

}  // namespace

float Clip::startTime() const {
  float t = std::numeric_limits<float>::max();
  forEachTrack(*this, [&](const Track& tr) {
    if (!tr.empty()) t = std::min(t, tr.startTime());
  });
  return t == std::numeric_limits<float>::max() ? 0.0f : t;
}

float Clip::endTime() const {
  float t = std::numeric_limits<float>::lowest();
  forEachTrack(*this, [&](const Track& tr) {
    if (!tr.empty()) t = std::max(t, tr.endTime());
  });
  return t == std::numeric_limits<float>::lowest() ? 0.0f : t;
}

float Clip::wrapTime(float t) const {
  const float start = startTime(), end = endTime();
  if (wrap == WrapMode::Clamp || end <= start) return std::clamp(t, start, end);
  const float length = end - start;
  float u = std::fmod(t - start, length);
  if (u < 0.0f) u += length;
  return start + u;
}

void Clip::applyToPose(float t, Pose& pose) const {
  for (const BoneChannel& c : boneChannels) {
    if (c.bone < 0 || c.bone >= static_cast<int>(pose.size())) continue;
    Trs& trs = pose[c.bone];
    if (!c.translation.empty()) c.translation.sample(t, &trs.translation.x);
    if (!c.scale.empty()) c.scale.sample(t, &trs.scale.x);
    if (!c.rotation.empty()) {
      float q[4];
      c.rotation.sample(t, q);
      trs.rotation = glm::quat(q[3], q[0], q[1], q[2]);
    }
  }
}

void Clip::applyToMorphWeights(float t, std::vector<std::vector<float>>& meshWeights) const {
  for (const MorphChannel& m : morphChannels) {
    if (m.mesh < 0 || m.mesh >= static_cast<int>(meshWeights.size())) continue;
    std::vector<float>& w = meshWeights[m.mesh];
    w.resize(m.weights.components);
    m.weights.sample(t, w.data());
  }
}

void Clip::validate() const {
  forEachTrack(*this, [](const Track& tr) { tr.validate(); });
}

}  // namespace mq
