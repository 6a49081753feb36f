#pragma once
// Explicit integrators (all with a = f(x, v) / m):
//  - symplectic (semi-implicit) Euler: v += h a(x, v); x += h v.
//  - velocity Verlet: x' = x + h v + h^2/2 a; a' = a(x', v + h a);
//    v' = v + h/2 (a + a'). Two force evaluations per step.
//  - classical Runge-Kutta of order 4 on (x, v). Four evaluations.

#include <vector>

#include "sim/cloth/integrators/integrator.h"

namespace mq::cloth {

class SymplecticEuler : public Integrator {
 public:
  IntegratorReport step(ClothState& s, float h, ClothForces& forces) override;

 private:
  std::vector<glm::vec3> f_;
};

class VelocityVerlet : public Integrator {
 public:
  IntegratorReport step(ClothState& s, float h, ClothForces& forces) override;

 private:
  std::vector<glm::vec3> f0_, f1_;
  ClothState trial_;
};

class RungeKutta4 : public Integrator {
 public:
  IntegratorReport step(ClothState& s, float h, ClothForces& forces) override;
  float stableStep(const ClothState& s, const ClothForces& forces) const override;

 private:
  ClothState trial_;
  std::vector<glm::vec3> f_, dx_[4], dv_[4];
};

}  // namespace mq::cloth
