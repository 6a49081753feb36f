#include <string>

#include "render/hair_shaders.h"

namespace mq::render {

// The physically based fibre (core/optics/hair_bsdf.h), per light:
//   S = sum_p M_p(theta_i, theta_o - 2 alpha_p) Nbar_p(phi, |sin theta_o|) + M_3 Abar_3 / 2 pi
// M_p in the shader (hairLongitudinal: hair_bsdf.cpp's, in floats, always
// through logarithms), Nbar_p from the core's table (hairAzimuthalTable).
std::string physicalHairFragmentDec() {
  return std::string(R"(//VTK::Normal::Dec
in vec3 hairTangentVC;
in vec3 hairParams;  // x: 0 root .. 1 tip, y: self-shadow, z: per-strand random
in vec3 hairTint;    // the painted pigments' colour against the style's (1: unpainted)
const int kHairPhi = )") +
         std::to_string(kTablePhi) + R"(;
const int kHairTheta = )" +
         std::to_string(kTableTheta) + R"(;
// log I0(x): the series below 12, the asymptotic series above.
float hairLogI0(float x) {
  if (x > 12.0) {
    float y = 1.0 / x;
    return x - 0.5 * log(6.2831853 * x) + log(1.0 + y * (0.125 + y * (0.0703125 + y * 0.0732421875)));
  }
  float q = 0.25 * x * x, term = 1.0, sum = 1.0;
  for (int k = 1; k < 18; ++k) {
    term *= q / float(k * k);
    sum += term;
  }
  return log(sum);
}
// d'Eon's M: csch(1/v) / (2v) exp(-sin_i sin_o / v) I0(cos_i cos_o / v).
float hairLongitudinal(float sinI, float cosI, float sinO, float cosO, float v) {
  float logNorm = v > 0.1 ? -log(2.0 * v * sinh(1.0 / v)) : -1.0 / v + 0.6931472 - log(2.0 * v);
  return exp(hairLogI0(cosI * cosO / v) - sinI * sinO / v + logNorm);
}
// Nbar_p, bilinear in (phi in [0, pi], |sin theta_o| in [0, 1]).
vec3 hairAzimuthalAt(int p, float phi, float sinO) {
  float x = phi * 0.31830989 * float(kHairPhi - 1), y = sinO * float(kHairTheta - 1);
  int k = min(int(x), kHairPhi - 2), t = min(int(y), kHairTheta - 2);
  float fx = x - float(k), fy = y - float(t);
  int i = (p * kHairTheta + t) * kHairPhi + k;
  return mix(mix(hairAzimuthalTable[i], hairAzimuthalTable[i + 1], fx),
             mix(hairAzimuthalTable[i + kHairPhi], hairAzimuthalTable[i + kHairPhi + 1], fx), fy);
}
vec3 hairResidualAt(float sinO) {
  float y = sinO * float(kHairTheta - 1);
  int t = min(int(y), kHairTheta - 2);
  return mix(hairResidualTable[t], hairResidualTable[t + 1], y - float(t));
}
)";
}

const char* const kPhysicalHairLighting = R"(
    float sinO = clamp(dot(V, T), -1.0, 1.0);
    float cosO = sqrt(max(0.0, 1.0 - sinO * sinO));
    vec3 Vp = V - sinO * T;
    // Ambient: light from all around, times the share the fibre sends back.
    // Painted pigments tint what the fibre absorbs from (all but R, the
    // surface reflection).
    vec3 color = hairAmbient * hairAlbedo * hairTint;
    for (int i = 0; i < mqLightCount; ++i) {
      vec3 L = mqLightDirVC[i];
      float sinI = clamp(dot(L, T), -1.0, 1.0);
      float cosI = sqrt(max(0.0, 1.0 - sinI * sinI));
      vec3 Lp = L - sinI * T;
      float across = length(Lp) * length(Vp);
      float phi = across > 1e-6 ? acos(clamp(dot(Lp, Vp) / across, -1.0, 1.0)) : 0.0;
      vec3 S = vec3(0.0);
      for (int p = 0; p < 3; ++p) {
        float sinOp = sinO * hairShiftCos[p] - cosO * hairShiftSin[p];
        float cosOp = abs(cosO * hairShiftCos[p] + sinO * hairShiftSin[p]);
        S += hairLobeWeight[p] * hairLongitudinal(sinI, cosI, sinOp, cosOp, hairVariance[p]) *
             hairAzimuthalAt(p, phi, abs(sinO)) * (p == 0 ? vec3(1.0) : hairTint);
      }
      S += hairLobeWeight[3] * hairLongitudinal(sinI, cosI, sinO, cosO, hairVariance[3]) *
           hairResidualAt(abs(sinO)) * 0.15915494 * hairTint;
      // Light reaching this side of the hair volume, as for Kajiya-Kay.
      // VTK's lights give a white Lambertian surface the radiance E cos,
      // which is pi times the physical E cos / pi: S takes the same pi.
      // The volume term stands for light scattered between fibres.
      float facing = clamp(0.55 + 0.45 * dot(volumeNormal, L), 0.0, 1.0);
      color += mqLightColour[i] * shadow * facing * (3.14159265 * S + hairLobeWeight4 * hairVolumeAlbedo * hairTint);
    }
    color *= 1.0 + hairColorVariation * (2.0 * hairParams.z - 1.0);
)";

}  // namespace mq::render
