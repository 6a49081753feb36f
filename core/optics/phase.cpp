#include "core/optics/phase.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mq::optics {

double henyeyGreenstein(double cosPsi, double g) {
  const double denominator = 1.0 + g * g - 2.0 * g * cosPsi;
  return (1.0 - g * g) / (4.0 * std::numbers::pi * denominator * std::sqrt(denominator));
}

double sampleHenyeyGreenstein(double g, double xi) {
  if (std::abs(g) < 1e-4) return 2.0 * xi - 1.0;
  const double ratio = (1.0 - g * g) / (1.0 - g + 2.0 * g * xi);
  const double cosPsi = (1.0 + g * g - ratio * ratio) / (2.0 * g);
  return std::clamp(cosPsi, -1.0, 1.0);
}

double schlickK(double g) { return 1.55 * g - 0.55 * g * g * g; }

double schlickPhase(double cosPsi, double g) {
  const double k = schlickK(g);
  const double denominator = 1.0 - k * cosPsi;
  return (1.0 - k * k) / (4.0 * std::numbers::pi * denominator * denominator);
}

}  // namespace mq::optics
