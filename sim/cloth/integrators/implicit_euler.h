#pragma once
// Implicit (backward) Euler after Baraff and Witkin, "Large steps in cloth
// simulation" (SIGGRAPH 1998): one linearised solve per step,
//
//   A dv = b,  A = M - h df/dv - h^2 df/dx,  b = h (f0 + h df/dx v0),
//   v1 = v0 + dv,  x1 = x0 + h v1,
//
// with A applied matrix-free by the force terms and solved by their
// "modified" preconditioned conjugate gradients: constrained vertices are
// filtered (S_i = 0 for pins, I - n n^T for a resting contact with normal n,
// whose normal velocity is set to zero through the start value z), the
// preconditioner is the inverse of A's 3x3 diagonal blocks, optionally plus a
// coarse level (coarse_correction.h). Each CG iteration is three fused vertex
// loops (product and dot, update and dot, direction), on large cloths as
// phases of one pool job (or on the caller alone, whichever PoolChooser found
// faster lately: the same results), and with the coarse level one small
// sequential solve.

#include <vector>

#include "core/util/pool_chooser.h"
#include "sim/cloth/integrators/cg_update.h"
#include "sim/cloth/integrators/coarse_correction.h"
#include "sim/cloth/integrators/integrator.h"

namespace mq::cloth {

class PhasedJob;

class ImplicitEuler : public Integrator {
 public:
  ImplicitEuler(int maxIterations, float tolerance, bool twoLevel = false)
      : maxIterations_(maxIterations), tolerance_(tolerance), twoLevel_(twoLevel) {}
  IntegratorReport step(ClothState& s, float h, ClothForces& forces) override;
  float stableStep(const ClothState& s, const ClothForces& forces) const override;
  // Where a large cloth's CG iterations run: as PoolChooser finds faster
  // (the default), always on the pool, or always on the calling thread
  // alone (Never: its preparation too; otherwise that is on the pool).
  enum class PoolUse { Chosen, Always, Never };
  void setPoolUse(PoolUse use) { poolUse_ = use; }

 private:
  void finishVertex(const ClothState& s, float h, size_t i);
  // Runs `job` (the step's preparation, its last phase `prepared`, or empty
  // and -1) with the solve's first phases on the pool when `prepareOnPool`,
  // then the CG iterations on the pool when `onPool`; else on the caller
  // alone. The preparation is a few phases of much work each: it pays on
  // the pool even where the iterations' many short phases do not.
  IntegratorReport solve(const ClothState& s, ClothForces& forces, PhasedJob& job, int prepared, bool prepareOnPool,
                         bool onPool);
  // y_i = filter(M p + sum of the terms' products)_i for i in [b, e) (after
  // the terms' productPass(p)); returns the sum of p_i . y_i.
  double multiplyFilteredRange(const ClothState& s, const ClothForces& forces, const std::vector<glm::vec3>& p,
                               std::vector<glm::vec3>& y, size_t b, size_t e) const;

  int maxIterations_;
  float tolerance_;
  bool twoLevel_;
  CoarseCorrection coarse_;
  std::vector<glm::vec3> coarseZ_;
  std::vector<glm::vec3> f_, b_, dv_, r_, c_, q_;
  SplitVec3 z_;
  std::vector<glm::mat3> diagonal_, otherDiagonal_;
  LaneBlocks preconditioner_;
  PoolChooser poolChoice_;
  PoolUse poolUse_ = PoolUse::Chosen;
};

}  // namespace mq::cloth
