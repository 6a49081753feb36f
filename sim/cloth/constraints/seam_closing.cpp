#include "sim/cloth/constraints/seam_closing.h"

#include <algorithm>
#include <cmath>

#include "core/util/error.h"

namespace mq::cloth {

void SeamClosing::start(const std::vector<Seam>& seams, float closingSpeed, float stretchRelief, size_t vertexCount) {
  if (!(stretchRelief >= 1.0f) || !std::isfinite(stretchRelief)) throw Error("sewing stretch relief must be >= 1");
  for (const auto& [a, b] : seams)
    if (a >= vertexCount || b >= vertexCount) throw Error("cloth seam vertex out of range");
  if (!(closingSpeed > 0.0f) || !std::isfinite(closingSpeed)) throw Error("seam closing speed must be positive");
  stretchRelief_ = stretchRelief;
  seams_ = seams;
  speed_ = closingSpeed;
}

SeamClosing::Result SeamClosing::close(ClothState& state, const std::vector<glm::vec3>& stepStart,
                                       StretchLimiter* limiter, float maxStretch, int passBudget, float h,
                                       float seamInvMassScale) const {
  const float closing = speed_ * h;
  std::vector<float> target(seams_.size());
  for (size_t k = 0; k < seams_.size(); ++k) {
    const auto [a, b] = seams_[k];
    target[k] = std::max(0.0f, glm::length(stepStart[a] - stepStart[b]) - closing);
  }
  const std::vector<float> freeInvMass = state.invMass;
  std::vector<float> heavy = state.invMass;
  for (const auto& [a, b] : seams_)
    heavy[a] = seamInvMassScale * freeInvMass[a], heavy[b] = seamInvMassScale * freeInvMass[b];
  Result result;
  constexpr int kRounds = 4;
  for (int round = 0; round < kRounds; ++round) {
    for (size_t k = 0; k < seams_.size(); ++k) {
      const auto [a, b] = seams_[k];
      const glm::vec3 d = state.x[a] - state.x[b];
      const float length = glm::length(d), wa = freeInvMass[a], wb = freeInvMass[b];
      if (length <= target[k] || wa + wb == 0.0f) continue;
      const glm::vec3 correction = (length - target[k]) / (length * (wa + wb)) * d;
      state.x[a] -= wa * correction;
      state.x[b] += wb * correction;
    }
    if (!limiter) continue;
    state.invMass = heavy;
    const StretchLimitResult r = limiter->limitByPositions(state, maxStretch, std::max(1, passBudget / kRounds), h);
    state.invMass = freeInvMass;
    result.passes += r.passes;
    result.held = r.maxStretchAfter <= maxStretch;
  }
  return result;
}

}  // namespace mq::cloth
