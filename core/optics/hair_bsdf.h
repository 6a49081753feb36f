#pragma once
// A physically based hair fibre: the scattering function of a rough
// dielectric cylinder that absorbs inside, after Marschner et al. 2003
// ("Light scattering from human hair fibers"), with the energy-conserving
// terms of d'Eon et al. 2011 ("An energy-conserving hair reflectance model")
// and Chiang et al. 2016 ("A practical and controllable hair and fur model for
// production path tracing"). Beyond the survey, which stops at Kajiya-Kay
// (§2.6.2); written from the papers' equations.
//
// Frame: x along the fibre from root to tip; a direction w has
//   sin theta = w.x                  (longitudinal angle, from the normal plane)
//   phi = atan2(w.z, w.y)            (azimuth around the fibre)
// w_i points toward the light, w_o toward the viewer. h in [-1, 1] is where
// the ray meets the fibre across its width (the offset of the incident ray
// from the axis, in radii).
//
// Scattering function, a sum over paths p = 0 (R, reflection), 1 (TT, through
// the fibre), 2 (TRT, one internal reflection), 3 (all longer paths):
//   S(w_i, w_o, h) = sum_p M_p(theta_i, theta_o) A_p(theta_o, h) N_p(phi_i - phi_o, h)
//   L_o(w_o) = integral over the sphere of S L_i(w_i) dw_i
// so a white furnace (sigma_a = 0, L_i = 1 everywhere) returns L_o = 1.
//
// M_p, longitudinal (d'Eon 2011), a normalised spherical Gaussian-like lobe
// of variance v_p around the mirror cone theta_i = -theta_o, shifted by the
// cuticle scales' tilt (Marschner's alpha_p on theta_h = (theta_i + theta_o)/2):
//   M(v) = csch(1/v) / (2v) exp(-sin theta_i sin theta_o' / v) I0(cos theta_i cos theta_o' / v),
//   theta_o' = theta_o - 2 alpha_p     (so the peak is at theta_h = alpha_p),
//   alpha_R = alpha, alpha_TT = -alpha/2, alpha_TRT = -3alpha/2 (alpha < 0: R toward the root),
//   widths beta, beta/2, 2 beta:  v_R = v, v_TT = v/4, v_TRT = v_3 = 4v,
//   v = (0.726 beta_m + 0.812 beta_m^2 + 3.7 beta_m^20)^2   (Chiang 2016's fit).
// M integrates to 1 over theta_i with the weight cos theta_i for any
// theta_o'. Shifting the exit angle keeps that exact; pbrt-v3 shifts
// theta_i instead, which gains or loses about 2 alpha_p tan theta_o of the
// lobe (5 % of TT at 45 degrees). Neither is reciprocal once alpha != 0.
//
// A_p, attenuation (Chiang 2016 after Marschner): Fresnel f at the entry
// (cos = cos theta_o cos gamma_o, eta = 1.55) and the absorption T along one
// crossing of the fibre,
//   T = exp(-sigma_a 2 cos gamma_t / cos theta_t),  sin gamma_o = h,
//   sin gamma_t = h / eta',  eta' = sqrt(eta^2 - sin^2 theta_o) / cos theta_o,
//   A_0 = f, A_1 = (1 - f)^2 T, A_2 = A_1 f T, A_3 = A_2 f T / (1 - f T),
// the last the geometric sum of all longer paths, so sum A_p = 1 when T = 1.
// sigma_a is per unit of the fibre's radius.
//
// N_p, azimuthal (Chiang 2016): a logistic of scale s around the exit
// azimuth of path p, trimmed and renormalised to [-pi, pi]:
//   Phi_p = 2 p gamma_t - 2 gamma_o + p pi,
//   N_p(phi) = trimmedLogistic(wrap(phi - Phi_p), s),  N_3 = 1 / (2 pi),
//   s = sqrt(pi / 8) (0.265 beta_n + 1.194 beta_n^2 + 5.372 beta_n^22).
//
// Absorption from pigments (Chiang 2016 §4.1), concentrations of eumelanin
// (brown-black) and pheomelanin (red-yellow):
//   sigma_a = C_eu (0.419, 0.697, 1.37) + C_pheo (0.187, 0.4, 1.05)
// and from a wanted colour c of a multiply scattering hair volume (their
// inverse fit, §4.2):
//   sigma_a = (ln c / (5.969 - 0.215 b + 2.532 b^2 - 10.73 b^3 + 5.574 b^4 + 0.245 b^5))^2,  b = beta_n.
//
// Not here: importance sampling (nothing traces paths), elliptical fibres,
// the medulla.

#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace mq::optics {

using Rgb = std::array<double, 3>;

// The lobes, as bits of HairFibre::lobes (for tests and pictures of one lobe).
enum HairLobe : unsigned { kHairR = 1u, kHairTT = 2u, kHairTRT = 4u, kHairResidual = 8u, kHairAllLobes = 15u };

struct HairFibre {
  Rgb sigmaA{0.0, 0.0, 0.0};           // absorption per fibre radius, per channel
  double eta = 1.55;                   // keratin
  double longitudinalRoughness = 0.3;  // beta_m
  double azimuthalRoughness = 0.3;     // beta_n
  double alphaDegrees = -3.0;          // the R lobe's shift on theta_h (Marschner: -2 .. -4 degrees of tilt)
  unsigned lobes = kHairAllLobes;
};

// ---- The terms ----

// v of Chiang's fit for beta_m (the R lobe's variance).
double hairLongitudinalVariance(double betaM);
// s of Chiang's fit for beta_n.
double hairAzimuthalScale(double betaN);
// M(v) for the (already shifted) incident angle; cosines >= 0.
double hairLongitudinal(double sinThetaI, double cosThetaI, double sinThetaO, double cosThetaO, double v);
// The logistic of scale s on [-pi, pi], renormalised there (integrates to 1).
double trimmedLogistic(double x, double s);
// N_p for phi = phi_i - phi_o (p = 0, 1, 2).
double hairAzimuthal(double phi, int p, double s, double gammaO, double gammaT);
// A_0 .. A_3 per channel.
std::array<Rgb, 4> hairAttenuation(double sinThetaO, double h, double eta, const Rgb& sigmaA);

// ---- The fibre ----

// S(w_i, w_o, h); w_i, w_o unit vectors in the fibre frame (see the top).
Rgb hairScattering(const HairFibre& fibre, const glm::dvec3& wi, const glm::dvec3& wo, double h);
// S averaged over h in [-1, 1] (the far field: what a fibre thinner than a
// pixel shows): h = sin gamma, the midpoint rule on gamma in [-pi/2, pi/2]
// with `samples` points (smooth in gamma where it is steep in h).
Rgb hairScatteringFarField(const HairFibre& fibre, const glm::dvec3& wi, const glm::dvec3& wo, int samples = 64);

// What the shader reads (render/hair_actor.cpp): the azimuthal factors
// averaged over h, for p = 0, 1, 2,
//   Nbar_p(phi, theta_o) = 1/2 integral_{-1}^{1} A_p(theta_o, h) N_p(phi, h) dh     (per channel),
// tabulated on phi in [0, pi] (Nbar is even in phi: h -> -h mirrors it) and
// |sin theta_o| in [0, 1] (even in theta_o), nodes at both ends; and the
// residual's A_3 averaged over h (its N_3 is 1 / 2 pi). The shader
// multiplies them by M_p, which it evaluates itself.
struct HairAzimuthalTable {
  int phiCount = 0, thetaCount = 0;
  std::vector<Rgb> lobes;     // [(p * thetaCount + t) * phiCount + k]
  std::vector<Rgb> residual;  // [t]
  // Bilinear in (phi, |sin theta_o|), as the shader reads it.
  Rgb lookup(int p, double phi, double sinThetaO) const;
  Rgb residualAt(double sinThetaO) const;
};
HairAzimuthalTable hairAzimuthalTable(const HairFibre& fibre, int phiCount = 32, int thetaCount = 8, int samples = 64);
// The far-field S through the table: the shader's sum, on the CPU.
Rgb hairScatteringFromTable(const HairFibre& fibre, const HairAzimuthalTable& table, const glm::dvec3& wi,
                            const glm::dvec3& wo);

// sum_p A_p averaged over h and over w_o on the sphere: the share of light a
// fibre sends back out for light from everywhere, were each M_p and N_p to
// integrate to exactly 1 (the furnace test shows they do within 1 %). Used
// for the shader's ambient term and to order pigments.
Rgb hairMeanAlbedo(const HairFibre& fibre);

// The diffuse reflectance of a deep volume of such fibres, per channel, from
// their mean albedo a: Kubelka-Munk's R_inf = (1 - sqrt(1 - a)) / (1 + sqrt(1 - a))
// for isotropic scattering. A cheap stand-in for the light scattered many
// times between fibres (what makes blond hair bright), not Zinke et al.'s
// dual scattering; hair scatters forward, so it is an upper bound.
Rgb hairVolumeReflectance(const Rgb& meanAlbedo);

// ---- Pigments ----

struct HairPigment {
  double eumelanin = 1.3;    // brown-black, Chiang's concentration units (0 .. ~8)
  double pheomelanin = 0.0;  // red-yellow
};
Rgb hairSigmaAFromPigment(const HairPigment& pigment);
// sigma_a giving roughly `color` (linear RGB in (0, 1]) for hair of
// azimuthal roughness beta_n.
Rgb hairSigmaAFromColor(const Rgb& color, double betaN);

// "black", "brown", "blond", "red", "grey"; throws mq::Error naming them.
HairPigment hairPigmentPreset(const std::string& name);
std::vector<std::string> hairPigmentPresetNames();

}  // namespace mq::optics
