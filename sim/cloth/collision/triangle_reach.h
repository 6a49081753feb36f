#pragma once
// The self-collision's cheap screen of vertex-triangle pairs, before their
// exact test: a vertex that is one of the triangle's corners, or in one flat
// patch with it, or out of its reach, is no candidate. For one triangle
// (scalar) or four neighbours in the tree at once (SSE lanes: the same float
// operations in the same order, none fused, so the same answers).

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#ifdef __SSE2__
#include <immintrin.h>
#endif

namespace mq::cloth {

// Where a triangle starts and how it moves in the step: the centre of its
// start positions and the radius around it that holds them, the mean of its
// corners' moves and their largest distance from it.
struct TriangleReach {
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
  glm::vec3 meanMove{0.0f};
  float spread = 0.0f;
};

inline TriangleReach triangleReach(const glm::vec3 (&start)[3], const glm::vec3 (&move)[3]) {
  TriangleReach t;
  t.centre = (start[0] + start[1] + start[2]) / 3.0f;
  t.meanMove = (move[0] + move[1] + move[2]) / 3.0f;
  for (int k = 0; k < 3; ++k) {
    t.radius = std::max(t.radius, glm::length(start[k] - t.centre));
    t.spread = std::max(t.spread, glm::length(move[k] - t.meanMove));
  }
  return t;
}

// Whether a vertex starting at `start` and moving by `move` may pass the
// exact test dist(x0) <= thickness + (the largest difference of its move and
// a corner's): that difference is at most |move - meanMove| + spread.
// Slightly generous, so that rounding never drops a pair the exact test keeps.
inline bool mayReach(const TriangleReach& t, const glm::vec3& start, const glm::vec3& move, float thickness) {
  const float farthest = thickness + glm::length(move - t.meanMove) + t.spread;
  return !(glm::length(start - t.centre) - t.radius > 1.0001f * farthest + 1e-6f);
}

// Per place of the triangle tree, as columns padded by three places (four
// places from any one are read at once): the triangles' corners, their
// highest flat patches (-1: none) and their reaches.
class TriangleColumns {
 public:
  void resize(size_t places) {
    for (std::vector<uint32_t>* c : {&a_, &b_, &c_}) c->resize(places + 3, UINT32_MAX);
    flat_.resize(places + 3, -1);
    for (std::vector<float>* c : {&centreX_, &centreY_, &centreZ_, &radius_, &moveX_, &moveY_, &moveZ_, &spread_})
      c->resize(places + 3, 0.0f);
  }
  void set(size_t k, const std::array<uint32_t, 3>& corners, int32_t flat, const TriangleReach& t) {
    a_[k] = corners[0], b_[k] = corners[1], c_[k] = corners[2], flat_[k] = flat;
    centreX_[k] = t.centre.x, centreY_[k] = t.centre.y, centreZ_[k] = t.centre.z, radius_[k] = t.radius;
    moveX_[k] = t.meanMove.x, moveY_[k] = t.meanMove.y, moveZ_[k] = t.meanMove.z, spread_[k] = t.spread;
  }
  // Whether the vertex (its highest flat patch `flat`, its start and move)
  // and the triangle at place k pass the screen: not a corner, not in one
  // flat patch, mayReach().
  bool screen(size_t k, uint32_t vertex, int32_t flat, const glm::vec3& start, const glm::vec3& move,
              float thickness) const {
    if (vertex == a_[k] || vertex == b_[k] || vertex == c_[k] || (flat >= 0 && flat == flat_[k])) return false;
    const TriangleReach t{
        {centreX_[k], centreY_[k], centreZ_[k]}, radius_[k], {moveX_[k], moveY_[k], moveZ_[k]}, spread_[k]};
    return mayReach(t, start, move, thickness);
  }
  // Bit k set: screen(first + k, ...) for k < 4, at once.
  unsigned screenFour(uint32_t first, uint32_t vertex, int32_t flat, const glm::vec3& start, const glm::vec3& move,
                      float thickness) const {
#ifdef __SSE2__
    auto column = [&](const std::vector<float>& c) { return _mm_loadu_ps(&c[first]); };
    auto indices = [&](const auto& c) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(&c[first])); };
    // glm::length(p - column point): its dot as ((x x + y y) + z z).
    auto distance = [&](const glm::vec3& p, const std::vector<float>& x, const std::vector<float>& y,
                        const std::vector<float>& z) {
      const __m128 dx = _mm_sub_ps(_mm_set1_ps(p.x), column(x)), dy = _mm_sub_ps(_mm_set1_ps(p.y), column(y));
      const __m128 dz = _mm_sub_ps(_mm_set1_ps(p.z), column(z));
      return _mm_sqrt_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz)));
    };
    const __m128i v = _mm_set1_epi32(int(vertex));
    __m128i out = _mm_or_si128(_mm_or_si128(_mm_cmpeq_epi32(v, indices(a_)), _mm_cmpeq_epi32(v, indices(b_))),
                               _mm_cmpeq_epi32(v, indices(c_)));
    if (flat >= 0) out = _mm_or_si128(out, _mm_cmpeq_epi32(_mm_set1_epi32(flat), indices(flat_)));
    const __m128 farthest =
        _mm_add_ps(_mm_add_ps(_mm_set1_ps(thickness), distance(move, moveX_, moveY_, moveZ_)), column(spread_));
    const __m128 far = _mm_cmpgt_ps(_mm_sub_ps(distance(start, centreX_, centreY_, centreZ_), column(radius_)),
                                    _mm_add_ps(_mm_mul_ps(_mm_set1_ps(1.0001f), farthest), _mm_set1_ps(1e-6f)));
    return unsigned(_mm_movemask_ps(_mm_or_ps(_mm_castsi128_ps(out), far))) ^ 0xFu;
#else
    unsigned mask = 0;
    for (uint32_t k = 0; k < 4; ++k) mask |= unsigned(screen(first + k, vertex, flat, start, move, thickness)) << k;
    return mask;
#endif
  }

 private:
  std::vector<uint32_t> a_, b_, c_;
  std::vector<int32_t> flat_;
  std::vector<float> centreX_, centreY_, centreZ_, radius_, moveX_, moveY_, moveZ_, spread_;
};

}  // namespace mq::cloth
