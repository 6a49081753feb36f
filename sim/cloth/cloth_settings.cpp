#include "sim/cloth/cloth_settings.h"

namespace mq::cloth {

namespace {

template <class E, size_t N>
bool parseName(const std::string& name, const std::pair<const char*, E> (&table)[N], E& out) {
  for (const auto& [n, e] : table)
    if (name == n) {
      out = e;
      return true;
    }
  return false;
}

template <class E, size_t N>
const char* nameOf(E value, const std::pair<const char*, E> (&table)[N]) {
  for (const auto& [n, e] : table)
    if (e == value) return n;
  return "?";
}

const std::pair<const char*, IntegratorKind> kIntegrators[] = {{"symplectic_euler", IntegratorKind::SymplecticEuler},
                                                               {"verlet", IntegratorKind::Verlet},
                                                               {"rk4", IntegratorKind::RK4},
                                                               {"implicit_euler", IntegratorKind::ImplicitEuler}};
const std::pair<const char*, BendingModel> kBending[] = {{"springs", BendingModel::Springs},
                                                         {"cantilever", BendingModel::Cantilever}};
const std::pair<const char*, StretchLimitMode> kLimits[] = {{"off", StretchLimitMode::Off},
                                                            {"position", StretchLimitMode::PositionCorrection},
                                                            {"velocity", StretchLimitMode::VelocityCorrection}};
const std::pair<const char*, CgPreconditioner> kPreconditioners[] = {{"block_jacobi", CgPreconditioner::BlockJacobi},
                                                                     {"two_level", CgPreconditioner::TwoLevel}};

}  // namespace

const char* integratorName(IntegratorKind kind) { return nameOf(kind, kIntegrators); }
const char* bendingModelName(BendingModel model) { return nameOf(model, kBending); }
const char* stretchLimitName(StretchLimitMode mode) { return nameOf(mode, kLimits); }
bool parseIntegrator(const std::string& name, IntegratorKind& kind) { return parseName(name, kIntegrators, kind); }
bool parseBendingModel(const std::string& name, BendingModel& model) { return parseName(name, kBending, model); }
bool parseStretchLimit(const std::string& name, StretchLimitMode& mode) { return parseName(name, kLimits, mode); }
const char* cgPreconditionerName(CgPreconditioner preconditioner) { return nameOf(preconditioner, kPreconditioners); }
bool parseCgPreconditioner(const std::string& name, CgPreconditioner& preconditioner) {
  return parseName(name, kPreconditioners, preconditioner);
}

}  // namespace mq::cloth
