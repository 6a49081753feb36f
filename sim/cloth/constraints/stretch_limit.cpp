#include "sim/cloth/constraints/stretch_limit.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "sim/cloth/parallel.h"

namespace mq::cloth {

namespace {

constexpr size_t kMeasureBlocks = 64;

// (|x_a - x_b| / rest)^2, 0 for a spring without rest length.
inline float squaredStretchOf(const std::vector<glm::vec3>& x, const Spring& s) {
  const glm::vec3 d = x[s.a] - x[s.b];
  const float rest2 = s.rest * s.rest;
  return rest2 > 0.0f ? glm::dot(d, d) / rest2 : 0.0f;
}

// Largest (|x_a - x_b| / rest)^2 over the first `count` springs, in 64 fixed
// blocks (in parallel when large): no square root per spring.
float maxSquaredStretchOf(const std::vector<glm::vec3>& x, const std::vector<Spring>& springs, size_t count) {
  float partial[kMeasureBlocks];
  std::fill(partial, partial + kMeasureBlocks, 0.0f);
  const size_t block = (count + kMeasureBlocks - 1) / kMeasureBlocks;
  auto body = [&](size_t b) {
    float m = 0.0f;
    for (size_t i = b * block; i < std::min(count, (b + 1) * block); ++i)
      m = std::max(m, squaredStretchOf(x, springs[i]));
    partial[b] = m;
  };
  if (count < 2 * kParallelGrain)
    for (size_t b = 0; b < kMeasureBlocks; ++b) body(b);
  else
    ThreadPool::shared().parallelBlocks(kMeasureBlocks, body);
  return *std::max_element(partial, partial + kMeasureBlocks);
}

bool samePosition(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof(glm::vec3)) == 0; }

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
  const size_t words = (count + 63) / 64;
  dirty_.assign(words, 0);
  squaredStretch_.assign(count, 0.0f);
  wordMax_.assign(words, 0.0f);
  wordStale_.assign(words, 0);
  movedFrom_.resize(vertexCount);
  moved_.assign(vertexCount, 0);
}

float StretchLimiter::measureAll(const std::vector<glm::vec3>& x) {
  const std::vector<Spring>& springs = *springs_;
  const size_t words = wordMax_.size(), n = x.size();
  measuredAt_.resize(n);
  const size_t wordsPerBlock = (words + kMeasureBlocks - 1) / kMeasureBlocks;
  const size_t verticesPerBlock = (n + kMeasureBlocks - 1) / kMeasureBlocks;
  auto body = [&](size_t b) {
    for (size_t w = b * wordsPerBlock; w < std::min(words, (b + 1) * wordsPerBlock); ++w) {
      float m = 0.0f;
      for (size_t k = 64 * w; k < std::min(count_, 64 * w + 64); ++k) {
        squaredStretch_[k] = squaredStretchOf(x, springs[k]);
        m = std::max(m, squaredStretch_[k]);
      }
      wordMax_[w] = m;
    }
    const size_t begin = std::min(n, b * verticesPerBlock), end = std::min(n, (b + 1) * verticesPerBlock);
    std::copy(x.begin() + begin, x.begin() + end, measuredAt_.begin() + begin);
  };
  if (count_ < 2 * kParallelGrain)
    for (size_t b = 0; b < kMeasureBlocks; ++b) body(b);
  else
    ThreadPool::shared().parallelBlocks(kMeasureBlocks, body);
  return *std::max_element(wordMax_.begin(), wordMax_.end(), [](float a, float b) { return a < b; });
}

void StretchLimiter::remeasureAround(const std::vector<glm::vec3>& x, uint32_t vertex) {
  if (samePosition(x[vertex], measuredAt_[vertex])) return;
  measuredAt_[vertex] = x[vertex];
  for (uint32_t i = incidenceStart_[vertex]; i < incidenceStart_[vertex + 1]; ++i) {
    const uint32_t k = incidence_[i];
    squaredStretch_[k] = squaredStretchOf(x, (*springs_)[k]);
    if (!wordStale_[k / 64]) wordStale_[k / 64] = 1, staleWords_.push_back(k / 64);
  }
}

float StretchLimiter::largestMeasured() {
  for (uint32_t w : staleWords_) {
    float m = 0.0f;
    for (size_t k = 64 * size_t(w); k < std::min(count_, 64 * size_t(w) + 64); ++k) m = std::max(m, squaredStretch_[k]);
    wordMax_[w] = m;
    wordStale_[w] = 0;
  }
  staleWords_.clear();
  float m = 0.0f;
  for (float w : wordMax_) m = std::max(m, w);
  return m;
}

float StretchLimiter::measure(const std::vector<glm::vec3>& x) {
  const size_t n = x.size();
  if (measuredAt_.size() != n) return measureAll(x);
  // The vertices moved since the last measure, found by comparing blocks of
  // positions (most are equal between the contact rounds); when many moved,
  // the whole cloth is measured again instead.
  constexpr size_t kGroup = 16;
  const size_t most = n / 8;
  changed_.clear();
  for (size_t g = 0; g < n; g += kGroup) {
    const size_t e = std::min(n, g + kGroup);
    if (std::memcmp(&x[g], &measuredAt_[g], (e - g) * sizeof(glm::vec3)) == 0) continue;
    for (size_t i = g; i < e; ++i)
      if (!samePosition(x[i], measuredAt_[i])) changed_.push_back(uint32_t(i));
    if (changed_.size() > most) return measureAll(x);
  }
  for (uint32_t v : changed_) remeasureAround(x, v);
  return largestMeasured();
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
  noteMove(s.x, sp.a);
  noteMove(s.x, sp.b);
  s.x[sp.a] -= wa * correction;
  s.x[sp.b] += wb * correction;
  if (wa != 0.0f) markAround(sp.a, k);
  if (wb != 0.0f) markAround(sp.b, k);
  return l2 / (sp.rest * sp.rest);
}

void StretchLimiter::noteMove(const std::vector<glm::vec3>& x, uint32_t vertex) {
  if (moved_[vertex]) return;
  moved_[vertex] = 1;
  movedFrom_[vertex] = x[vertex];
  movedList_.push_back(vertex);
}

void StretchLimiter::markAround(uint32_t vertex, size_t except) {
  for (uint32_t i = incidenceStart_[vertex]; i < incidenceStart_[vertex + 1]; ++i) {
    const uint32_t k = incidence_[i];
    if (k != except) dirty_[k / 64] |= uint64_t(1) << (k % 64);
  }
}

void StretchLimiter::markOverTarget(float target) {
  // A hair below target^2: a spring the division rounds under it is still
  // checked (checking one within the limit changes nothing).
  const float threshold = target * target * (1.0f - 1e-4f);
  std::fill(dirty_.begin(), dirty_.end(), 0);
  for (size_t w = 0; w < wordMax_.size(); ++w) {
    if (wordMax_[w] <= threshold) continue;
    for (size_t k = 64 * w; k < std::min(count_, 64 * w + 64); ++k)
      if (squaredStretch_[k] > threshold) dirty_[w] |= uint64_t(1) << (k % 64);
  }
}

float StretchLimiter::remeasureMoved(const std::vector<glm::vec3>& x) {
  for (uint32_t v : movedList_) remeasureAround(x, v);
  return largestMeasured();
}

StretchLimitResult StretchLimiter::limitByPositions(ClothState& s, float maxStretch, int maxPasses, float h) {
  StretchLimitResult result;
  const float maxSquared = maxStretch * maxStretch;
  float worstSquared = measure(s.x);
  result.maxStretchBefore = result.maxStretchAfter = std::sqrt(worstSquared);
  if (worstSquared <= maxSquared) return result;
  // Aim a hair below the limit so rounding leaves every spring within it.
  const float target = maxStretch * (1.0f - 1e-3f);
  // Symmetric Gauss-Seidel: forward and backward passes alternate, so a
  // correction travels across the cloth in both directions. The first pass
  // checks every spring over the target (the others it would leave alone); a
  // correction marks the springs around the moved ends, which the current
  // pass checks when they come after it in its order, the next pass otherwise.
  // Each pass tracks the worst spring it meets (before correcting it); the
  // cloth is re-measured (the springs at the moved vertices) only when a pass
  // met none beyond the limit (a later correction in that pass may still
  // have stretched an earlier spring a little), not after every pass.
  markOverTarget(target);
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
      worstSquared = remeasureMoved(s.x);
      measured = true;
    }
  }
  if (!measured) worstSquared = remeasureMoved(s.x);
  result.maxStretchAfter = std::sqrt(worstSquared);
  // The velocities take the corrections over the step; only moved vertices changed.
  for (uint32_t v : movedList_) {
    s.v[v] += (s.x[v] - movedFrom_[v]) / h;
    moved_[v] = 0;
  }
  movedList_.clear();
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
