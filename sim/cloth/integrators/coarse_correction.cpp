#include "sim/cloth/integrators/coarse_correction.h"

#include <algorithm>
#include <queue>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mq::cloth {

namespace {

constexpr uint32_t kNone = ~0u;

// Baraff-Witkin's filter of vertex i as a matrix (0 for a pin, the tangent
// plane's projector for a resting contact).
glm::mat3 filterMatrix(const ClothState& s, size_t i) {
  if (s.invMass[i] == 0.0f) return glm::mat3(0.0f);
  if (s.contactNormal.empty()) return glm::mat3(1.0f);
  const glm::vec3& n = s.contactNormal[i];
  return glm::mat3(1.0f) - glm::outerProduct(n, n);
}

// a[begin, end) . b[begin, end) with four partial sums: the factorisation and
// the substitutions are chains of these, and one running sum would wait on
// every addition. On x86-64 the sums are two SSE2 pairs (the same
// arithmetic, in half the instructions).
double dotRange(const double* a, const double* b, size_t begin, size_t end) {
  size_t k = begin;
#if defined(__SSE2__)
  __m128d s01 = _mm_setzero_pd(), s23 = _mm_setzero_pd();
  for (; k + 4 <= end; k += 4) {
    s01 = _mm_add_pd(s01, _mm_mul_pd(_mm_loadu_pd(a + k), _mm_loadu_pd(b + k)));
    s23 = _mm_add_pd(s23, _mm_mul_pd(_mm_loadu_pd(a + k + 2), _mm_loadu_pd(b + k + 2)));
  }
  double s0 = _mm_cvtsd_f64(s01), s1 = _mm_cvtsd_f64(_mm_unpackhi_pd(s01, s01));
  const double s2 = _mm_cvtsd_f64(s23), s3 = _mm_cvtsd_f64(_mm_unpackhi_pd(s23, s23));
#else
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  for (; k + 4 <= end; k += 4) {
    s0 += a[k] * b[k];
    s1 += a[k + 1] * b[k + 1];
    s2 += a[k + 2] * b[k + 2];
    s3 += a[k + 3] * b[k + 3];
  }
#endif
  for (; k < end; ++k) s0 += a[k] * b[k];
  return (s0 + s1) + (s2 + s3);
}

// y[begin, end) -= a[begin, end) * t (two at a time with SSE2, the same arithmetic).
void subtractScaled(double* y, const double* a, double t, size_t begin, size_t end) {
  size_t k = begin;
#if defined(__SSE2__)
  const __m128d scale = _mm_set1_pd(t);
  for (; k + 2 <= end; k += 2)
    _mm_storeu_pd(y + k, _mm_sub_pd(_mm_loadu_pd(y + k), _mm_mul_pd(_mm_loadu_pd(a + k), scale)));
#endif
  for (; k < end; ++k) y[k] -= a[k] * t;
}

}  // namespace

void CoarseCorrection::build(const SpringForce& springs, size_t vertexCount) {
  std::vector<std::vector<uint32_t>> neighbours(vertexCount);
  for (const Spring& s : springs.springs()) {
    neighbours[s.a].push_back(s.b);
    neighbours[s.b].push_back(s.a);
  }
  // Walk the cloth breadth first (so neighbouring patches get close numbers
  // and A_c is banded); the first vertex not yet in a patch seeds a new one,
  // grown breadth first over vertices not yet in a patch.
  patchOf_.assign(vertexCount, kNone);
  patchCount_ = 0;
  std::vector<uint8_t> visited(vertexCount, 0);
  std::vector<uint32_t> grow;
  for (uint32_t root = 0; root < vertexCount; ++root) {
    if (visited[root]) continue;
    std::queue<uint32_t> walk;
    walk.push(root);
    visited[root] = 1;
    while (!walk.empty()) {
      const uint32_t seed = walk.front();
      walk.pop();
      for (uint32_t n : neighbours[seed])
        if (!visited[n]) visited[n] = 1, walk.push(n);
      if (patchOf_[seed] != kNone) continue;
      const uint32_t patch = uint32_t(patchCount_++);
      grow.assign(1, seed);
      patchOf_[seed] = patch;
      for (size_t k = 0; k < grow.size() && grow.size() < kPatchSize; ++k)
        for (uint32_t n : neighbours[grow[k]])
          if (patchOf_[n] == kNone && grow.size() < kPatchSize) patchOf_[n] = patch, grow.push_back(n);
    }
  }
  patchStart_.assign(patchCount_ + 1, 0);
  for (uint32_t v = 0; v < vertexCount; ++v) ++patchStart_[patchOf_[v] + 1];
  for (size_t p = 0; p < patchCount_; ++p) patchStart_[p + 1] += patchStart_[p];
  patchVertices_.resize(vertexCount);
  std::vector<uint32_t> fill(patchStart_.begin(), patchStart_.end() - 1);
  for (uint32_t v = 0; v < vertexCount; ++v) patchVertices_[fill[patchOf_[v]]++] = v;
  order_ = 3 * patchCount_;
  std::vector<uint32_t> firstPatch(patchCount_);
  for (uint32_t p = 0; p < patchCount_; ++p) firstPatch[p] = p;
  for (const Spring& s : springs.springs()) {
    const uint32_t i = patchOf_[s.a], j = patchOf_[s.b];
    firstPatch[std::max(i, j)] = std::min(firstPatch[std::max(i, j)], std::min(i, j));
  }
  firstColumn_.resize(order_);
  for (size_t row = 0; row < order_; ++row) firstColumn_[row] = 3 * firstPatch[row / 3];
  matrix_.assign(order_ * order_, 0.0);
  rhs_.assign(order_, 0.0);
  dead_.assign(order_, 0);
}

void CoarseCorrection::assemble(const ClothState& s, const std::vector<glm::mat3>& otherDiagonal,
                                const SpringForce& springs) {
  prepareAssembly(s);
  assemblePatches(s, otherDiagonal, springs, 0, patchCount_);
  factorise();
}

void CoarseCorrection::prepareAssembly(const ClothState& s) {
  patchDiagonal_.resize(patchCount_);
  // Most vertices are free (S = I): only pins and contacts pay for the
  // products, with their filters made once per vertex.
  const bool anyContact = !s.contactNormal.empty();
  filterOf_.assign(s.size(), kFree);
  filters_.clear();
  for (size_t v = 0; v < s.size(); ++v) {
    if (s.invMass[v] != 0.0f && !(anyContact && s.contactNormal[v] != glm::vec3(0.0f))) continue;
    filterOf_[v] = uint32_t(filters_.size());
    filters_.push_back(filterMatrix(s, v));
  }
}

// Every entry gets its terms in the same order whatever the patch ranges
// (vertices in order, then springs in order): the parts may run in parallel.
void CoarseCorrection::assemblePatches(const ClothState& s, const std::vector<glm::mat3>& otherDiagonal,
                                       const SpringForce& springs, size_t begin, size_t end) {
  auto owns = [&](uint32_t p) { return p >= begin && p < end; };
  // Only the lower triangle's envelope (and the diagonal 3x3 blocks) is used.
  for (size_t row = 3 * begin; row < 3 * end; ++row)
    std::fill(&matrix_[row * order_ + firstColumn_[row]], &matrix_[row * order_ + row / 3 * 3 + 3], 0.0);
  auto addBlock = [&](uint32_t pi, uint32_t pj, const glm::mat3& block) {
    double* row = &matrix_[3 * pi * order_ + 3 * pj];
    for (int r = 0; r < 3; ++r, row += order_)
      for (int c = 0; c < 3; ++c) row[c] += double(block[c][r]);  // glm: [column][row]
  };
  // The diagonal blocks are summed apart (compact, in cache) and written once.
  std::fill(patchDiagonal_.begin() + ptrdiff_t(begin), patchDiagonal_.begin() + ptrdiff_t(end), glm::dmat3(0.0));
  auto addDiagonal = [&](uint32_t p, const glm::mat3& block) {
    if (owns(p)) patchDiagonal_[p] += glm::dmat3(block);
  };
  // The block (i, j) of the symmetric A_c, stored at the lower one of (i, j) and (j, i).
  auto addLower = [&](uint32_t pi, uint32_t pj, const glm::mat3& block) {
    if (!owns(std::max(pi, pj))) return;
    if (pi >= pj)
      addBlock(pi, pj, block);
    else
      addBlock(pj, pi, glm::transpose(block));
  };
  for (size_t v = 0; v < s.size(); ++v) {
    if (!owns(patchOf_[v])) continue;
    const glm::mat3& d = otherDiagonal[v];
    if (filterOf_[v] == kFree) {
      addDiagonal(patchOf_[v], d);
      continue;
    }
    const glm::mat3& S = filters_[filterOf_[v]];
    addDiagonal(patchOf_[v], S * d * S);
  }
  // A spring adds S_a K S_a and S_b K S_b on the diagonal, -S_a K S_b and
  // its transpose off it. Within one patch of free vertices the four cancel
  // exactly (a rigid translation does not stretch the spring): skipped.
  // With K = e e^T + beta I, S_a K S_b = (S_a e)(S_b e)^T + beta S_a S_b
  // (the filters are symmetric).
  const glm::mat3 identity(1.0f);
  const auto& list = springs.springs();
  for (size_t k = 0; k < list.size(); ++k) {
    const uint32_t va = list[k].a, vb = list[k].b, pa = patchOf_[va], pb = patchOf_[vb];
    if (!owns(pa) && !owns(pb)) continue;
    const bool freeA = filterOf_[va] == kFree, freeB = filterOf_[vb] == kFree;
    if (pa == pb && freeA && freeB) continue;
    const SpringForce::ImplicitBlock& b = springs.implicitBlock(k);
    if (freeA && freeB) {
      const glm::mat3 K = glm::outerProduct(b.e, b.e) + glm::mat3(b.beta);
      addDiagonal(pa, K);
      addDiagonal(pb, K);
      addLower(pa, pb, -K);
      continue;
    }
    const glm::mat3& Sa = freeA ? identity : filters_[filterOf_[va]];
    const glm::mat3& Sb = freeB ? identity : filters_[filterOf_[vb]];
    const glm::vec3 ea = Sa * b.e, eb = Sb * b.e;
    const glm::mat3 SaSa = freeA ? identity : Sa * Sa, SbSb = freeB ? identity : Sb * Sb;
    const glm::mat3 SaSb = freeA ? Sb : freeB ? Sa : Sa * Sb;
    const glm::mat3 offDiagonal = glm::outerProduct(ea, eb) + b.beta * SaSb;  // glm: outerProduct(c, r) = c r^T
    addDiagonal(pa, glm::outerProduct(ea, ea) + b.beta * SaSa);
    addDiagonal(pb, glm::outerProduct(eb, eb) + b.beta * SbSb);
    if (pa != pb) {
      addLower(pa, pb, -offDiagonal);
    } else {  // (a, b) and (b, a) land on the same block
      addDiagonal(pa, -offDiagonal);
      addDiagonal(pa, -glm::transpose(offDiagonal));
    }
  }
  for (size_t p = begin; p < end; ++p) {
    double* row = &matrix_[3 * p * order_ + 3 * p];
    for (int r = 0; r < 3; ++r, row += order_)
      for (int c = 0; c < 3; ++c) row[c] += patchDiagonal_[p][c][r];
  }
}

// In-place envelope Cholesky A_c = L L^T (lower triangle). An unknown without
// stiffness (every vertex of its patch pinned, or all held along the same
// contact normal) is dropped: its row and column become the identity's and
// its coarse correction is zero.
void CoarseCorrection::factorise() {
  for (size_t i = 0; i < order_; ++i) {
    const size_t fi = firstColumn_[i];
    for (size_t j = fi; j <= i; ++j) {
      if (j < i && dead_[j]) {
        at(i, j) = 0.0;
        continue;
      }
      const double* li = &matrix_[i * order_];
      const double* lj = &matrix_[j * order_];
      const double sum = at(i, j) - dotRange(li, lj, std::max(fi, size_t(firstColumn_[j])), j);
      if (j < i) {
        at(i, j) = sum / at(j, j);
      } else {
        const double original = at(i, i);
        dead_[i] = !(original > 0.0) || !(sum > 1e-9 * original);
        at(i, i) = dead_[i] ? 1.0 : std::sqrt(sum);
        if (dead_[i])
          for (size_t k = fi; k < i; ++k) at(i, k) = 0.0;
      }
    }
  }
}

double CoarseCorrection::solve(const std::vector<glm::vec3>& r, std::vector<glm::vec3>& perPatch) {
  restrictResidual(r, 0, patchCount_);
  return solveRestricted(perPatch);
}

void CoarseCorrection::restrictResidual(const std::vector<glm::vec3>& r, size_t begin, size_t end) {
  // Summed patch by patch (in registers: not one read-modify-write per vertex).
  for (size_t p = begin; p < end; ++p) {
    double sx = 0.0, sy = 0.0, sz = 0.0;
    for (uint32_t k = patchStart_[p]; k < patchStart_[p + 1]; ++k) {
      const glm::vec3& rv = r[patchVertices_[k]];
      sx += double(rv.x), sy += double(rv.y), sz += double(rv.z);
    }
    rhs_[3 * p] = sx, rhs_[3 * p + 1] = sy, rhs_[3 * p + 2] = sz;
  }
}

double CoarseCorrection::solveRestricted(std::vector<glm::vec3>& perPatch) {
  x_.assign(rhs_.begin(), rhs_.end());
  std::vector<double>& x = x_;
  for (size_t i = 0; i < order_; ++i) {
    if (dead_[i]) {
      x[i] = 0.0;
      continue;
    }
    const double* li = &matrix_[i * order_];
    x[i] = (x[i] - dotRange(li, x.data(), firstColumn_[i], i)) / li[i];
  }
  for (size_t i = order_; i-- > 0;) {
    const double* li = &matrix_[i * order_];
    const double xi = x[i] /= li[i];
    subtractScaled(x.data(), li, xi, firstColumn_[i], i);
  }
  perPatch.resize(patchCount_);
  double dot = 0.0;
  for (size_t p = 0; p < patchCount_; ++p) {
    for (int c = 0; c < 3; ++c) {
      const double value = dead_[3 * p + c] ? 0.0 : x[3 * p + c];
      perPatch[p][c] = float(value);
      dot += rhs_[3 * p + c] * value;
    }
  }
  return dot;
}

}  // namespace mq::cloth
