#pragma once
// Kubelka-Munk two-flux model of a layer (Kubelka and Munk 1931; survey
// §1.5.1, "Résolution analytique"). Down and up fluxes in a layer of
// absorption K, scattering S (mm^-1) and thickness h obey
//   dPhi_d / (S dh) = a Phi_d - Phi_u,   -dPhi_u / (S dh) = a Phi_u - Phi_d,
// with a = 1 + K/S (the survey prints a = 1 + (sigma_a + sigma_s), a typo).
// With b = sqrt(a^2 - 1) and c = a sinh(bSh) + b cosh(bSh):
//   R = sinh(bSh) / c,   T = b / c,   opaque R_inf = a - b,
//   inverse K/S = (1 - R_inf)^2 / (2 R_inf).
// Layers stack by the adding rule, with multiple reflections between them:
//   R12 = R1 + T1^2 R2 / (1 - R1' R2),   T12 = T1 T2 / (1 - R1' R2),
// where R1' is the top layer's reflectance seen from below. One uniform layer
// is symmetric (R' = R); a stack is not, so R' is carried along, which keeps
// the rule associative.
// How K and S relate to sigma_a and sigma_s' is a convention, not part of the
// model (skin_tone.h states the one it uses).

namespace mq::optics {

struct KubelkaMunkLayer {
  double reflectance = 0, transmittance = 1;
  double reflectanceFromBelow = 0;  // equal to reflectance for one uniform layer
};

KubelkaMunkLayer kubelkaMunkLayer(double absorption, double scattering, double thickness);
double kubelkaMunkOpaqueReflectance(double absorption, double scattering);  // R_inf
double kubelkaMunkAbsorptionOverScattering(double opaqueReflectance);       // K/S

// `top` over `bottom`, lit from above.
KubelkaMunkLayer addLayers(const KubelkaMunkLayer& top, const KubelkaMunkLayer& bottom);

}  // namespace mq::optics
