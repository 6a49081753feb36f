#include "sim/cloth/integrators/cg_update.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

namespace mq::cloth {

namespace {

double updateScalar(const CgUpdate& u, size_t begin, size_t end, double dot) {
  for (size_t i = begin; i < end; ++i) {
    u.dv[i] += u.alpha * u.c[i];
    u.r[i] -= u.alpha * u.q[i];
    const glm::vec3 z = u.preconditioner->times(i, u.r[i]);
    u.z->x[i] = z.x, u.z->y[i] = z.y, u.z->z[i] = z.z;
    dot += double(glm::dot(u.r[i], z));
  }
  return dot;
}

#if defined(__x86_64__) && defined(__GNUC__)

// AVX2 without FMA on purpose: a fused multiply-add rounds once where the
// scalar path rounds twice, and the two paths must agree bit for bit.
__attribute__((target("avx2"))) double updateGroupAvx2(const CgUpdate& u, size_t i, double dot) {
  const __m256 alpha = _mm256_set1_ps(u.alpha);
  float* dv = &u.dv[i].x;
  float* r = &u.r[i].x;
  const float* c = &u.c[i].x;
  const float* q = &u.q[i].x;
  // dv and r element by element, as stored (x0 y0 z0 x1 ...).
  __m256 a[3];
  for (int k = 0; k < 3; ++k) {
    _mm256_storeu_ps(dv + 8 * k,
                     _mm256_add_ps(_mm256_loadu_ps(dv + 8 * k), _mm256_mul_ps(alpha, _mm256_loadu_ps(c + 8 * k))));
    a[k] = _mm256_sub_ps(_mm256_loadu_ps(r + 8 * k), _mm256_mul_ps(alpha, _mm256_loadu_ps(q + 8 * k)));
    _mm256_storeu_ps(r + 8 * k, a[k]);
  }
  // r's eight vertices transposed into x, y and z vectors.
  const __m256 m03 = _mm256_permute2f128_ps(a[0], a[1], 0x30);             // x0 y0 z0 x1 | x4 y4 z4 x5
  const __m256 m14 = _mm256_permute2f128_ps(a[0], a[2], 0x21);             // y1 z1 x2 y2 | y5 z5 x6 y6
  const __m256 m25 = _mm256_permute2f128_ps(a[1], a[2], 0x30);             // z2 x3 y3 z3 | z6 x7 y7 z7
  const __m256 xy = _mm256_shuffle_ps(m14, m25, _MM_SHUFFLE(2, 1, 3, 2));  // x2 y2 x3 y3
  const __m256 yz = _mm256_shuffle_ps(m03, m14, _MM_SHUFFLE(1, 0, 2, 1));  // y0 z0 y1 z1
  const __m256 x = _mm256_shuffle_ps(m03, xy, _MM_SHUFFLE(2, 0, 3, 0));
  const __m256 y = _mm256_shuffle_ps(yz, xy, _MM_SHUFFLE(3, 1, 2, 0));
  const __m256 z = _mm256_shuffle_ps(yz, m25, _MM_SHUFFLE(3, 0, 3, 1));
  // z = P r with glm's order: (m[0][k] x + m[1][k] y) + m[2][k] z.
  const float* P = u.preconditioner->group(i / LaneBlocks::kLanes);
  auto entry = [&](int col, int row) __attribute__((target("avx2"))) {
    return _mm256_loadu_ps(P + 8 * (3 * col + row));
  };
  auto row = [&](int k) __attribute__((target("avx2"))) {
    return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(entry(0, k), x), _mm256_mul_ps(entry(1, k), y)),
                         _mm256_mul_ps(entry(2, k), z));
  };
  const __m256 zx = row(0), zy = row(1), zz = row(2);
  _mm256_storeu_ps(&u.z->x[i], zx);
  _mm256_storeu_ps(&u.z->y[i], zy);
  _mm256_storeu_ps(&u.z->z[i], zz);
  const __m256 d = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(x, zx), _mm256_mul_ps(y, zy)), _mm256_mul_ps(z, zz));
  alignas(32) double lanes[8];
  _mm256_store_pd(lanes, _mm256_cvtps_pd(_mm256_castps256_ps128(d)));
  _mm256_store_pd(lanes + 4, _mm256_cvtps_pd(_mm256_extractf128_ps(d, 1)));
  for (double l : lanes) dot += l;  // vertex by vertex, as the scalar path sums
  return dot;
}

bool hasAvx2() {
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
}

#endif

}  // namespace

double cgUpdateRange(const CgUpdate& u, size_t begin, size_t end, bool vectorised) {
  double dot = 0.0;
  size_t i = begin;
#if defined(__x86_64__) && defined(__GNUC__)
  if (vectorised && hasAvx2() && begin % LaneBlocks::kLanes == 0)
    for (; i + LaneBlocks::kLanes <= end; i += LaneBlocks::kLanes) dot = updateGroupAvx2(u, i, dot);
#endif
  return updateScalar(u, i, end, dot);
}

}  // namespace mq::cloth
