#include "core/hair/flow_field.h"

#include <cmath>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace mq {

namespace {

constexpr float kInvFourPi = 0.0795774715f;
constexpr float kCoreFraction = 0.02f;  // source core radius / sqrt(panel area)

inline glm::vec3 sourceVelocity(const PointSource& s, const glm::vec3& x) {
  const glm::vec3 d = x - s.position;
  const float r2 = s.radius * s.radius;
  const float q = glm::dot(d, d) + r2;
  return d * (s.strength * r2 / (q * std::sqrt(q)));
}

inline glm::vec3 vortexVelocity(const Vortex& v, const glm::vec3& x) {
  const glm::vec3 d = x - v.position;
  const float r2 = v.radius * v.radius;
  const float falloff = std::exp(0.5f - glm::dot(d, d) / (2.0f * r2));
  return glm::cross(v.axis, d) * (v.strength / v.radius * falloff);
}

}  // namespace

void FlowField::setObstacle(const SurfacePanels& panels, const std::vector<uint8_t>& scalpPanel) {
  panels_ = panels;
  scalpPanel_ = scalpPanel;
  scalpPanel_.resize(panels.size(), 0);
  const int n = int(panels.size());
  sourcePositions_.resize(n);
  for (int j = 0; j < n; ++j) {
    const float depth = j < int(panels.depths.size()) ? panels.depths[j] : std::sqrt(panels.areas[j]);
    sourcePositions_[j] = panels.centers[j] - depth * panels.normals[j];
  }
  const size_t padded = (panels.size() + 15) & ~size_t(15);  // whole AVX-512 lanes
  px_.assign(padded, 0.0f);
  py_.assign(padded, 0.0f);
  pz_.assign(padded, 0.0f);
  weight_.assign(padded, 0.0f);
  core2_.assign(padded, 1.0f);
  for (int j = 0; j < n; ++j) {
    px_[j] = sourcePositions_[j].x;
    py_[j] = sourcePositions_[j].y;
    pz_[j] = sourcePositions_[j].z;
    core2_[j] = kCoreFraction * kCoreFraction * panels.areas[j];
  }
  // a(i, j): normal velocity at collocation point i from a unit flux at source j.
  Eigen::MatrixXd a(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const glm::vec3 d = panels.centers[i] - sourcePositions_[j];
      const float q = glm::dot(d, d) + core2_[j];
      a(i, j) = kInvFourPi * glm::dot(d, panels.normals[i]) / (q * std::sqrt(q));
    }
  lu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(a);
  solveStrengths();
}

void FlowField::setPrimitives(const FlowPrimitives& primitives, const glm::vec3& headOrigin, float scalpOutflow) {
  streams_.clear();
  uniform_ = glm::vec3(0.0f);
  for (UniformStream s : primitives.streams) {
    const float len = glm::length(s.direction);
    if (len <= 0.0f) continue;
    s.direction /= len;
    uniform_ += s.direction * s.strength;
    streams_.push_back(s);
  }
  sources_ = primitives.sources;
  for (PointSource& s : sources_) {
    s.position += headOrigin;
    s.radius = std::max(s.radius, 1e-4f);
  }
  vortices_.clear();
  for (Vortex v : primitives.vortices) {
    const float len = glm::length(v.axis);
    if (len <= 0.0f) continue;
    v.axis /= len;
    v.position += headOrigin;
    v.radius = std::max(v.radius, 1e-4f);
    vortices_.push_back(v);
  }
  scalpOutflow_ = scalpOutflow;
  solveStrengths();
}

void FlowField::setNoise(uint32_t seed, float amplitude, float wavelength) {
  perlin_ = PerlinNoise(seed);
  noiseAmplitude_ = amplitude;
  noiseFrequency_ = wavelength > 0.0f ? 1.0f / wavelength : 1.0f;
}

void FlowField::solveStrengths() {
  const int n = int(panels_.size());
  flux_.assign(n, 0.0f);
  target_.assign(n, 0.0f);
  if (n == 0) return;
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) {
    target_[i] = scalpPanel_[i] ? scalpOutflow_ : 0.0f;
    rhs[i] = target_[i] - glm::dot(primitiveVelocity(panels_.centers[i]), panels_.normals[i]);
  }
  const Eigen::VectorXd q = lu_.solve(rhs);
  for (int j = 0; j < n; ++j) {
    flux_[j] = float(q[j]);
    weight_[j] = float(q[j]) * kInvFourPi;
  }
}

glm::vec3 FlowField::primitiveVelocity(const glm::vec3& x) const {
  glm::vec3 v = uniform_;
  for (const PointSource& s : sources_) v += sourceVelocity(s, x);
  for (const Vortex& w : vortices_) v += vortexVelocity(w, x);
  return v;
}

namespace {

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

glm::vec3 sumSources(const float* px, const float* py, const float* pz, const float* w, const float* core2, size_t n,
                     const glm::vec3& x) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (hasAvx512()) return sumSourcesAvx512(px, py, pz, w, core2, n, x);
  if (hasAvx2()) return sumSourcesAvx2(px, py, pz, w, core2, n, x);
#endif
  float vx = 0.0f, vy = 0.0f, vz = 0.0f;
#if defined(__SSE2__)
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
#else
  for (size_t j = 0; j < n; ++j) {
    const float dx = x.x - px[j], dy = x.y - py[j], dz = x.z - pz[j];
    const float r2 = dx * dx + dy * dy + dz * dz + core2[j];
    const float s = w[j] / (r2 * std::sqrt(r2));
    vx += s * dx;
    vy += s * dy;
    vz += s * dz;
  }
#endif
  return {vx, vy, vz};
}

}  // namespace

glm::vec3 FlowField::panelVelocity(const glm::vec3& x, int skip) const {
  glm::vec3 v = sumSources(px_.data(), py_.data(), pz_.data(), weight_.data(), core2_.data(), px_.size(), x);
  if (skip >= 0 && size_t(skip) < panels_.size()) {
    const glm::vec3 d = x - sourcePositions_[skip];
    const float r2 = glm::dot(d, d) + core2_[skip];
    v -= d * (weight_[skip] / (r2 * std::sqrt(r2)));
  }
  return v;
}

glm::vec3 FlowField::noise(const glm::vec3& x) const {
  if (noiseAmplitude_ <= 0.0f) return glm::vec3(0.0f);
  return noiseAmplitude_ * perlin_.noise3(x * noiseFrequency_);
}

}  // namespace mq
