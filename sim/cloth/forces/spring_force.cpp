#include "sim/cloth/forces/spring_force.h"

#include <algorithm>
#include <cmath>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

#include "sim/cloth/parallel.h"

namespace mq::cloth {

namespace {

using SpringFrame = SpringForce::SpringFrame;

// Inlined: called per spring in the force and the implicit passes of every
// step (out of line it cost more than its arithmetic).
[[gnu::always_inline]] inline SpringFrame frameOf(const glm::vec3& xa, const glm::vec3& xb) {
  const glm::vec3 delta = xa - xb;
  const float l = glm::length(delta);
  return {l > 1e-12f ? delta / l : glm::vec3(0.0f), l};
}

glm::mat3 stiffness(const Spring& s, const SpringFrame& fr, bool filtered) {
  const glm::mat3 ddT = glm::outerProduct(fr.d, fr.d);
  float lateral = fr.length > 1e-12f ? 1.0f - s.rest / fr.length : 0.0f;
  if (filtered) lateral = std::max(lateral, 0.0f);
  return -s.k * (ddT + lateral * (glm::mat3(1.0f) - ddT));
}

}  // namespace

SpringForce::SpringForce(std::vector<Spring> springs, size_t vertexCount) : springs_(std::move(springs)) {
  std::vector<uint32_t> count(vertexCount + 1, 0);
  for (const Spring& s : springs_) {
    ++count[s.a + 1];
    ++count[s.b + 1];
  }
  for (size_t v = 0; v < vertexCount; ++v) count[v + 1] += count[v];
  incidenceStart_ = count;
  incidence_.resize(2 * springs_.size());
  std::vector<uint32_t> fill(count.begin(), count.end() - 1);
  for (size_t i = 0; i < springs_.size(); ++i) {
    incidence_[fill[springs_[i].a]++] = int32_t(i + 1);
    incidence_[fill[springs_[i].b]++] = -int32_t(i + 1);
  }
  perSpring_.resize(springs_.size());
  force_.resize(springs_.size());
  blocks_.resize(springs_.size());
  buildRows(vertexCount);
}

void SpringForce::gather(const std::vector<glm::vec3>& perSpring, std::vector<glm::vec3>& y) const {
  forRange(y.size(), [&](size_t b, size_t e) {
    for (size_t v = b; v < e; ++v) y[v] += gatherAt(v, perSpring);
  });
}

[[gnu::always_inline]] inline glm::vec3 SpringForce::forceOf(const Spring& s, const ClothState& st,
                                                             const SpringFrame& fr) {
  const float relSpeed = glm::dot(st.v[s.a] - st.v[s.b], fr.d);
  return -(s.k * (fr.length - s.rest) + s.kd * relSpeed) * fr.d;
}

void SpringForce::addForces(const ClothState& st, std::vector<glm::vec3>& f) const {
  forRange(springs_.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const Spring& s = springs_[i];
      perSpring_[i] = forceOf(s, st, frameOf(st.x[s.a], st.x[s.b]));
    }
  });
  gather(perSpring_, f);
}

double SpringForce::potentialEnergy(const ClothState& st) const {
  return deterministicSum(springs_.size(), [&](size_t i) {
    const Spring& s = springs_[i];
    const double stretch = double(glm::length(st.x[s.a] - st.x[s.b])) - s.rest;
    return 0.5 * s.k * stretch * stretch;
  });
}

[[gnu::always_inline]] inline void SpringForce::linearise(size_t i, const ClothState& st, float h,
                                                          const SpringFrame& fr) {
  const Spring& s = springs_[i];
  // -h^2 K + h kd d d^T with K = -k [d d^T + lateral (I - d d^T)].
  const float lateral = fr.length > 1e-12f ? std::max(0.0f, 1.0f - s.rest / fr.length) : 0.0f;
  const float alpha = h * h * s.k * (1.0f - lateral) + h * s.kd, beta = h * h * s.k * lateral;
  blocks_[i] = {std::sqrt(alpha) * fr.d, beta};
  // h^2 K (v_a - v_b) = -h^2 k [(1 - lateral) (d . dv) d + lateral dv].
  const glm::vec3 dv = st.v[s.a] - st.v[s.b];
  perSpring_[i] = -(h * h * s.k) * ((1.0f - lateral) * glm::dot(fr.d, dv) * fr.d + lateral * dv);
}

// (The three helpers are inlined: called per spring and per vertex in every step.)
// One pass per vertex (in the order of its incidences, as gather() sums):
// its part of h^2 K v0, its diagonal block and its sliced-ELL slots.
[[gnu::always_inline]] inline void SpringForce::collectImplicit(size_t v, glm::vec3& hKv, glm::mat3& diagonal) {
  const uint32_t first = incidenceStart_[v], degree = incidenceStart_[v + 1] - first;
  const size_t firstSlot = slotOf(v);
  // The diagonal block sum of e e^T + beta I: its six distinct entries
  // (summed as the full matrix would be, entry by entry).
  float xx = 0.0f, xy = 0.0f, xz = 0.0f, yy = 0.0f, yz = 0.0f, zz = 0.0f;
  glm::vec3 kv(0.0f);
  for (uint32_t k = 0; k < degree; ++k) {
    const int32_t signedIndex = incidence_[first + k];
    const uint32_t spring = uint32_t(std::abs(signedIndex) - 1);
    const ImplicitBlock& block = blocks_[spring];
    kv += signedIndex > 0 ? perSpring_[spring] : -perSpring_[spring];
    const glm::vec3& e = block.e;
    xx += e.x * e.x + block.beta, yy += e.y * e.y + block.beta, zz += e.z * e.z + block.beta;
    xy += e.x * e.y, xz += e.x * e.z, yz += e.y * e.z;
    const size_t slot = firstSlot + k * kLanes;  // spare slots (k >= degree) stay zero
    rowEx_[slot] = block.e.x;
    rowEy_[slot] = block.e.y;
    rowEz_[slot] = block.e.z;
    rowBeta_[slot] = block.beta;
  }
  hKv += kv;
  diagonal += glm::mat3(xx, xy, xz, xy, yy, yz, xz, yz, zz);
}

void SpringForce::prepareImplicit(const ClothState& st, float h, std::vector<glm::vec3>& hKv,
                                  std::vector<glm::mat3>& diagonal) {
  forRange(springs_.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const Spring& s = springs_[i];
      linearise(i, st, h, frameOf(st.x[s.a], st.x[s.b]));
    }
  });
  forRange(diagonal.size(), [&](size_t b, size_t e) {
    for (size_t v = b; v < e; ++v) collectImplicit(v, hKv[v], diagonal[v]);
  });
}

void SpringForce::prepareStepSprings(const ClothState& st, float h, size_t begin, size_t end) {
  for (size_t i = begin; i < end; ++i) {
    const Spring& s = springs_[i];
    const SpringFrame fr = frameOf(st.x[s.a], st.x[s.b]);
    force_[i] = forceOf(s, st, fr);
    linearise(i, st, h, fr);
  }
}

void SpringForce::prepareStepVertex(size_t v, glm::vec3& f, glm::vec3& hKv, glm::mat3& diagonal) {
  // The springs' records are read in incidence order, scattered over three
  // arrays written by the spring pass (often on the other core): fetch a few
  // vertices ahead so the misses overlap.
  constexpr size_t kAhead = 3;
  if (v + kAhead + 1 < incidenceStart_.size()) {
    for (uint32_t k = incidenceStart_[v + kAhead]; k < incidenceStart_[v + kAhead + 1]; ++k) {
      const uint32_t spring = uint32_t(std::abs(incidence_[k]) - 1);
      __builtin_prefetch(&force_[spring]);
      __builtin_prefetch(&perSpring_[spring]);
      __builtin_prefetch(&blocks_[spring]);
    }
  }
  f += gatherAt(v, force_);
  collectImplicit(v, hKv, diagonal);
}

void SpringForce::buildRows(size_t vertexCount) {
  auto degree = [&](uint32_t v) { return incidenceStart_[v + 1] - incidenceStart_[v]; };
  // Lane order: the solver's product ranges (ReduceBlocks) hold whole
  // blocks, so within each range the full blocks may take its vertices in
  // any order; by decreasing degree, a block's width wastes few slots (the
  // 10k T-shirt: 169,600 slots for 165,876 incidences, against 204,960 in
  // the vertex order). The last, partial block
  // keeps the vertex order (the scalar path takes it).
  const size_t blocks = (vertexCount + kLanes - 1) / kLanes, fullEnd = vertexCount / kLanes * kLanes;
  laneVertex_.resize(blocks * kLanes);
  for (size_t j = 0; j < laneVertex_.size(); ++j) laneVertex_[j] = int32_t(std::min(j, vertexCount - 1));
  const ReduceBlocks ranges(vertexCount);
  for (size_t r = 0; r < ReduceBlocks::kCount; ++r) {
    const size_t begin = ranges.begin(r), end = std::min(ranges.end(r), fullEnd);
    if (begin < end)
      std::stable_sort(laneVertex_.begin() + ptrdiff_t(begin), laneVertex_.begin() + ptrdiff_t(end),
                       [&](int32_t a, int32_t b) { return degree(uint32_t(a)) > degree(uint32_t(b)); });
  }
  positionOf_.resize(vertexCount);
  for (size_t j = 0; j < vertexCount; ++j) positionOf_[size_t(laneVertex_[j])] = uint32_t(j);
  rowStart_.assign(blocks + 1, 0);
  rowWidth_.assign(blocks, 0);
  for (size_t b = 0; b < blocks; ++b) {
    uint32_t width = 0;
    for (size_t j = b * kLanes; j < std::min(vertexCount, (b + 1) * kLanes); ++j)
      width = std::max(width, degree(uint32_t(laneVertex_[j])));
    rowWidth_[b] = width;
    rowStart_[b + 1] = rowStart_[b] + uint32_t(kLanes) * width;
  }
  const size_t slots = rowStart_[blocks];
  rowOther_.assign(slots, 0);
  for (size_t j = 0; j < blocks * kLanes; ++j) {
    const size_t b = j / kLanes, lane = j % kLanes;
    const uint32_t v = uint32_t(laneVertex_[j]), vertexDegree = j < vertexCount ? degree(v) : 0;
    for (uint32_t k = 0; k < rowWidth_[b]; ++k) {
      const size_t slot = rowStart_[b] + k * kLanes + lane;
      rowOther_[slot] = int32_t(3 * v);
      if (k >= vertexDegree) continue;
      const int32_t signedIndex = incidence_[incidenceStart_[v] + k];
      const uint32_t spring = uint32_t(std::abs(signedIndex) - 1);
      rowOther_[slot] = int32_t(3 * (signedIndex > 0 ? springs_[spring].b : springs_[spring].a));
    }
  }
  for (auto* row : {&rowEx_, &rowEy_, &rowEz_, &rowBeta_}) row->assign(slots, 0.0f);
}

glm::vec3 SpringForce::productAt(size_t v) const {
  const glm::vec3* p = product_->data();
  const glm::vec3 pv = p[v];
  const size_t firstSlot = slotOf(v);
  glm::vec3 sum(0.0f);
  for (uint32_t k = 0; k < rowWidth_[positionOf_[v] / kLanes]; ++k) {
    const size_t slot = firstSlot + k * kLanes;
    const glm::vec3 e(rowEx_[slot], rowEy_[slot], rowEz_[slot]);
    const glm::vec3 dp = pv - p[rowOther_[slot] / 3];
    sum += glm::dot(e, dp) * e + rowBeta_[slot] * dp;
  }
  return sum;
}

#if defined(__x86_64__) && defined(__GNUC__)
namespace {

// Eight vertices at once (one sliced-ELL block), AVX2 + FMA chosen at run
// time: lane l accumulates vertex lanes[l]'s row, so no horizontal sums. The
// eight neighbours' (and the lanes' own) positions are read as eight masked
// 16-byte loads (x, y, z; the masked fourth float is never touched) and
// transposed into x, y and z vectors: cheaper than three 8-wide gathers.
__attribute__((target("avx2,fma"))) inline __m128 loadXyz(const float* p, int32_t offset) {
  return _mm_maskload_ps(p + offset, _mm_setr_epi32(-1, -1, -1, 0));
}

__attribute__((target("avx2,fma"))) inline void loadNeighbours(const float* p, const int32_t* other, __m256& x,
                                                               __m256& y, __m256& z) {
  auto at = [&](int l) __attribute__((target("avx2,fma"))) { return loadXyz(p, other[l]); };
  const __m256 r0 = _mm256_insertf128_ps(_mm256_castps128_ps256(at(0)), at(4), 1);  // x0 y0 z0 . | x4 y4 z4 .
  const __m256 r1 = _mm256_insertf128_ps(_mm256_castps128_ps256(at(1)), at(5), 1);
  const __m256 r2 = _mm256_insertf128_ps(_mm256_castps128_ps256(at(2)), at(6), 1);
  const __m256 r3 = _mm256_insertf128_ps(_mm256_castps128_ps256(at(3)), at(7), 1);
  const __m256 t0 = _mm256_unpacklo_ps(r0, r1);  // x0 x1 y0 y1 | x4 x5 y4 y5
  const __m256 t1 = _mm256_unpackhi_ps(r0, r1);  // z0 z1 . . | z4 z5 . .
  const __m256 t2 = _mm256_unpacklo_ps(r2, r3);
  const __m256 t3 = _mm256_unpackhi_ps(r2, r3);
  x = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
  y = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
  z = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
}

__attribute__((target("avx2,fma"))) void blockProductAvx2(const float* p, const int32_t* lanes, uint32_t start,
                                                          uint32_t width, const int32_t* other, const float* ex,
                                                          const float* ey, const float* ez, const float* beta,
                                                          float* y) {
  int32_t self[8];
  for (int l = 0; l < 8; ++l) self[l] = 3 * lanes[l];
  __m256 px, py, pz;
  loadNeighbours(p, self, px, py, pz);
  __m256 ax = _mm256_setzero_ps(), ay = _mm256_setzero_ps(), az = _mm256_setzero_ps();
  for (uint32_t k = 0; k < width; ++k) {
    const uint32_t s = start + 8 * k;
    __m256 ox, oy, oz;
    loadNeighbours(p, other + s, ox, oy, oz);
    const __m256 qx = _mm256_sub_ps(px, ox), qy = _mm256_sub_ps(py, oy), qz = _mm256_sub_ps(pz, oz);
    const __m256 dx = _mm256_loadu_ps(ex + s), dy = _mm256_loadu_ps(ey + s), dz = _mm256_loadu_ps(ez + s);
    const __m256 t = _mm256_fmadd_ps(dx, qx, _mm256_fmadd_ps(dy, qy, _mm256_mul_ps(dz, qz)));
    const __m256 b = _mm256_loadu_ps(beta + s);
    ax = _mm256_fmadd_ps(t, dx, _mm256_fmadd_ps(b, qx, ax));
    ay = _mm256_fmadd_ps(t, dy, _mm256_fmadd_ps(b, qy, ay));
    az = _mm256_fmadd_ps(t, dz, _mm256_fmadd_ps(b, qz, az));
  }
  alignas(32) float sums[3][8];
  _mm256_store_ps(sums[0], ax);
  _mm256_store_ps(sums[1], ay);
  _mm256_store_ps(sums[2], az);
  for (int l = 0; l < 8; ++l) {
    float* yl = y + 3 * ptrdiff_t(lanes[l]);
    yl[0] += sums[0][l];
    yl[1] += sums[1][l];
    yl[2] += sums[2][l];
  }
}

bool hasAvx2() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
}

}  // namespace
#endif

void SpringForce::addProductRange(size_t begin, size_t end, glm::vec3* y) const {
#if defined(__x86_64__) && defined(__GNUC__)
  static_assert(kLanes == 8 && sizeof(glm::vec3) == 3 * sizeof(float));
  if (hasAvx2() && !positionOf_.empty()) {
    // Whole ranges of the lane order eight vertices at a time; the rest
    // (partly covered ranges, the last partial block) one at a time.
    const float* p = &product_->data()->x;
    const ReduceBlocks ranges(positionOf_.size());
    const size_t fullEnd = positionOf_.size() / kLanes * kLanes;
    size_t v = begin;
    while (v < end) {
      const size_t r = v / ranges.size, rangeEnd = std::min(ranges.end(r), fullEnd);
      if (v >= fullEnd || v != ranges.begin(r) || rangeEnd > end) {
        const size_t stop = std::min(end, v < fullEnd ? rangeEnd : end);
        for (; v < stop; ++v) y[v] += productAt(v);
        continue;
      }
      for (; v < rangeEnd; v += kLanes) {
        const size_t b = v / kLanes;
        blockProductAvx2(p, &laneVertex_[v], rowStart_[b], rowWidth_[b], rowOther_.data(), rowEx_.data(), rowEy_.data(),
                         rowEz_.data(), rowBeta_.data(), &y->x);
      }
    }
    return;
  }
#endif
  for (size_t v = begin; v < end; ++v) y[v] += productAt(v);
}

glm::mat3 SpringForce::stiffnessBlock(size_t spring, const std::vector<glm::vec3>& x, bool filtered) const {
  const Spring& s = springs_[spring];
  return stiffness(s, frameOf(x[s.a], x[s.b]), filtered);
}

}  // namespace mq::cloth
