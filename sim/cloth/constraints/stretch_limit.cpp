#include "sim/cloth/constraints/stretch_limit.h"

#include <algorithm>

#include "sim/cloth/parallel.h"

namespace mq::cloth {

float maxStretchOf(const std::vector<glm::vec3>& x, const std::vector<Spring>& springs, size_t count) {
  constexpr size_t kBlocks = 64;
  float partial[kBlocks];
  std::fill(partial, partial + kBlocks, 0.0f);
  const size_t block = (count + kBlocks - 1) / kBlocks;
  auto body = [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) {
      float m = 0.0f;
      for (size_t i = b * block; i < std::min(count, (b + 1) * block); ++i) {
        const Spring& s = springs[i];
        if (s.rest > 0.0f) m = std::max(m, glm::length(x[s.a] - x[s.b]) / s.rest);
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

StretchLimitResult limitStretchByPositions(ClothState& s, const std::vector<Spring>& springs, size_t count,
                                           float maxStretch, int maxPasses, float h) {
  StretchLimitResult result;
  result.maxStretchBefore = maxStretchOf(s.x, springs, count);
  result.maxStretchAfter = result.maxStretchBefore;
  if (result.maxStretchBefore <= maxStretch) return result;
  const std::vector<glm::vec3> before = s.x;
  // Aim a hair below the limit so rounding leaves every spring within it.
  const float target = maxStretch * (1.0f - 1e-3f);
  // Symmetric Gauss-Seidel: forward and backward passes alternate, so a
  // correction travels across the cloth in both directions.
  for (; result.passes < maxPasses && result.maxStretchAfter > maxStretch; ++result.passes) {
    const bool forward = result.passes % 2 == 0;
    for (size_t k = 0; k < count; ++k) {
      const Spring& sp = springs[forward ? k : count - 1 - k];
      const glm::vec3 d = s.x[sp.a] - s.x[sp.b];
      const float l = glm::length(d), limit = target * sp.rest;
      if (l <= limit) continue;
      const float wa = s.invMass[sp.a], wb = s.invMass[sp.b];
      if (wa + wb == 0.0f) continue;
      const glm::vec3 correction = ((l - limit) / (l * (wa + wb))) * d;
      s.x[sp.a] -= wa * correction;
      s.x[sp.b] += wb * correction;
    }
    result.maxStretchAfter = maxStretchOf(s.x, springs, count);
  }
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
