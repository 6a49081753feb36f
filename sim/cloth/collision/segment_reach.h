#pragma once
// The self-collision's exact edge-edge test for four pairs of segments at
// once (SSE lanes): whether the segments p0 p1 and q0 q1 of a lane are
// within `reach` of each other. The same float operations, in the same
// order, as the scalar test (glm's dot, length and mix and
// closestSegmentParameters, none fused), so a lane's answer is the scalar
// answer: the searches drop the pairs it rejects before their scalar test.

#include <cstdint>

#include <glm/glm.hpp>

#if defined(__SSE2__)
#include <immintrin.h>
#define MQ_SEGMENT_REACH_SSE 1
#endif

#include "sim/cloth/collision/proximity.h"

namespace mq::cloth {

// The scalar test: the segments' bounding balls within reach, then their
// closest points (not coincident) within reach.
inline bool segmentsWithinReach(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& q0, const glm::vec3& q1,
                                float reach) {
  const float apart = glm::length(0.5f * (p0 + p1 - q0 - q1)) - 0.5f * (glm::length(p0 - p1) + glm::length(q0 - q1));
  if (apart > reach) return false;
  const glm::vec2 st = closestSegmentParameters(p0, p1, q0, q1);
  const float l = glm::length(glm::mix(p0, p1, st.x) - glm::mix(q0, q1, st.y));
  return !(l < 1e-9f || l > reach);
}

#ifdef MQ_SEGMENT_REACH_SSE
// Four points or vectors by coordinate.
struct Vec3x4 {
  __m128 x, y, z;
};

namespace segment_reach_detail {
inline Vec3x4 sub(const Vec3x4& a, const Vec3x4& b) {
  return {_mm_sub_ps(a.x, b.x), _mm_sub_ps(a.y, b.y), _mm_sub_ps(a.z, b.z)};
}
// glm::dot's order: (x + y) + z.
inline __m128 dot(const Vec3x4& a, const Vec3x4& b) {
  return _mm_add_ps(_mm_add_ps(_mm_mul_ps(a.x, b.x), _mm_mul_ps(a.y, b.y)), _mm_mul_ps(a.z, b.z));
}
// glm::mix(a, b, t) = a (1 - t) + b t.
inline Vec3x4 mix(const Vec3x4& a, const Vec3x4& b, __m128 t) {
  const __m128 u = _mm_sub_ps(_mm_set1_ps(1.0f), t);
  return {_mm_add_ps(_mm_mul_ps(a.x, u), _mm_mul_ps(b.x, t)), _mm_add_ps(_mm_mul_ps(a.y, u), _mm_mul_ps(b.y, t)),
          _mm_add_ps(_mm_mul_ps(a.z, u), _mm_mul_ps(b.z, t))};
}
inline __m128 clamp01(__m128 v) { return _mm_min_ps(_mm_max_ps(v, _mm_setzero_ps()), _mm_set1_ps(1.0f)); }
inline __m128 select(__m128 when, __m128 yes, __m128 no) {
  return _mm_or_ps(_mm_and_ps(when, yes), _mm_andnot_ps(when, no));
}
}  // namespace segment_reach_detail

// Bit k set: lane k passes segmentsWithinReach. Inlined into its caller:
// its lanes stay in registers.
__attribute__((always_inline)) inline unsigned segmentsWithinReach(const Vec3x4& p0, const Vec3x4& p1, const Vec3x4& q0,
                                                                   const Vec3x4& q1, __m128 reach) {
  using namespace segment_reach_detail;
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f), half = _mm_set1_ps(0.5f);
  const __m128 eps = _mm_set1_ps(1e-12f), sign = _mm_set1_ps(-0.0f);
  const Vec3x4 d1 = sub(p1, p0), d2 = sub(q1, q0), r = sub(p0, q0);
  const __m128 a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r), c = dot(d1, r), b = dot(d1, d2);
  // Bounding balls (|p0 - p1| is sqrt(a): a difference's negation is exact).
  const Vec3x4 sum = sub(sub({_mm_add_ps(p0.x, p1.x), _mm_add_ps(p0.y, p1.y), _mm_add_ps(p0.z, p1.z)}, q0), q1);
  const Vec3x4 mid = {_mm_mul_ps(half, sum.x), _mm_mul_ps(half, sum.y), _mm_mul_ps(half, sum.z)};
  const __m128 apart =
      _mm_sub_ps(_mm_sqrt_ps(dot(mid, mid)), _mm_mul_ps(half, _mm_add_ps(_mm_sqrt_ps(a), _mm_sqrt_ps(e))));
  // closestSegmentParameters, its branches as selects: the general case first.
  const __m128 denom = _mm_sub_ps(_mm_mul_ps(a, e), _mm_mul_ps(b, b));
  const __m128 s0 =
      _mm_and_ps(_mm_cmpgt_ps(denom, eps), clamp01(_mm_div_ps(_mm_sub_ps(_mm_mul_ps(b, f), _mm_mul_ps(c, e)), denom)));
  const __m128 t0 = _mm_div_ps(_mm_add_ps(_mm_mul_ps(b, s0), f), e);
  const __m128 sAtT0 = clamp01(_mm_div_ps(_mm_xor_ps(c, sign), a)), sAtT1 = clamp01(_mm_div_ps(_mm_sub_ps(b, c), a));
  const __m128 below = _mm_cmplt_ps(t0, zero), above = _mm_cmpgt_ps(t0, one);
  __m128 s = select(below, sAtT0, select(above, sAtT1, s0));
  __m128 t = select(below, zero, select(above, one, t0));
  // A point segment: the other's closest point to it.
  const __m128 pointP = _mm_cmple_ps(a, eps), pointQ = _mm_cmple_ps(e, eps);
  s = select(pointQ, sAtT0, s);
  t = select(pointQ, zero, t);
  s = _mm_andnot_ps(pointP, s);
  t = select(pointP, _mm_andnot_ps(pointQ, clamp01(_mm_div_ps(f, e))), t);
  const Vec3x4 d = sub(mix(p0, p1, s), mix(q0, q1, t));
  const __m128 l = _mm_sqrt_ps(dot(d, d));
  const __m128 rejected =
      _mm_or_ps(_mm_cmpgt_ps(apart, reach), _mm_or_ps(_mm_cmplt_ps(l, _mm_set1_ps(1e-9f)), _mm_cmpgt_ps(l, reach)));
  return unsigned(_mm_movemask_ps(rejected)) ^ 0xFu;
}

// Bit k set: lane k's segments are surely farther apart than `reach`, from
// the line through their midpoints: the segments (midpoints m_p, m_q, half
// vectors h_p, h_q, d = m_p - m_q) project onto it at least
// |d| - (|d.h_p| + |d.h_q|) / |d| apart, no more than their distance. That
// bound is rounded, so it is compared with `reach` grown by 0.1% and 10 um:
// far more than its rounding and the exact test's, so a pair it rejects
// fails segmentsWithinReach too (a cheap screen before it).
inline unsigned segmentsApart(const Vec3x4& midOffset, const Vec3x4& halfP, const Vec3x4& halfQ, __m128 reach) {
  using namespace segment_reach_detail;
  const __m128 sign = _mm_set1_ps(-0.0f);
  const __m128 length2 = dot(midOffset, midOffset), length = _mm_sqrt_ps(length2);
  const __m128 projected =
      _mm_add_ps(_mm_andnot_ps(sign, dot(midOffset, halfP)), _mm_andnot_ps(sign, dot(midOffset, halfQ)));
  const __m128 grown = _mm_add_ps(_mm_mul_ps(_mm_set1_ps(1.001f), reach), _mm_set1_ps(1e-5f));
  // (|d|^2 - projected) / |d| > grown, without the division (|d| = 0 keeps the pair).
  return unsigned(_mm_movemask_ps(_mm_cmpgt_ps(_mm_sub_ps(length2, projected), _mm_mul_ps(length, grown))));
}
#endif

}  // namespace mq::cloth
