#pragma once
// Implicit (backward) Euler after Baraff and Witkin, "Large steps in cloth
// simulation" (SIGGRAPH 1998): one linearised solve per step,
//
//   A dv = b,  A = M - h df/dv - h^2 df/dx,  b = h (f0 + h df/dx v0),
//   v1 = v0 + dv,  x1 = x0 + h v1,
//
// with A applied matrix-free by the force terms and solved by their
// "modified" preconditioned conjugate gradients: pinned vertices are
// filtered out of the search directions (dv = 0 there), the preconditioner is
// the inverse of A's 3x3 diagonal blocks.

#include <vector>

#include "sim/cloth/integrators/integrator.h"

namespace mq::cloth {

class ImplicitEuler : public Integrator {
 public:
  ImplicitEuler(int maxIterations, float tolerance) : maxIterations_(maxIterations), tolerance_(tolerance) {}
  IntegratorReport step(ClothState& s, float h, ClothForces& forces) override;
  float stableStep(const ClothState& s, const ClothForces& forces) const override;

 private:
  void multiply(const ClothState& s, ClothForces& forces, const std::vector<glm::vec3>& p,
                std::vector<glm::vec3>& y) const;
  IntegratorReport solve(const ClothState& s, ClothForces& forces);

  int maxIterations_;
  float tolerance_;
  std::vector<glm::vec3> f_, b_, dv_, r_, z_, c_, q_;
  std::vector<glm::mat3> diagonal_, preconditioner_;
};

}  // namespace mq::cloth
