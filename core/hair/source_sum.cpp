#include "core/hair/source_sum.h"

#include <cmath>
#include <initializer_list>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace mq {

namespace {

glm::vec3 sumSourcesPortable(const float* px, const float* py, const float* pz, const float* w, const float* core2,
                             size_t n, const glm::vec3& x) {
  float vx = 0.0f, vy = 0.0f, vz = 0.0f;
  for (size_t j = 0; j < n; ++j) {
    const float dx = x.x - px[j], dy = x.y - py[j], dz = x.z - pz[j];
    const float r2 = dx * dx + dy * dy + dz * dz + core2[j];
    const float s = w[j] / (r2 * std::sqrt(r2));
    vx += s * dx;
    vy += s * dy;
    vz += s * dz;
  }
  return {vx, vy, vz};
}

#if defined(__SSE2__)
glm::vec3 sumSourcesSse(const float* px, const float* py, const float* pz, const float* w, const float* core2, size_t n,
                        const glm::vec3& x) {
  float vx = 0.0f, vy = 0.0f, vz = 0.0f;
  // Four sources per iteration; 1/r^3 from rsqrt refined by one Newton step.
  __m128 ax = _mm_setzero_ps(), ay = _mm_setzero_ps(), az = _mm_setzero_ps();
  const __m128 qx = _mm_set1_ps(x.x), qy = _mm_set1_ps(x.y), qz = _mm_set1_ps(x.z);
  const __m128 half = _mm_set1_ps(0.5f), three = _mm_set1_ps(3.0f);
  for (size_t j = 0; j < n; j += 4) {
    const __m128 dx = _mm_sub_ps(qx, _mm_loadu_ps(px + j));
    const __m128 dy = _mm_sub_ps(qy, _mm_loadu_ps(py + j));
    const __m128 dz = _mm_sub_ps(qz, _mm_loadu_ps(pz + j));
    const __m128 r2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)),
                                 _mm_add_ps(_mm_mul_ps(dz, dz), _mm_loadu_ps(core2 + j)));
    __m128 inv = _mm_rsqrt_ps(r2);
    inv = _mm_mul_ps(_mm_mul_ps(half, inv), _mm_sub_ps(three, _mm_mul_ps(r2, _mm_mul_ps(inv, inv))));
    const __m128 s = _mm_mul_ps(_mm_loadu_ps(w + j), _mm_mul_ps(inv, _mm_mul_ps(inv, inv)));
    ax = _mm_add_ps(ax, _mm_mul_ps(s, dx));
    ay = _mm_add_ps(ay, _mm_mul_ps(s, dy));
    az = _mm_add_ps(az, _mm_mul_ps(s, dz));
  }
  alignas(16) float lanes[4];
  _mm_store_ps(lanes, ax);
  vx = lanes[0] + lanes[1] + lanes[2] + lanes[3];
  _mm_store_ps(lanes, ay);
  vy = lanes[0] + lanes[1] + lanes[2] + lanes[3];
  _mm_store_ps(lanes, az);
  vz = lanes[0] + lanes[1] + lanes[2] + lanes[3];
  return {vx, vy, vz};
}
#endif

#if defined(__x86_64__) && defined(__GNUC__)
// Eight sources per iteration with AVX2 + FMA, chosen at run time (the build
// targets plain x86-64); 1/r^3 from rsqrt refined by one Newton step.
__attribute__((target("avx2,fma"))) glm::vec3 sumSourcesAvx2(const float* px, const float* py, const float* pz,
                                                             const float* w, const float* core2, size_t n,
                                                             const glm::vec3& x) {
  __m256 ax = _mm256_setzero_ps(), ay = _mm256_setzero_ps(), az = _mm256_setzero_ps();
  const __m256 qx = _mm256_set1_ps(x.x), qy = _mm256_set1_ps(x.y), qz = _mm256_set1_ps(x.z);
  const __m256 half = _mm256_set1_ps(0.5f), three = _mm256_set1_ps(3.0f);
  for (size_t j = 0; j < n; j += 8) {
    const __m256 dx = _mm256_sub_ps(qx, _mm256_loadu_ps(px + j));
    const __m256 dy = _mm256_sub_ps(qy, _mm256_loadu_ps(py + j));
    const __m256 dz = _mm256_sub_ps(qz, _mm256_loadu_ps(pz + j));
    const __m256 r2 =
        _mm256_fmadd_ps(dx, dx, _mm256_fmadd_ps(dy, dy, _mm256_fmadd_ps(dz, dz, _mm256_loadu_ps(core2 + j))));
    __m256 inv = _mm256_rsqrt_ps(r2);
    inv = _mm256_mul_ps(_mm256_mul_ps(half, inv), _mm256_fnmadd_ps(r2, _mm256_mul_ps(inv, inv), three));
    const __m256 s = _mm256_mul_ps(_mm256_loadu_ps(w + j), _mm256_mul_ps(inv, _mm256_mul_ps(inv, inv)));
    ax = _mm256_fmadd_ps(s, dx, ax);
    ay = _mm256_fmadd_ps(s, dy, ay);
    az = _mm256_fmadd_ps(s, dz, az);
  }
  alignas(32) float lanes[3][8];
  _mm256_store_ps(lanes[0], ax);
  _mm256_store_ps(lanes[1], ay);
  _mm256_store_ps(lanes[2], az);
  glm::vec3 v(0.0f);
  for (int d = 0; d < 3; ++d)
    for (int k = 0; k < 8; ++k) v[d] += lanes[d][k];
  return v;
}

// Sixteen sources per iteration with AVX-512: rsqrt14 (relative error
// below 2^-14) is accurate enough without a Newton step.
// GCC 12 warns inside its own avx512fintrin.h (the undefined start value of
// _mm512_setzero_ps and the reductions): a false positive.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
__attribute__((target("avx512f"))) glm::vec3 sumSourcesAvx512(const float* px, const float* py, const float* pz,
                                                              const float* w, const float* core2, size_t n,
                                                              const glm::vec3& x) {
  __m512 ax = _mm512_setzero_ps(), ay = _mm512_setzero_ps(), az = _mm512_setzero_ps();
  const __m512 qx = _mm512_set1_ps(x.x), qy = _mm512_set1_ps(x.y), qz = _mm512_set1_ps(x.z);
  size_t j = 0;
  for (; j + 16 <= n; j += 16) {
    const __m512 dx = _mm512_sub_ps(qx, _mm512_loadu_ps(px + j));
    const __m512 dy = _mm512_sub_ps(qy, _mm512_loadu_ps(py + j));
    const __m512 dz = _mm512_sub_ps(qz, _mm512_loadu_ps(pz + j));
    const __m512 r2 =
        _mm512_fmadd_ps(dx, dx, _mm512_fmadd_ps(dy, dy, _mm512_fmadd_ps(dz, dz, _mm512_loadu_ps(core2 + j))));
    const __m512 inv = _mm512_rsqrt14_ps(r2);
    const __m512 s = _mm512_mul_ps(_mm512_loadu_ps(w + j), _mm512_mul_ps(inv, _mm512_mul_ps(inv, inv)));
    ax = _mm512_fmadd_ps(s, dx, ax);
    ay = _mm512_fmadd_ps(s, dy, ay);
    az = _mm512_fmadd_ps(s, dz, az);
  }
  glm::vec3 v(_mm512_reduce_add_ps(ax), _mm512_reduce_add_ps(ay), _mm512_reduce_add_ps(az));
  if (j < n) v += sumSourcesAvx2(px + j, py + j, pz + j, w + j, core2 + j, n - j, x);
  return v;
}
#pragma GCC diagnostic pop

bool hasAvx512() {
  static const bool yes = __builtin_cpu_supports("avx512f");
  return yes;
}

bool hasAvx2() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
}
#endif

}  // namespace

bool sourceSumKernelRuns(SourceSumKernel kernel) {
  switch (kernel) {
    case SourceSumKernel::Portable:
      return true;
#if defined(__SSE2__)
    case SourceSumKernel::Sse:
      return true;
#endif
#if defined(__x86_64__) && defined(__GNUC__)
    case SourceSumKernel::Avx2:
      return hasAvx2();
    case SourceSumKernel::Avx512:
      return hasAvx512() && hasAvx2();  // its tail runs the AVX2 kernel
#endif
    default:
      return false;
  }
}

SourceSumKernel fastestSourceSumKernel() {
  static const SourceSumKernel fastest = [] {
    for (SourceSumKernel k : {SourceSumKernel::Avx512, SourceSumKernel::Avx2, SourceSumKernel::Sse})
      if (sourceSumKernelRuns(k)) return k;
    return SourceSumKernel::Portable;
  }();
  return fastest;
}

glm::vec3 sumSources(SourceSumKernel kernel, const float* px, const float* py, const float* pz, const float* w,
                     const float* core2, size_t n, const glm::vec3& x) {
  switch (sourceSumKernelRuns(kernel) ? kernel : SourceSumKernel::Portable) {
#if defined(__x86_64__) && defined(__GNUC__)
    case SourceSumKernel::Avx512:
      return sumSourcesAvx512(px, py, pz, w, core2, n, x);
    case SourceSumKernel::Avx2:
      return sumSourcesAvx2(px, py, pz, w, core2, n, x);
#endif
#if defined(__SSE2__)
    case SourceSumKernel::Sse:
      return sumSourcesSse(px, py, pz, w, core2, n, x);
#endif
    default:
      return sumSourcesPortable(px, py, pz, w, core2, n, x);
  }
}

}  // namespace mq
