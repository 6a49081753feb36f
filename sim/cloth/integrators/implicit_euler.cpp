#include "sim/cloth/integrators/implicit_euler.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "sim/cloth/parallel.h"

namespace mq::cloth {

namespace {

// Baraff-Witkin's filter S_i: removes the constrained directions of vertex i.
inline glm::vec3 filtered(const ClothState& s, size_t i, const glm::vec3& a) {
  if (s.invMass[i] == 0.0f) return glm::vec3(0.0f);
  if (!s.contactNormal.empty()) {
    const glm::vec3& n = s.contactNormal[i];
    return a - glm::dot(a, n) * n;
  }
  return a;
}

}  // namespace

float ImplicitEuler::stableStep(const ClothState&, const ClothForces&) const {
  return std::numeric_limits<float>::infinity();
}

double ImplicitEuler::multiplyFilteredRange(const ClothState& s, const ClothForces& forces,
                                            const std::vector<glm::vec3>& p, std::vector<glm::vec3>& y, size_t b,
                                            size_t e) const {
  const auto& terms = forces.terms();
  for (size_t i = b; i < e; ++i) y[i] = s.mass[i] * p[i];
  for (const ForceTerm* t : terms) t->addProductRange(b, e, y.data());
  double dot = 0.0;
  for (size_t i = b; i < e; ++i) {
    y[i] = filtered(s, i, y[i]);
    dot += double(glm::dot(p[i], y[i]));
  }
  return dot;
}

// The last of a vertex's preparation, once every term has added its part:
// b = h (f0 + h df/dx v0), A's diagonal block and its inverse, and the
// start value of dv.
void ImplicitEuler::finishVertex(const ClothState& s, float h, size_t i) {
  b_[i] = h * f_[i] + b_[i];
  if (twoLevel_) {
    otherDiagonal_[i] += glm::mat3(s.mass[i]);
    diagonal_[i] += otherDiagonal_[i];
  } else {
    diagonal_[i] += glm::mat3(s.mass[i]);
  }
  preconditioner_.set(i, glm::inverse(diagonal_[i]));
  // z: the constrained part of dv (stop a resting contact's normal velocity).
  dv_[i] = glm::vec3(0.0f);
  if (!s.contactNormal.empty() && s.invMass[i] != 0.0f)
    dv_[i] = (s.contactSpeed[i] - glm::dot(s.v[i], s.contactNormal[i])) * s.contactNormal[i];
}

IntegratorReport ImplicitEuler::step(ClothState& s, float h, ClothForces& forces) {
  const size_t n = s.size();
  const auto start = std::chrono::steady_clock::now();
  const bool large = n >= 2 * kParallelGrain;
  const bool onPool = large && (poolUse_ == PoolUse::Chosen ? poolChoice_.nextOnPool() : poolUse_ == PoolUse::Always);
  f_.resize(n);
  b_.resize(n);
  diagonal_.resize(n);
  // Two-level: the springs' diagonal blocks apart from the others' (the coarse
  // level takes the springs exactly, block by block).
  if (twoLevel_) otherDiagonal_.resize(n);
  preconditioner_.resize(n);
  dv_.resize(n);
  if (twoLevel_ && !coarse_.built(n)) coarse_.build(forces.springs(), n);
  PhasedJob job;
  int prepared = -1;
  const auto& terms = forces.terms();
  SpringForce& springs = forces.springs();
  ExternalForces& external = forces.external();
  if (terms.size() == 2 && terms[0] == &springs && terms[1] == &external) {
    // Springs and external forces only: their force and linearisation passes
    // fused into two phases (springs, then vertices) of the solve's first job.
    external.setStep(h);
    const size_t springCount = springs.springs().size();
    // By value: the job runs in solve(), after this block's locals are gone.
    const int springPhase =
        job.add((springCount + kParallelBlock - 1) / kParallelBlock, -1, [&, springCount](size_t b) {
          springs.prepareStepSprings(s, h, b * kParallelBlock, std::min(springCount, (b + 1) * kParallelBlock));
        });
    prepared = job.add((n + kParallelBlock - 1) / kParallelBlock, springPhase, [&](size_t b) {
      for (size_t i = b * kParallelBlock; i < std::min(n, (b + 1) * kParallelBlock); ++i) {
        f_[i] = b_[i] = glm::vec3(0.0f);
        diagonal_[i] = glm::mat3(0.0f);
        springs.prepareStepVertex(i, f_[i], b_[i], diagonal_[i]);
        f_[i] += external.forceAt(s, i);
        if (twoLevel_) otherDiagonal_[i] = glm::mat3(0.0f);
        (twoLevel_ ? otherDiagonal_[i] : diagonal_[i]) += glm::mat3(external.implicitDiagonalAt(i));
        finishVertex(s, h, i);
      }
    });
  } else {
    forces.computeForces(s, f_);
    b_.assign(n, glm::vec3(0.0f));  // collects h^2 df/dx v0
    diagonal_.assign(n, glm::mat3(0.0f));
    if (twoLevel_) otherDiagonal_.assign(n, glm::mat3(0.0f));
    for (ForceTerm* t : terms) t->prepareImplicit(s, h, b_, twoLevel_ && t != &springs ? otherDiagonal_ : diagonal_);
    forRange(n, [&](size_t bb, size_t e) {
      for (size_t i = bb; i < e; ++i) finishVertex(s, h, i);
    });
  }
  const IntegratorReport report = solve(s, forces, job, prepared, large && poolUse_ != PoolUse::Never, onPool);
  if (large && poolUse_ == PoolUse::Chosen) {
    // Per iteration, the preparation counted as one.
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    poolChoice_.record(onPool, seconds.count(), double(report.solverIterations + 1));
  }
  forRange(n, [&](size_t bb, size_t e) {
    for (size_t i = bb; i < e; ++i) {
      s.v[i] += dv_[i];
      s.x[i] += h * s.v[i];
    }
  });
  return report;
}

namespace {

// Sum of the blocks' partial results in block order (as blockReduce adds them).
double sumInOrder(const double* partial) {
  double total = 0.0;
  for (size_t b = 0; b < ReduceBlocks::kCount; ++b) total += partial[b];
  return total;
}

// Patches per block of the parallel restriction P^T r.
constexpr size_t kPatchesPerBlock = 8;

// Parts of the coarse matrix's assembly on the pool (one per pool thread):
// assembled alone it kept one thread busy while the other had only the first
// product. Each part reads every spring, so on the caller alone it is one.
constexpr size_t kPoolAssemblyParts = 2;

}  // namespace

// The CG's vertex loops run as phases of one pool job per iteration (see
// PhasedJob): the new direction, the product and its dot, the update and its
// dot, and the coarse level's restriction; only the small coarse solve runs
// alone. Every vertex's arithmetic and every sum's order are those of one
// loop per phase, so the result does not depend on the grouping.
IntegratorReport ImplicitEuler::solve(const ClothState& s, ClothForces& forces, PhasedJob& job, int prepared,
                                      bool prepareOnPool, bool onPool) {
  const size_t n = s.size();
  r_.resize(n);
  z_.resize(n);
  q_.resize(n);
  c_.resize(n);
  const ReduceBlocks blocks(n);
  constexpr size_t kBlocks = ReduceBlocks::kCount;
  const size_t patchBlocks = twoLevel_ ? (coarse_.patchCount() + kPatchesPerBlock - 1) / kPatchesPerBlock : 0;
  auto addRestriction = [&](PhasedJob& job, int after) {
    if (!twoLevel_) return;
    job.add(patchBlocks, after, [&](size_t b) {
      coarse_.restrictResidual(r_, b * kPatchesPerBlock, std::min(coarse_.patchCount(), (b + 1) * kPatchesPerBlock));
    });
  };
  // z = P r is z_ (block Jacobi) plus the coarse level's per-patch part.
  auto coarseAt = [&](size_t i) { return twoLevel_ ? coarseZ_[coarse_.patchOf()[i]] : glm::vec3(0.0f); };
  double productDots[kBlocks] = {}, updateDots[kBlocks] = {};

  // r = filter(b - A z), c = filter(P r), after the phases `prepared` of
  // the job if any. The coarse matrix is assembled meanwhile.
  for (const ForceTerm* t : forces.terms()) t->productPass(dv_);
  {
    // In parts by patch range; the factorisation is claimed after the
    // product's blocks, so the thread done first with its part goes on with
    // those instead of waiting for the other part.
    int parts = -1;
    if (twoLevel_) {
      const size_t patches = coarse_.patchCount();
      const int filters = job.add(1, prepared, [&](size_t) { coarse_.prepareAssembly(s); });
      const size_t partCount = prepareOnPool ? kPoolAssemblyParts : 1;
      parts = job.add(partCount, filters, [&, partCount, patches](size_t part) {
        coarse_.assemblePatches(s, otherDiagonal_, forces.springs(), part * patches / partCount,
                                (part + 1) * patches / partCount);
      });
    }
    const int product = job.add(kBlocks, prepared, [&](size_t b) {
      if (blocks.begin(b) < blocks.end(b)) multiplyFilteredRange(s, forces, dv_, q_, blocks.begin(b), blocks.end(b));
    });
    if (twoLevel_) job.add(1, parts, [&](size_t) { coarse_.factorise(); });
    const int residual = job.add(kBlocks, product, [&](size_t bk) {
      double dot = 0.0;
      for (size_t i = blocks.begin(bk); i < blocks.end(bk); ++i) {
        r_[i] = filtered(s, i, b_[i]) - q_[i];
        const glm::vec3 z = preconditioner_.times(i, r_[i]);
        z_.x[i] = z.x, z_.y[i] = z.y, z_.z[i] = z.z;
        c_[i] = filtered(s, i, z);
        dot += double(glm::dot(r_[i], c_[i]));
      }
      updateDots[bk] = dot;
    });
    addRestriction(job, residual);
    job.run(prepareOnPool);
  }
  double delta = sumInOrder(updateDots);
  if (twoLevel_) delta += coarse_.solveRestricted(coarseZ_);
  const double delta0 = delta;
  const double stop = double(tolerance_) * double(tolerance_) * delta0;
  // The next direction: c = filter(z + coarse + beta c); the first one
  // (beta = 0) only needs the coarse part added.
  bool firstDirection = true;
  float beta = 0.0f;
  auto direction = [&](size_t b, size_t e) {
    if (firstDirection) {
      if (twoLevel_)
        for (size_t i = b; i < e; ++i) c_[i] = filtered(s, i, z_.at(i) + coarseAt(i));
      return;
    }
    for (size_t i = b; i < e; ++i) c_[i] = filtered(s, i, z_.at(i) + coarseAt(i) + beta * c_[i]);
  };
  bool fuseDirection = true;
  for (const ForceTerm* t : forces.terms()) fuseDirection = fuseDirection && t->productPassOnlyKeepsP();
  int it = 0;
  for (; it < maxIterations_ && delta > stop && delta > 0.0; ++it) {
    PhasedJob job;
    int directionPhase = -1;
    if (fuseDirection)
      directionPhase = job.add(kBlocks, -1, [&](size_t b) { direction(blocks.begin(b), blocks.end(b)); });
    else
      forRange(n, direction);
    for (const ForceTerm* t : forces.terms()) t->productPass(c_);
    const int product = job.add(kBlocks, directionPhase, [&](size_t b) {
      productDots[b] = 0.0;
      if (blocks.begin(b) < blocks.end(b))
        productDots[b] = multiplyFilteredRange(s, forces, c_, q_, blocks.begin(b), blocks.end(b));
    });
    const double deltaOld = delta;
    const int update = job.add(kBlocks, product, [&](size_t bk) {
      updateDots[bk] = 0.0;
      const double cq = sumInOrder(productDots);
      if (!(cq > 0.0)) return;
      const CgUpdate step{float(deltaOld / cq), c_.data(), q_.data(), dv_.data(), r_.data(), &preconditioner_, &z_};
      updateDots[bk] = cgUpdateRange(step, blocks.begin(bk), blocks.end(bk));
    });
    addRestriction(job, update);
    job.run(onPool);
    if (!(sumInOrder(productDots) > 0.0)) break;
    double deltaNew = sumInOrder(updateDots);
    deltaNew += twoLevel_ ? coarse_.solveRestricted(coarseZ_) : 0.0;
    beta = float(deltaNew / delta);
    delta = deltaNew;
    firstDirection = false;
  }
  return {it, delta0 > 0.0 ? float(std::sqrt(std::max(delta, 0.0) / delta0)) : 0.0f};
}

}  // namespace mq::cloth
