#include "core/optics/hanrahan_krueger.h"

#include <cmath>

#include "core/optics/fresnel.h"
#include "core/optics/phase.h"

namespace mq::optics {

namespace {

// The direction light from `outside` (pointing away from the surface) takes
// inside the layer after refraction; it goes down (z < 0).
glm::dvec3 refractedDown(const glm::dvec3& outside, double eta) {
  const double cosInside = refractedCos(outside.z, eta);
  const glm::dvec2 tangent = -glm::dvec2(outside.x, outside.y) / eta;
  return {tangent.x, tangent.y, -cosInside};
}

}  // namespace

double hanrahanKruegerBrdf(const ScatteringLayer& layer, const glm::dvec3& toLight, const glm::dvec3& toViewer) {
  const glm::dvec3 incident = refractedDown(toLight, layer.eta);
  const glm::dvec3 leaving = -refractedDown(toViewer, layer.eta);  // reversed path: going up
  const double cosIn = -incident.z, cosOut = leaving.z;
  const double sigmaT = layer.sigmaA + layer.sigmaS;
  const double albedo = layer.sigmaS / sigmaT;
  const double transmitIn = 1.0 - fresnelDielectric(toLight.z, layer.eta);
  const double transmitOut = 1.0 - fresnelDielectric(toViewer.z, layer.eta);
  const double phase = henyeyGreenstein(glm::dot(incident, leaving), layer.g);
  const double opticalDepth = sigmaT * layer.thickness;
  const double thicknessFactor = -std::expm1(-opticalDepth * (1.0 / cosIn + 1.0 / cosOut));
  return albedo * transmitIn * transmitOut * phase / (cosIn + cosOut) * thicknessFactor;
}

}  // namespace mq::optics
