#pragma once
// Christensen-Burley normalised diffusion (Christensen and Burley 2015, the
// profile of RenderMan, Cycles and Eevee). It stands in for the survey's
// BSSRDF diffusion term L_d (§1.5.2) with a shape fitted to Monte-Carlo
// references; it is not in the survey.
//
//   R(r) = A (e^{-r/d} + e^{-r/(3d)}) / (8 pi d r)     (mm^-2), int R 2 pi r dr = A
//   fraction within r:  1 - e^{-r/d}/4 - 3 e^{-r/(3d)}/4
//   d = l / s, with l a mean free path and s the scaling factor of the fit.
//
// Line-spread (Abel) projection, the response along a line to a line source,
// which is what a ring integral needs (preintegrated.h):
//   P(s) = int R(sqrt(s^2 + t^2)) dt = A/(4 pi d) [K0(s/d) + K0(s/(3d))]   (mm^-1),
//   int_{-inf}^{inf} P ds = A.

namespace mq::optics {

struct BurleyProfile {
  double albedo = 1.0;  // A, the total diffuse reflectance
  double shape = 1.0;   // d (mm)

  double radial(double r) const;          // R(r)
  double fractionWithin(double r) const;  // CDF of the normalised profile
  double lineSpread(double s) const;      // P(s)
  // The radius at which fractionWithin reaches xi in [0, 1): importance
  // sampling of the profile over the disc (its angle is uniform).
  double sampleRadius(double xi) const;
};

// Scaling factors s(A) of the fit (Christensen and Burley 2015, §5):
// searchlight configuration with l the (volume) mean free path 1/sigma_t,
double burleyScaleSearchlightMfp(double albedo);  // 1.85 - A + 7 |A - 0.8|^3
// diffuse transmission with l the mean free path (Cycles' choice),
double burleyScaleDiffuseMfp(double albedo);  // 1.9 - A + 3.5 (A - 0.8)^2
// searchlight with l the diffuse mean free path 1/sigma_tr.
double burleyScaleSearchlightDiffuseMfp(double albedo);  // 3.5 + 100 (A - 0.33)^4

// The profile for a diffuse colour and a diffuse mean free path 1/sigma_tr (mm).
BurleyProfile burleyFromDiffuseMfp(double albedo, double diffuseMeanFreePath);

}  // namespace mq::optics
