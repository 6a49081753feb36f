#include "sim/cloth/integrators/implicit_euler.h"

#include <cmath>
#include <limits>

#include "sim/cloth/parallel.h"

namespace mq::cloth {

namespace {

void filterPinned(const ClothState& s, std::vector<glm::vec3>& a) {
  forRange(s.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i)
      if (s.invMass[i] == 0.0f) a[i] = glm::vec3(0.0f);
  });
}

double dot(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
  return deterministicSum(a.size(), [&](size_t i) { return double(glm::dot(a[i], b[i])); });
}

}  // namespace

float ImplicitEuler::stableStep(const ClothState&, const ClothForces&) const {
  return std::numeric_limits<float>::infinity();
}

void ImplicitEuler::multiply(const ClothState& s, ClothForces& forces, const std::vector<glm::vec3>& p,
                             std::vector<glm::vec3>& y) const {
  forRange(s.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) y[i] = s.mass[i] * p[i];
  });
  for (ForceTerm* t : forces.terms()) t->addProduct(p, y);
}

IntegratorReport ImplicitEuler::step(ClothState& s, float h, ClothForces& forces) {
  const size_t n = s.size();
  forces.computeForces(s, f_);
  b_.assign(n, glm::vec3(0.0f));  // collects h^2 df/dx v0
  diagonal_.assign(n, glm::mat3(0.0f));
  for (ForceTerm* t : forces.terms()) t->prepareImplicit(s, h, b_, diagonal_);
  preconditioner_.resize(n);
  forRange(n, [&](size_t bb, size_t e) {
    for (size_t i = bb; i < e; ++i) {
      b_[i] = h * f_[i] + b_[i];
      preconditioner_[i] = glm::inverse(diagonal_[i] + glm::mat3(s.mass[i]));
    }
  });
  const IntegratorReport report = solve(s, forces);
  forRange(n, [&](size_t bb, size_t e) {
    for (size_t i = bb; i < e; ++i) {
      s.v[i] += dv_[i];
      s.x[i] += h * s.v[i];
    }
  });
  return report;
}

IntegratorReport ImplicitEuler::solve(const ClothState& s, ClothForces& forces) {
  const size_t n = s.size();
  dv_.assign(n, glm::vec3(0.0f));
  r_ = b_;
  filterPinned(s, r_);
  z_.resize(n);
  q_.resize(n);
  auto precondition = [&](const std::vector<glm::vec3>& in, std::vector<glm::vec3>& out) {
    forRange(n, [&](size_t b, size_t e) {
      for (size_t i = b; i < e; ++i) out[i] = preconditioner_[i] * in[i];
    });
  };
  precondition(r_, z_);
  c_ = z_;
  double delta = dot(r_, z_);
  const double delta0 = delta;
  const double stop = double(tolerance_) * double(tolerance_) * delta0;
  int it = 0;
  for (; it < maxIterations_ && delta > stop && delta > 0.0; ++it) {
    multiply(s, forces, c_, q_);
    filterPinned(s, q_);
    const double cq = dot(c_, q_);
    if (!(cq > 0.0)) break;
    const float alpha = float(delta / cq);
    forRange(n, [&](size_t b, size_t e) {
      for (size_t i = b; i < e; ++i) {
        dv_[i] += alpha * c_[i];
        r_[i] -= alpha * q_[i];
      }
    });
    precondition(r_, z_);
    const double deltaNew = dot(r_, z_);
    const float beta = float(deltaNew / delta);
    delta = deltaNew;
    forRange(n, [&](size_t b, size_t e) {
      for (size_t i = b; i < e; ++i) c_[i] = z_[i] + beta * c_[i];
    });
    filterPinned(s, c_);
  }
  return {it, delta0 > 0.0 ? float(std::sqrt(delta / delta0)) : 0.0f};
}

}  // namespace mq::cloth
