#include "core/optics/burley.h"

#include <cmath>
#include <numbers>

namespace mq::optics {

double BurleyProfile::radial(double r) const {
  return albedo * (std::exp(-r / shape) + std::exp(-r / (3.0 * shape))) / (8.0 * std::numbers::pi * shape * r);
}

double BurleyProfile::fractionWithin(double r) const {
  return 1.0 - 0.25 * std::exp(-r / shape) - 0.75 * std::exp(-r / (3.0 * shape));
}

double BurleyProfile::lineSpread(double s) const {
  const double x = std::abs(s);
  return albedo / (4.0 * std::numbers::pi * shape) *
         (std::cyl_bessel_k(0.0, x / shape) + std::cyl_bessel_k(0.0, x / (3.0 * shape)));
}

double BurleyProfile::sampleRadius(double xi) const {
  // The CDF is increasing and concave (its density e^{-r/d} + e^{-r/3d} falls),
  // so Newton's steps from r = 0 stay left of the root and converge to it.
  double r = 0.0;
  for (int i = 0; i < 100; ++i) {
    const double density = (std::exp(-r / shape) + std::exp(-r / (3.0 * shape))) / (4.0 * shape);
    const double step = (xi - fractionWithin(r)) / density;
    r += step;
    if (step < 1e-13 * (r + shape)) break;
  }
  return r;
}

double burleyScaleSearchlightMfp(double albedo) {
  const double offset = std::abs(albedo - 0.8);
  return 1.85 - albedo + 7.0 * offset * offset * offset;
}

double burleyScaleDiffuseMfp(double albedo) { return 1.9 - albedo + 3.5 * (albedo - 0.8) * (albedo - 0.8); }

double burleyScaleSearchlightDiffuseMfp(double albedo) {
  const double offset = albedo - 0.33;
  return 3.5 + 100.0 * offset * offset * offset * offset;
}

BurleyProfile burleyFromDiffuseMfp(double albedo, double diffuseMeanFreePath) {
  return {albedo, diffuseMeanFreePath / burleyScaleSearchlightDiffuseMfp(albedo)};
}

}  // namespace mq::optics
