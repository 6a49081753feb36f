#pragma once
// Jensen's dipole diffusion profile (Jensen, Marschner, Levoy, Hanrahan 2001;
// survey §1.5.2, "Estimation de la diffusion par dipôle"). The survey gives
// the idea (a real source under the surface, a negative image above it) but
// not the formulas; these follow the corrected form (Jensen 2001 misprints
// R_d(r); DreamWorks MoonRay's Dipole.cc notes it):
//
//   sigma_s' = sigma_s (1 - g),  sigma_t' = sigma_a + sigma_s',
//   alpha' = sigma_s' / sigma_t',  sigma_tr = sqrt(3 sigma_a sigma_t'),
//   z_r = 1 / sigma_t',  z_v = z_r (1 + 4A/3),  d = sqrt(r^2 + z^2),
//   R_d(r) = alpha'/(4 pi) [ z_r (1 + sigma_tr d_r) e^{-sigma_tr d_r} / d_r^3
//                          + z_v (1 + sigma_tr d_v) e^{-sigma_tr d_v} / d_v^3 ]   (mm^-2)
//   total  R_d = (alpha'/2) (1 + e^{-(4/3) A sqrt(3(1 - alpha'))}) e^{-sqrt(3(1 - alpha'))}
//
// Because  int_0^R z (1 + s d) e^{-s d} / d^3 r dr = e^{-s z} - z e^{-s d_R} / d_R,
// the reflectance inside a disc of radius R has the closed form
//   C(R) = (alpha'/2) [ e^{-sigma_tr z_r} - z_r e^{-sigma_tr d_r(R)} / d_r(R) + (same with v) ].

namespace mq::optics {

class Dipole {
 public:
  // Reduced coefficients (mm^-1) and the relative index of the medium.
  Dipole(double sigmaA, double sigmaSPrime, double eta);

  double reducedAlbedo() const { return reducedAlbedo_; }
  double sigmaTr() const { return sigmaTr_; }
  double boundaryA() const { return boundaryA_; }
  double diffuseMeanFreePath() const { return 1.0 / sigmaTr_; }  // mm

  double radialReflectance(double r) const;       // R_d(r), mm^-2
  double reflectanceWithin(double radius) const;  // C(R)
  double totalReflectance() const;

 private:
  double reducedAlbedo_, sigmaTPrime_, sigmaTr_, boundaryA_, zReal_, zVirtual_;
};

// Total diffuse reflectance of a semi-infinite medium, as a function of the
// reduced albedo and Jensen's A. Strictly increasing in alpha', 1 at alpha' = 1.
double dipoleTotalReflectance(double reducedAlbedo, double boundaryA);

// The alpha' whose dipoleTotalReflectance is totalReflectance (in [0, 1]),
// found by bisection (the function is monotone), as MoonRay's findAlphaP.
double reducedAlbedoForReflectance(double totalReflectance, double boundaryA);

// Coefficients from what an artist sets: a diffuse colour (total reflectance)
// and a diffuse mean free path 1/sigma_tr (mm), as MoonRay does.
struct ReducedCoefficients {
  double sigmaA = 0, sigmaSPrime = 0;  // mm^-1
};
ReducedCoefficients coefficientsFromReflectance(double totalReflectance, double diffuseMeanFreePath, double eta);

}  // namespace mq::optics
