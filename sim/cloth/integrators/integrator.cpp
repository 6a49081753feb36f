#include "sim/cloth/integrators/integrator.h"

#include <cmath>
#include <limits>

#include "sim/cloth/integrators/explicit_integrators.h"
#include "sim/cloth/integrators/implicit_euler.h"

namespace mq::cloth {

float Integrator::stableStep(const ClothState& s, const ClothForces& forces) const {
  return explicitStableStep(s, forces, 2.0f);
}

float explicitStableStep(const ClothState& s, const ClothForces& forces, float reach) {
  // Gershgorin bounds on the stiffness and damping rates of the stiffest vertex.
  const float omega = std::sqrt(forces.maxStiffnessPerMass(s.mass));
  const float damping = forces.maxDampingPerMass(s.mass);
  const float hStiff = omega > 0.0f ? reach / omega : std::numeric_limits<float>::infinity();
  const float hDamp = damping > 0.0f ? 1.0f / damping : std::numeric_limits<float>::infinity();
  return 0.9f * std::min(hStiff, hDamp);
}

std::unique_ptr<Integrator> makeIntegrator(const ClothSettings& settings) {
  switch (settings.integrator) {
    case IntegratorKind::SymplecticEuler:
      return std::make_unique<SymplecticEuler>();
    case IntegratorKind::Verlet:
      return std::make_unique<VelocityVerlet>();
    case IntegratorKind::RK4:
      return std::make_unique<RungeKutta4>();
    case IntegratorKind::ImplicitEuler:
      return std::make_unique<ImplicitEuler>(settings.cgMaxIterations, settings.cgTolerance,
                                             settings.cgPreconditioner == CgPreconditioner::TwoLevel);
  }
  return nullptr;
}

}  // namespace mq::cloth
