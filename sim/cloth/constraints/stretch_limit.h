#pragma once
// Provot's elongation limit ("Deformation constraints in a mass-spring model
// to describe rigid cloth behavior", Graphics Interface 1995): no structural
// spring may be longer than maxStretch times its rest length.
//
//  - Position correction (Provot): after a step, every over-long spring is
//    shortened to the limit by moving both ends toward each other (only the
//    free end when the other is pinned), repeated (Gauss-Seidel, fixed order)
//    until no spring exceeds the limit or the pass budget is spent; the
//    velocities take the same correction divided by h.
//  - Velocity correction (Vassilev, Spanlang and Chrysanthou, "Fast cloth
//    animation on walking avatars", Eurographics 2001): for an over-long
//    spring, the part of the ends' relative velocity that lengthens it is
//    removed (shared by inverse mass), then the positions are re-integrated
//    from the step's start, x = x0 + h v.
//
// `maxStretchOf()` measures the largest length / rest length.

#include <vector>

#include "sim/cloth/cloth_state.h"
#include "sim/cloth/forces/spring_force.h"

namespace mq::cloth {

struct StretchLimitResult {
  int passes = 0;
  float maxStretchBefore = 1.0f;
  float maxStretchAfter = 1.0f;
};

StretchLimitResult limitStretchByPositions(ClothState& s, const std::vector<Spring>& springs, size_t count,
                                           float maxStretch, int maxPasses, float h);

// The position correction for one cloth, with the springs around each vertex
// kept between calls. A pass visits only the springs whose ends moved since
// they were last checked (a bit set per spring, scanned in the pass's order):
// the others are known to be within the limit, so the result is that of the
// full Gauss-Seidel sweep, and where the limit cannot hold (cloth pinched
// between two body parts) the passes cost the pinched region, not the cloth.
// The squared stretch of every spring is kept too, with the positions it was
// measured at: a call (the contact rounds call it again and again with a few
// vertices moved in between) measures again only the springs at vertices
// that moved, and its first pass visits only the springs over the target.
// The springs must not change while the limiter lives.
class StretchLimiter {
 public:
  StretchLimiter() = default;
  // The first `count` springs; `springs` must outlive the limiter.
  StretchLimiter(const std::vector<Spring>& springs, size_t count, size_t vertexCount);
  StretchLimitResult limitByPositions(ClothState& s, float maxStretch, int maxPasses, float h);

 private:
  // Shortens spring k to `limit` when longer; returns its (length / rest)^2
  // before, 0 when it was within the limit or cannot move.
  float correct(ClothState& s, size_t k, float target);
  void markAround(uint32_t vertex, size_t except);
  void noteMove(const std::vector<glm::vec3>& x, uint32_t vertex);
  // The largest squared stretch at x: the springs at the vertices that moved
  // since the last measure, or all of them when many moved.
  float measure(const std::vector<glm::vec3>& x);
  float measureAll(const std::vector<glm::vec3>& x);
  float remeasureMoved(const std::vector<glm::vec3>& x);
  void remeasureAround(const std::vector<glm::vec3>& x, uint32_t vertex);
  float largestMeasured();
  void markOverTarget(float target);

  const std::vector<Spring>* springs_ = nullptr;
  size_t count_ = 0;
  std::vector<uint32_t> incidenceStart_, incidence_;  // CSR: the springs at each vertex
  std::vector<uint64_t> dirty_;                       // one bit per spring: check in a pass
  // The last measure: (length / rest)^2 per spring at the positions
  // measuredAt_, its largest per 64 springs (stale ones listed).
  std::vector<glm::vec3> measuredAt_;
  std::vector<float> squaredStretch_, wordMax_;
  std::vector<uint8_t> wordStale_;
  std::vector<uint32_t> staleWords_, changed_;
  // The vertices this call moved, with their positions before it (for the velocities).
  std::vector<uint8_t> moved_;
  std::vector<uint32_t> movedList_;
  std::vector<glm::vec3> movedFrom_;
};

StretchLimitResult limitStretchByVelocities(ClothState& s, const std::vector<glm::vec3>& x0,
                                            const std::vector<Spring>& springs, size_t count, float maxStretch,
                                            int maxPasses, float h);

// Largest |x_a - x_b| / rest over the first `count` springs.
float maxStretchOf(const std::vector<glm::vec3>& x, const std::vector<Spring>& springs, size_t count);

}  // namespace mq::cloth
