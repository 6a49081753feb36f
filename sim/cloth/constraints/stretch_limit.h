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

StretchLimitResult limitStretchByVelocities(ClothState& s, const std::vector<glm::vec3>& x0,
                                            const std::vector<Spring>& springs, size_t count, float maxStretch,
                                            int maxPasses, float h);

// Largest |x_a - x_b| / rest over the first `count` springs.
float maxStretchOf(const std::vector<glm::vec3>& x, const std::vector<Spring>& springs, size_t count);

}  // namespace mq::cloth
