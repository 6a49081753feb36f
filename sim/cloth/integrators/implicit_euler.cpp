#include "sim/cloth/integrators/implicit_euler.h"

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

double ImplicitEuler::multiplyFiltered(const ClothState& s, ClothForces& forces, const std::vector<glm::vec3>& p,
                                       std::vector<glm::vec3>& y) const {
  const auto& terms = forces.terms();
  for (const ForceTerm* t : terms) t->productPass(p);
  return blockReduce(s.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) y[i] = s.mass[i] * p[i];
    for (const ForceTerm* t : terms) t->addProductRange(b, e, y.data());
    double dot = 0.0;
    for (size_t i = b; i < e; ++i) {
      y[i] = filtered(s, i, y[i]);
      dot += double(glm::dot(p[i], y[i]));
    }
    return dot;
  });
}

IntegratorReport ImplicitEuler::step(ClothState& s, float h, ClothForces& forces) {
  const size_t n = s.size();
  forces.computeForces(s, f_);
  b_.assign(n, glm::vec3(0.0f));  // collects h^2 df/dx v0
  diagonal_.assign(n, glm::mat3(0.0f));
  // Two-level: the springs' diagonal blocks apart from the others' (the coarse
  // level takes the springs exactly, block by block).
  if (twoLevel_) otherDiagonal_.assign(n, glm::mat3(0.0f));
  for (ForceTerm* t : forces.terms())
    t->prepareImplicit(s, h, b_, twoLevel_ && t != &forces.springs() ? otherDiagonal_ : diagonal_);
  preconditioner_.resize(n);
  dv_.resize(n);
  forRange(n, [&](size_t bb, size_t e) {
    for (size_t i = bb; i < e; ++i) {
      b_[i] = h * f_[i] + b_[i];
      if (twoLevel_) {
        otherDiagonal_[i] += glm::mat3(s.mass[i]);
        diagonal_[i] += otherDiagonal_[i];
      } else {
        diagonal_[i] += glm::mat3(s.mass[i]);
      }
      preconditioner_[i] = glm::inverse(diagonal_[i]);
      // z: the constrained part of dv (stop a resting contact's normal velocity).
      dv_[i] = glm::vec3(0.0f);
      if (!s.contactNormal.empty() && s.invMass[i] != 0.0f)
        dv_[i] = (s.contactSpeed[i] - glm::dot(s.v[i], s.contactNormal[i])) * s.contactNormal[i];
    }
  });
  if (twoLevel_) {
    if (!coarse_.built(n)) coarse_.build(forces.springs(), n);
    coarse_.assemble(s, otherDiagonal_, forces.springs());
  }
  const IntegratorReport report = solve(s, forces);
  forRange(n, [&](size_t bb, size_t e) {
    for (size_t i = bb; i < e; ++i) {
      s.v[i] += dv_[i];
      s.x[i] += h * s.v[i];
    }
  });
  return report;
}

double ImplicitEuler::coarseSolve() { return twoLevel_ ? coarse_.solve(r_, coarseZ_) : 0.0; }

IntegratorReport ImplicitEuler::solve(const ClothState& s, ClothForces& forces) {
  const size_t n = s.size();
  r_.resize(n);
  z_.resize(n);
  q_.resize(n);
  c_.resize(n);
  // z = P r is z_ (block Jacobi) plus the coarse level's per-patch part.
  auto coarseAt = [&](size_t i) { return twoLevel_ ? coarseZ_[coarse_.patchOf()[i]] : glm::vec3(0.0f); };
  // r = filter(b - A z), c = filter(P r).
  multiplyFiltered(s, forces, dv_, q_);
  double delta = blockReduce(n, [&](size_t b, size_t e) {
    double dot = 0.0;
    for (size_t i = b; i < e; ++i) {
      r_[i] = filtered(s, i, b_[i]) - q_[i];
      z_[i] = preconditioner_[i] * r_[i];
      c_[i] = filtered(s, i, z_[i]);
      dot += double(glm::dot(r_[i], c_[i]));
    }
    return dot;
  });
  if (twoLevel_) {
    delta += coarseSolve();
    forRange(n, [&](size_t b, size_t e) {
      for (size_t i = b; i < e; ++i) c_[i] = filtered(s, i, z_[i] + coarseAt(i));
    });
  }
  const double delta0 = delta;
  const double stop = double(tolerance_) * double(tolerance_) * delta0;
  int it = 0;
  for (; it < maxIterations_ && delta > stop && delta > 0.0; ++it) {
    const double cq = multiplyFiltered(s, forces, c_, q_);
    if (!(cq > 0.0)) break;
    const float alpha = float(delta / cq);
    double deltaNew = blockReduce(n, [&](size_t b, size_t e) {
      double dot = 0.0;
      for (size_t i = b; i < e; ++i) {
        dv_[i] += alpha * c_[i];
        r_[i] -= alpha * q_[i];
        z_[i] = preconditioner_[i] * r_[i];
        dot += double(glm::dot(r_[i], z_[i]));
      }
      return dot;
    });
    deltaNew += coarseSolve();
    const float beta = float(deltaNew / delta);
    delta = deltaNew;
    forRange(n, [&](size_t b, size_t e) {
      for (size_t i = b; i < e; ++i) c_[i] = filtered(s, i, z_[i] + coarseAt(i) + beta * c_[i]);
    });
  }
  return {it, delta0 > 0.0 ? float(std::sqrt(std::max(delta, 0.0) / delta0)) : 0.0f};
}

}  // namespace mq::cloth
