#include "core/optics/kubelka_munk.h"

#include <cmath>

namespace mq::optics {

KubelkaMunkLayer kubelkaMunkLayer(double absorption, double scattering, double thickness) {
  if (scattering <= 0.0) return {0.0, std::exp(-absorption * thickness), 0.0};  // Beer-Lambert
  const double a = 1.0 + absorption / scattering;
  const double b = std::sqrt(a * a - 1.0);
  const double sh = scattering * thickness;
  const double x = b * sh;
  if (x > 300.0) {
    const double opaque = kubelkaMunkOpaqueReflectance(absorption, scattering);
    return {opaque, 0.0, opaque};
  }
  // Divided through by b, so K = 0 (b = 0) needs no special case:
  // R = Sh sinhc(x) / (a Sh sinhc(x) + cosh x),  T = 1 / (same).
  const double sinhc = x < 1e-8 ? 1.0 : std::sinh(x) / x;
  const double denominator = a * sh * sinhc + std::cosh(x);
  const double reflectance = sh * sinhc / denominator;
  return {reflectance, 1.0 / denominator, reflectance};
}

double kubelkaMunkOpaqueReflectance(double absorption, double scattering) {
  const double a = 1.0 + absorption / scattering;
  return 1.0 / (a + std::sqrt(a * a - 1.0));  // = a - b without the cancellation
}

double kubelkaMunkAbsorptionOverScattering(double opaqueReflectance) {
  const double complement = 1.0 - opaqueReflectance;
  return complement * complement / (2.0 * opaqueReflectance);
}

KubelkaMunkLayer addLayers(const KubelkaMunkLayer& top, const KubelkaMunkLayer& bottom) {
  const double interreflection = 1.0 / (1.0 - top.reflectanceFromBelow * bottom.reflectance);
  return {top.reflectance + top.transmittance * top.transmittance * bottom.reflectance * interreflection,
          top.transmittance * bottom.transmittance * interreflection,
          bottom.reflectanceFromBelow +
              bottom.transmittance * bottom.transmittance * top.reflectanceFromBelow * interreflection};
}

}  // namespace mq::optics
