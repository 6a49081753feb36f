#include "core/optics/fresnel.h"

#include <cmath>

namespace mq::optics {

double refractedCos(double cosIncident, double eta) {
  if (eta == 1.0) return cosIncident;  // exact at grazing angles too
  const double sin2Transmitted = (1.0 - cosIncident * cosIncident) / (eta * eta);
  if (sin2Transmitted > 1.0) return -1.0;
  return std::sqrt(1.0 - sin2Transmitted);
}

double fresnelDielectric(double cosIncident, double eta) {
  if (eta == 1.0) return 0.0;  // index-matched: no boundary
  const double cosT = refractedCos(cosIncident, eta);
  if (cosT < 0.0) return 1.0;
  const double perpendicular = (cosIncident - eta * cosT) / (cosIncident + eta * cosT);
  const double parallel = (eta * cosIncident - cosT) / (eta * cosIncident + cosT);
  return 0.5 * (perpendicular * perpendicular + parallel * parallel);
}

double diffuseFresnelReflectance(double eta) {
  if (eta == 1.0) return 0.0;
  if (eta > 1.0) return -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
  return -0.4399 + 0.7099 / eta - 0.3319 / (eta * eta) + 0.0636 / (eta * eta * eta);
}

double boundaryMismatch(double eta) {
  const double fdr = diffuseFresnelReflectance(eta);
  return (1.0 + fdr) / (1.0 - fdr);
}

}  // namespace mq::optics
