#pragma once
// Sewing as a constraint: each seam pair's distance shrinks by at most a
// closing speed times the step, solved together with the elongation limit
// in the position pass. The seam vertices weigh less there (their inverse
// mass scaled down), so the panel behind a seam is dragged along instead of
// the seam giving way. Unlike zero-length seam springs, a wide gap cannot
// close in one step. While seams close, the elongation limit may be relaxed
// (panels bent around a body need a little more before their seams meet).

#include <cstdint>
#include <utility>
#include <vector>

#include "sim/cloth/cloth_state.h"
#include "sim/cloth/constraints/stretch_limit.h"

namespace mq::cloth {

class SeamClosing {
 public:
  using Seam = std::pair<uint32_t, uint32_t>;

  // Throws mq::Error for vertices out of range, a speed that is not
  // positive, or a relief below 1.
  void start(const std::vector<Seam>& seams, float closingSpeed, float stretchRelief, size_t vertexCount);
  void stop() { seams_.clear(); }
  bool active() const { return !seams_.empty(); }
  // The elongation limit while sewing: maxStretch times the relief.
  float maxStretch(float maxStretch) const { return active() ? maxStretch * stretchRelief_ : maxStretch; }

  struct Result {
    bool held = true;  // the elongation limit held after the last round
    int passes = 0;    // elongation-limit passes spent
  };
  // Gauss-Seidel over the seam pairs (each no farther apart than at the
  // step's start, `stepStart`, minus the closing distance) and, when
  // `limiter` is given, the elongation limit with `passBudget` passes in all.
  // Positions only: the velocities keep no memory of the pull.
  Result close(ClothState& state, const std::vector<glm::vec3>& stepStart, StretchLimiter* limiter, float maxStretch,
               int passBudget, float h, float seamInvMassScale) const;

 private:
  std::vector<Seam> seams_;
  float speed_ = 0.0f;  // m/s
  float stretchRelief_ = 1.0f;
};

}  // namespace mq::cloth
