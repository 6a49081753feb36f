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
  auto body = [&](size_t b) {
    float m = 0.0f;
    for (size_t i = b * block; i < std::min(count, (b + 1) * block); ++i) {
      const Spring& s = springs[i];
      const glm::vec3 d = x[s.a] - x[s.b];
      const float rest2 = s.rest * s.rest;
      if (rest2 > 0.0f) m = std::max(m, glm::dot(d, d) / rest2);
    }
    partial[b] = m;
  };
  if (count < 2 * kParallelGrain)
    for (size_t b = 0; b < kBlocks; ++b) body(b);
  else
    ThreadPool::shared().parallelBlocks(kBlocks, body);
  return *std::max_element(partial, partial + kBlocks);
}

}  // namespace

float maxStretchOf(const std::vector<glm::vec3>& x, const std::vector<Spring>& springs, size_t count) {
  return std::sqrt(maxSquaredStretchOf(x, springs, count));
}

StretchLimitResult limitStretchByPositions(ClothState& s, const std::vector<Spring>& springs, size_t count,
                                           float maxStretch, int maxPasses, float h) {
  StretchLimiter limiter(springs, count, s.size());
  return limiter.limitByPositions(s, maxStretch, maxPasses, h);
}

StretchLimiter::StretchLimiter(const std::vector<Spring>& springs, size_t count, size_t vertexCount)
    : springs_(&springs), count_(count) {
  std::vector<uint32_t> start(vertexCount + 1, 0);
  for (size_t k = 0; k < count; ++k) ++start[springs[k].a + 1], ++start[springs[k].b + 1];
  for (size_t v = 0; v < vertexCount; ++v) start[v + 1] += start[v];
  incidence_.resize(start[vertexCount]);
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (size_t k = 0; k < count; ++k) {
    incidence_[fill[springs[k].a]++] = uint32_t(k);
    incidence_[fill[springs[k].b]++] = uint32_t(k);
  }
  incidenceStart_ = std::move(start);
  dirty_.assign((count + 63) / 64, 0);
}

float StretchLimiter::correct(ClothState& s, size_t k, float target) {
  const Spring& sp = (*springs_)[k];
  const glm::vec3 d = s.x[sp.a] - s.x[sp.b];
  const float l2 = glm::dot(d, d), limit = target * sp.rest;
  if (l2 <= limit * limit) return 0.0f;
  const float wa = s.invMass[sp.a], wb = s.invMass[sp.b];
  if (wa + wb == 0.0f) return 0.0f;
  const float l = std::sqrt(l2);
  const glm::vec3 correction = ((l - limit) / (l * (wa + wb))) * d;
  s.x[sp.a] -= wa * correction;
  s.x[sp.b] += wb * correction;
  if (wa != 0.0f) markAround(sp.a, k);
  if (wb != 0.0f) markAround(sp.b, k);
  return l2 / (sp.rest * sp.rest);
}

void StretchLimiter::markAround(uint32_t vertex, size_t except) {
  for (uint32_t i = incidenceStart_[vertex]; i < incidenceStart_[vertex + 1]; ++i) {
    const uint32_t k = incidence_[i];
    if (k != except) dirty_[k / 64] |= uint64_t(1) << (k % 64);
  }
}

StretchLimitResult StretchLimiter::limitByPositions(ClothState& s, float maxStretch, int maxPasses, float h) {
  StretchLimitResult result;
  const std::vector<Spring>& springs = *springs_;
  const size_t count = count_;
  const float maxSquared = maxStretch * maxStretch;
  float worstSquared = maxSquaredStretchOf(s.x, springs, count);
  result.maxStretchBefore = result.maxStretchAfter = std::sqrt(worstSquared);
  if (worstSquared <= maxSquared) return result;
  const std::vector<glm::vec3> before = s.x;
  // Aim a hair below the limit so rounding leaves every spring within it.
  const float target = maxStretch * (1.0f - 1e-3f);
  // Symmetric Gauss-Seidel: forward and backward passes alternate, so a
  // correction travels across the cloth in both directions. The first pass
  // checks every spring; a correction marks the springs around the moved
  // ends, which the current pass checks when they come after it in its
  // order, the next pass otherwise.
  // Each pass tracks the worst spring it meets (before correcting it); the
  // whole cloth is re-measured only when a pass met none beyond the limit
  // (a later correction in that pass may still have stretched an earlier
  // spring a little), not after every pass.
  std::fill(dirty_.begin(), dirty_.end(), ~uint64_t(0));
  if (count % 64 != 0) dirty_.back() = (uint64_t(1) << (count % 64)) - 1;
  const size_t words = dirty_.size();
  bool measured = true;
  while (result.passes < maxPasses && worstSquared > maxSquared) {
    const bool forward = result.passes % 2 == 0;
    float passWorst = 0.0f;
    size_t checked = 0;
    for (size_t n = 0; n < words; ++n) {
      const size_t w = forward ? n : words - 1 - n;
      // Bits at or behind the pass's position in this word wait for the next pass.
      uint64_t behind = 0;
      for (uint64_t pending; (pending = dirty_[w] & ~behind) != 0;) {
        const int bit = forward ? __builtin_ctzll(pending) : 63 - __builtin_clzll(pending);
        behind = forward ? (bit == 63 ? ~uint64_t(0) : (uint64_t(2) << bit) - 1) : ~((uint64_t(1) << bit) - 1);
        dirty_[w] &= ~(uint64_t(1) << bit);
        passWorst = std::max(passWorst, correct(s, w * 64 + size_t(bit), target));
        ++checked;
      }
    }
    if (checked == 0) break;  // nothing moved since the last measure: more passes change nothing
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
