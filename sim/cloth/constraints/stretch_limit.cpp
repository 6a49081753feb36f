#include "sim/cloth/constraints/stretch_limit.h"

#include <algorithm>
#include <cmath>

#include "sim/cloth/parallel.h"

namespace mq::cloth {

namespace {

// Largest (|x_a - x_b| / rest)^2 over the first `count` springs, in 64 fixed
// blocks (in parallel when large): no square root per spring.
float maxSquaredStretchOf(const std::vector<glm::vec3>& x, const std::vector<Spring>& springs, size_t count) {
  constexpr size_t kBlocks = 64;
  float partial[kBlocks];
  std::fill(partial, partial + kBlocks, 0.0f);
  const size_t block = (count + kBlocks - 1) / kBlocks;
  auto body = [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) {
      float m = 0.0f;
      for (size_t i = b * block; i < std::min(count, (b + 1) * block); ++i) {
        const Spring& s = springs[i];
        const glm::vec3 d = x[s.a] - x[s.b];
        const float rest2 = s.rest * s.rest;
        if (rest2 > 0.0f) m = std::max(m, glm::dot(d, d) / rest2);
      }
      partial[b] = m;
    }
  };
  if (count < 2 * kParallelGrain)
    body(0, kBlocks);
  else
    ThreadPool::shared().parallelFor(0, kBlocks, 1, body);
  return *std::max_element(partial, partial + kBlocks);
}

}  // namespace

float maxStretchOf(const std::vector<glm::vec3>& x, const std::vector<Spring>& springs, size_t count) {
  return std::sqrt(maxSquaredStretchOf(x, springs, count));
}

StretchLimitResult limitStretchByPositions(ClothState& s, const std::vector<Spring>& springs, size_t count,
                                           float maxStretch, int maxPasses, float h) {
  StretchLimitResult result;
  const float maxSquared = maxStretch * maxStretch;
  float worstSquared = maxSquaredStretchOf(s.x, springs, count);
  result.maxStretchBefore = result.maxStretchAfter = std::sqrt(worstSquared);
  if (worstSquared <= maxSquared) return result;
  const std::vector<glm::vec3> before = s.x;
  // Aim a hair below the limit so rounding leaves every spring within it.
  const float target = maxStretch * (1.0f - 1e-3f);
  // Symmetric Gauss-Seidel: forward and backward passes alternate, so a
  // correction travels across the cloth in both directions. Most springs are
  // within the limit: compared squared, they cost no square root.
  // Each pass tracks the worst spring it meets (before correcting it); the
  // whole cloth is re-measured only when a pass met none beyond the limit
  // (a later correction in that pass may still have stretched an earlier
  // spring a little), not after every pass.
  bool measured = true;
  while (result.passes < maxPasses && worstSquared > maxSquared) {
    const bool forward = result.passes % 2 == 0;
    float passWorst = 0.0f;
    for (size_t k = 0; k < count; ++k) {
      const Spring& sp = springs[forward ? k : count - 1 - k];
      const glm::vec3 d = s.x[sp.a] - s.x[sp.b];
      const float l2 = glm::dot(d, d), limit = target * sp.rest;
      if (l2 <= limit * limit) continue;
      const float wa = s.invMass[sp.a], wb = s.invMass[sp.b];
      if (wa + wb == 0.0f) continue;
      passWorst = std::max(passWorst, l2 / (sp.rest * sp.rest));
      const float l = std::sqrt(l2);
      const glm::vec3 correction = ((l - limit) / (l * (wa + wb))) * d;
      s.x[sp.a] -= wa * correction;
      s.x[sp.b] += wb * correction;
    }
    ++result.passes;
    measured = false;
    worstSquared = passWorst;
    if (worstSquared <= maxSquared) {
      worstSquared = maxSquaredStretchOf(s.x, springs, count);
      measured = true;
    }
  }
  if (!measured) worstSquared = maxSquaredStretchOf(s.x, springs, count);
  result.maxStretchAfter = std::sqrt(worstSquared);
  forRange(s.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) s.v[i] += (s.x[i] - before[i]) / h;
  });
  return result;
}

StretchLimitResult limitStretchByVelocities(ClothState& s, const std::vector<glm::vec3>& x0,
                                            const std::vector<Spring>& springs, size_t count, float maxStretch,
                                            int maxPasses, float h) {
  StretchLimitResult result;
  result.maxStretchBefore = maxStretchOf(s.x, springs, count);
  result.maxStretchAfter = result.maxStretchBefore;
  for (; result.passes < maxPasses && result.maxStretchAfter > maxStretch; ++result.passes) {
    for (size_t i = 0; i < count; ++i) {
      const Spring& sp = springs[i];
      const glm::vec3 d = s.x[sp.a] - s.x[sp.b];
      const float l = glm::length(d);
      if (l <= maxStretch * sp.rest) continue;
      const float wa = s.invMass[sp.a], wb = s.invMass[sp.b];
      if (wa + wb == 0.0f) continue;
      const glm::vec3 dir = d / l;
      const float lengthening = glm::dot(s.v[sp.a] - s.v[sp.b], dir);
      if (lengthening <= 0.0f) continue;
      const glm::vec3 dv = (lengthening / (wa + wb)) * dir;
      s.v[sp.a] -= wa * dv;
      s.v[sp.b] += wb * dv;
      s.x[sp.a] = x0[sp.a] + h * s.v[sp.a];
      s.x[sp.b] = x0[sp.b] + h * s.v[sp.b];
    }
    result.maxStretchAfter = maxStretchOf(s.x, springs, count);
  }
  return result;
}

}  // namespace mq::cloth
