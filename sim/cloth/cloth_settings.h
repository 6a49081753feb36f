#pragma once
// What a user chooses about a cloth simulation besides the fabric.

#include <string>

#include <glm/glm.hpp>

namespace mq::cloth {

enum class IntegratorKind { SymplecticEuler, Verlet, RK4, ImplicitEuler };
enum class BendingModel { Springs, Cantilever };
enum class StretchLimitMode { Off, PositionCorrection, VelocityCorrection };
// The implicit solve's CG preconditioner: the inverse of the 3x3 diagonal
// blocks, or that plus a coarse level of rigidly moving vertex patches
// (sim/cloth/integrators/coarse_correction.h).
enum class CgPreconditioner { BlockJacobi, TwoLevel };

struct ClothSettings {
  IntegratorKind integrator = IntegratorKind::ImplicitEuler;
  // Solver steps per step() call; 0 = automatic: 1 for the implicit
  // integrator, the stability bound of the stiffest spring for explicit ones.
  int substeps = 0;
  BendingModel bending = BendingModel::Springs;
  glm::vec3 gravity{0.0f, -9.81f, 0.0f};
  glm::vec3 wind{0.0f};     // m/s, air velocity
  float airDamping = 0.5f;  // N s/m^3: drag per unit cloth area per unit relative speed
  StretchLimitMode stretchLimit = StretchLimitMode::PositionCorrection;
  float maxStretch = 1.10f;     // Provot's limit: no structural spring longer than this times its rest length
  int stretchIterations = 100;  // passes of the correction at most per solver step
  // When the position correction cannot hold the limit in a step, the step is
  // redone with 2, 4, ... times the substeps, up to this factor (1 = never).
  int maxRefinement = 8;
  bool selfCollisions = false;
  float collisionThickness = 0.005f;  // m: cloth keeps this far from colliders and the body
  float selfThickness = 0.004f;       // m: distance kept between non-adjacent cloth elements
  float friction = -1.0f;             // < 0: the fabric's friction
  int cgMaxIterations = 100;          // implicit integrator: conjugate-gradient iterations at most
  float cgTolerance = 1e-3f;          // relative residual (preconditioned norm)
  // Two-level: far fewer iterations on stiff sheets, nearer the exact motion,
  // and on the walking T-shirt it holds the cloth out of the body at half
  // block Jacobi's iteration cap. Its converged solve carries more of the
  // cloth's momentum: a trouser leg overshoots a swinging leg that stops, so
  // the elongation limit after the contacts keeps the touched vertices out
  // of the leg (ClothSimulator::limitStretchKeepingContactsOut). Resting contacts hold on downward-facing
  // surfaces too, or the converged solve squeezes a tight waistband up into
  // the body. Garment sewing always uses block Jacobi (GarmentSimulation).
  CgPreconditioner cgPreconditioner = CgPreconditioner::TwoLevel;
};

const char* integratorName(IntegratorKind kind);
const char* bendingModelName(BendingModel model);
const char* stretchLimitName(StretchLimitMode mode);
const char* cgPreconditionerName(CgPreconditioner preconditioner);
// Parse the names above; return false for an unknown name.
bool parseIntegrator(const std::string& name, IntegratorKind& kind);
bool parseBendingModel(const std::string& name, BendingModel& model);
bool parseStretchLimit(const std::string& name, StretchLimitMode& mode);
bool parseCgPreconditioner(const std::string& name, CgPreconditioner& preconditioner);

}  // namespace mq::cloth
