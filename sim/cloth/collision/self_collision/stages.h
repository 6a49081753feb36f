#pragma once
// What the stages of the self-collision search (self_collision.h) share:
// the step's state (SelfCollision::Step), the node motion bounds, and small
// parallel helpers. Internal to sim/cloth/collision.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <vector>

#ifdef __SSE2__
#include <immintrin.h>
#endif

#include "core/util/thread_pool.h"
#include "sim/cloth/collision/self_collision.h"

namespace mq::cloth {

// One step's search: what every stage reads (the cloth, where it started,
// the thickness, each vertex's move) and what the first stages leave to the
// later ones (the element boxes, which kind the trees hold, whether the
// motion bounds are used).
struct SelfCollision::Step {
  Step(const ClothState& cloth, const std::vector<glm::vec3>& start, float gap) : s(cloth), x0(start), thickness(gap) {}
  const ClothState& s;
  const std::vector<glm::vec3>& x0;
  float thickness;
  std::vector<glm::vec3> move;  // per vertex: s.x - x0
  std::vector<float> offMean;   // per vertex: its move's distance from the mean move
  float meanMotion = 0.0f;      // the mean length of a move
  float deviation = 0.0f;       // the largest distance of a move from the mean move
  // The cloth's moves differ much: a candidate's boxes swept over the step overlap.
  bool swept = false;
  // The trees hold relative boxes, and candidates need swept ones to overlap
  // (sweptBoxes, sweptEdgeBoxes: by place in the trees).
  bool checkSwept = false;
  bool bounded = false;  // the searches use the node motion bounds
  std::vector<Box> boxes, edgeBoxes, sweptBoxes, sweptEdgeBoxes;

  // The largest difference of a vertex's move in `first` and one in `second`.
  float closing(std::initializer_list<uint32_t> first, std::initializer_list<uint32_t> second) const {
    float worst = 0.0f;
    for (uint32_t a : first)
      for (uint32_t b : second) {
        const glm::vec3 d = move[a] - move[b];
        worst = std::max(worst, glm::dot(d, d));
      }
    return std::sqrt(worst);
  }
  // A vertex's box over the step, grown by the thickness.
  Box sweptBox(uint32_t v) const {
    Box b;
    b.extend(x0[v]), b.extend(s.x[v]);
    b.min -= glm::vec3(thickness);
    b.max += glm::vec3(thickness);
    return b;
  }
  // A vertex's box at the start, grown by half the thickness plus its distance from the mean move.
  Box relativeBox(uint32_t v) const {
    Box b;
    b.extend(x0[v]);
    const float grow = offMean[v] + 0.5f * thickness;
    b.min -= glm::vec3(grow);
    b.max += glm::vec3(grow);
    return b;
  }
};

namespace self_collision {

constexpr size_t kBlocks = 64;
#ifdef __SSE2__
constexpr bool kScreened = true;  // EdgeColumns::apartOrNeighbours screens the edge pairs
#else
constexpr bool kScreened = false;
#endif

constexpr uint32_t kNoTriangle = UINT32_MAX;

inline bool sharesVertex(uint32_t a0, uint32_t a1, uint32_t b0, uint32_t b1) {
  return a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1;
}

// Runs body(begin, end) over [0, count) in chunks of `chunk`, in parallel.
template <class Body>
inline void inChunks(size_t count, size_t chunk, Body&& body) {
  ThreadPool::shared().parallelBlocks((count + chunk - 1) / chunk,
                                      [&](size_t b) { body(b * chunk, std::min(count, (b + 1) * chunk)); });
}

// Per place of `tree`: the value of the primitive there (in parallel).
template <class T>
std::vector<T> placeOrdered(const AabbTree& tree, const std::vector<T>& byPrimitive) {
  std::vector<T> byPlace(byPrimitive.size());
  inChunks(byPlace.size(), 4096, [&](size_t k0, size_t k1) {
    for (size_t k = k0; k < k1; ++k) byPlace[k] = byPrimitive[tree.primitive(uint32_t(k))];
  });
  return byPlace;
}

// Grows m to hold o (row by row).
inline void extend(NodeMotion& m, const NodeMotion& o) {
#ifdef __SSE2__
  float* rows = &m.startMin.x;
  const float* other = &o.startMin.x;
  for (int r = 0; r < 16; r += 8) {
    _mm_store_ps(rows + r, _mm_min_ps(_mm_load_ps(rows + r), _mm_load_ps(other + r)));
    _mm_store_ps(rows + r + 4, _mm_max_ps(_mm_load_ps(rows + r + 4), _mm_load_ps(other + r + 4)));
  }
#else
  m.startMin = glm::min(m.startMin, o.startMin), m.startMax = glm::max(m.startMax, o.startMax);
  m.moveMin = glm::min(m.moveMin, o.moveMin), m.moveMax = glm::max(m.moveMax, o.moveMax);
#endif
}
// A vertex's motion: where it starts and how it moves.
inline NodeMotion pointMotion(const glm::vec3& start, const glm::vec3& move) {
  NodeMotion m;
  m.startMin = m.startMax = glm::vec4(start, 0.0f);
  m.moveMin = m.moveMax = glm::vec4(move, 0.0f);
  return m;
}

// Whether elements whose vertices start within `gap` of each other and
// whose moves differ by up to `farthest` (both squared) can pass the exact
// test dist(x0) <= thickness + closing. Slightly generous, so that rounding
// never drops a pair the exact test keeps.
inline bool withinReach(float gap2, float farthest2, float thickness) {
  if (gap2 <= thickness * thickness) return true;
  return std::sqrt(gap2) <= 1.001f * (thickness + std::sqrt(farthest2)) + 1e-6f;
}
// Whether two nodes' elements can pass it: their start boxes are within the
// thickness plus the largest difference of two of their moves (four lanes at
// a time, the fourth zero).
#ifdef __SSE2__
inline bool withinReach(__m128 aStartMin, __m128 aStartMax, __m128 aMoveMin, __m128 aMoveMax, __m128 bStartMin,
                        __m128 bStartMax, __m128 bMoveMin, __m128 bMoveMax, float thickness) {
  const __m128 zero = _mm_setzero_ps(), sign = _mm_set1_ps(-0.0f);
  const __m128 gap = _mm_max_ps(_mm_max_ps(_mm_sub_ps(aStartMin, bStartMax), _mm_sub_ps(bStartMin, aStartMax)), zero);
  const __m128 far = _mm_max_ps(_mm_andnot_ps(sign, _mm_sub_ps(aMoveMax, bMoveMin)),
                                _mm_andnot_ps(sign, _mm_sub_ps(bMoveMax, aMoveMin)));
  // Horizontal sums of the squares: gap2 in lane 0, far2 in lane 2 of the pair.
  const __m128 g2 = _mm_mul_ps(gap, gap), f2 = _mm_mul_ps(far, far);
  const __m128 s1 = _mm_add_ps(_mm_unpacklo_ps(g2, f2), _mm_unpackhi_ps(g2, f2));  // g0+g2 f0+f2 g1+g3 f1+f3
  const __m128 s2 = _mm_add_ps(s1, _mm_movehl_ps(s1, s1));                         // gap2 far2 . .
  return withinReach(_mm_cvtss_f32(s2), _mm_cvtss_f32(_mm_shuffle_ps(s2, s2, 1)), thickness);
}
inline __m128 row(const glm::vec4& v) { return _mm_load_ps(&v.x); }
// A point as a row, built in registers (a NodeMotion built on the stack and
// read back at once stalls on the store).
inline __m128 row(const glm::vec3& p) { return _mm_setr_ps(p.x, p.y, p.z, 0.0f); }
#endif

inline bool withinReach(const NodeMotion& a, const NodeMotion& b, float thickness) {
#ifdef __SSE2__
  return withinReach(row(a.startMin), row(a.startMax), row(a.moveMin), row(a.moveMax), row(b.startMin), row(b.startMax),
                     row(b.moveMin), row(b.moveMax), thickness);
#else
  const glm::vec4 gap = glm::max(glm::max(a.startMin - b.startMax, b.startMin - a.startMax), glm::vec4(0.0f));
  const glm::vec4 far = glm::max(glm::abs(a.moveMax - b.moveMin), glm::abs(b.moveMax - a.moveMin));
  return withinReach(glm::dot(gap, gap), glm::dot(far, far), thickness);
#endif
}
// The same for a node's elements and a vertex.
inline bool withinReach(const NodeMotion& a, const glm::vec3& start, const glm::vec3& move, float thickness) {
#ifdef __SSE2__
  const __m128 p = row(start), d = row(move);
  return withinReach(row(a.startMin), row(a.startMax), row(a.moveMin), row(a.moveMax), p, p, d, d, thickness);
#else
  return withinReach(a, pointMotion(start, move), thickness);
#endif
}

// Runs body(item, outBlock) over [0, count) in fixed blocks, in parallel, and
// concatenates the blocks' outputs in order: deterministic.
template <class T, class Body>
std::vector<T> collectInBlocks(size_t count, Body&& body) {
  std::vector<std::vector<T>> blocks(kBlocks);
  const size_t size = (count + kBlocks - 1) / kBlocks;
  ThreadPool::shared().parallelBlocks(kBlocks, [&](size_t b) {
    for (size_t i = b * size; i < std::min(count, (b + 1) * size); ++i) body(i, blocks[b]);
  });
  size_t total = 0;
  for (const auto& b : blocks) total += b.size();
  std::vector<T> all;
  all.reserve(total);
  for (auto& b : blocks) all.insert(all.end(), b.begin(), b.end());
  return all;
}

}  // namespace self_collision
}  // namespace mq::cloth
