#pragma once
// Time integrators: advance (x, v) by one step h under the cloth's forces.
// Vertices with invMass 0 (pins) keep their velocity (the simulator sets it
// to reach the pin target).

#include <memory>

#include "sim/cloth/cloth_settings.h"
#include "sim/cloth/cloth_state.h"
#include "sim/cloth/forces/cloth_forces.h"

namespace mq::cloth {

struct IntegratorReport {
  int solverIterations = 0;  // CG iterations (implicit), 0 for explicit
  float solverResidual = 0.0f;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual IntegratorReport step(ClothState& s, float h, ClothForces& forces) = 0;
  // The step size beyond which the method is unstable for these forces
  // (infinity for the implicit one).
  virtual float stableStep(const ClothState& s, const ClothForces& forces) const;
};

std::unique_ptr<Integrator> makeIntegrator(const ClothSettings& settings);

// Stability bound of an explicit method whose stability interval on the
// imaginary axis is `reach` (2 for symplectic Euler and Verlet, 2.8 for RK4).
float explicitStableStep(const ClothState& s, const ClothForces& forces, float reach);

}  // namespace mq::cloth
