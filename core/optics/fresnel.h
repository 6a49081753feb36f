#pragma once
// Fresnel terms at the skin's surface (survey §1.5.2, "Modèles de réflexion
// et transmission": A = (1 + F_dr) / (1 - F_dr), which the survey writes with
// R_d for the mean diffuse Fresnel reflectance).
//
// eta is always the index of the far side over the index of the near side,
// so light leaving skin (n = 1.3) for air sees eta = 1/1.3.

namespace mq::optics {

// Unpolarised reflectance of a smooth dielectric boundary for light arriving
// at cos(theta) = cosIncident (>= 0) from the near side; 1 under total
// internal reflection.
double fresnelDielectric(double cosIncident, double eta);

// Refracted cosine (>= 0), or -1 under total internal reflection.
double refractedCos(double cosIncident, double eta);

// F_dr, the diffuse Fresnel reflectance seen from inside a medium of relative
// index eta (Egan and Hilgeman 1979 polynomial fits, as used by Jensen et al.
// 2001):
//   eta > 1:  -1.440/eta^2 + 0.710/eta + 0.668 + 0.0636 eta
//   eta < 1:  -0.4399 + 0.7099/eta - 0.3319/eta^2 + 0.0636/eta^3
// Both fits give about 0.0016 at eta = 1; an index-matched boundary reflects
// nothing, so eta == 1 returns exactly 0.
double diffuseFresnelReflectance(double eta);

// Jensen's boundary term A = (1 + F_dr) / (1 - F_dr).
double boundaryMismatch(double eta);

}  // namespace mq::optics
