#include "sim/cloth/integrators/explicit_integrators.h"

#include <cmath>
#include <limits>

#include "sim/cloth/parallel.h"

namespace mq::cloth {

IntegratorReport SymplecticEuler::step(ClothState& s, float h, ClothForces& forces) {
  forces.computeForces(s, f_);
  forRange(s.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      s.v[i] += (h * s.invMass[i]) * f_[i];
      s.x[i] += h * s.v[i];
    }
  });
  return {};
}

IntegratorReport VelocityVerlet::step(ClothState& s, float h, ClothForces& forces) {
  forces.computeForces(s, f0_);
  trial_ = s;
  forRange(s.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const glm::vec3 a = s.invMass[i] * f0_[i];
      trial_.x[i] = s.x[i] + h * s.v[i] + (0.5f * h * h) * a;
      trial_.v[i] = s.v[i] + h * a;
    }
  });
  forces.computeForces(trial_, f1_);
  forRange(s.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      s.x[i] = trial_.x[i];
      s.v[i] += (0.5f * h * s.invMass[i]) * (f0_[i] + f1_[i]);
    }
  });
  return {};
}

float RungeKutta4::stableStep(const ClothState& s, const ClothForces& forces) const {
  return explicitStableStep(s, forces, 2.8f);
}

IntegratorReport RungeKutta4::step(ClothState& s, float h, ClothForces& forces) {
  static constexpr float stage[4] = {0.0f, 0.5f, 0.5f, 1.0f};
  trial_ = s;
  for (int k = 0; k < 4; ++k) {
    dx_[k].resize(s.size());
    dv_[k].resize(s.size());
    if (k > 0) {
      const float c = stage[k] * h;
      forRange(s.size(), [&](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) {
          trial_.x[i] = s.x[i] + c * dx_[k - 1][i];
          trial_.v[i] = s.v[i] + c * dv_[k - 1][i];
        }
      });
    }
    forces.computeForces(trial_, f_);
    forRange(s.size(), [&](size_t b, size_t e) {
      for (size_t i = b; i < e; ++i) {
        dx_[k][i] = trial_.v[i];
        dv_[k][i] = s.invMass[i] * f_[i];
      }
    });
  }
  forRange(s.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      s.x[i] += (h / 6.0f) * (dx_[0][i] + 2.0f * dx_[1][i] + 2.0f * dx_[2][i] + dx_[3][i]);
      s.v[i] += (h / 6.0f) * (dv_[0][i] + 2.0f * dv_[1][i] + 2.0f * dv_[2][i] + dv_[3][i]);
    }
  });
  return {};
}

}  // namespace mq::cloth
