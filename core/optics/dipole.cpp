#include "core/optics/dipole.h"

#include <cmath>
#include <numbers>

#include "core/optics/fresnel.h"

namespace mq::optics {

namespace {

// One pole's term z (1 + s d) e^{-s d} / d^3 at distance d from a pole at depth z.
double poleTerm(double z, double d, double sigmaTr) {
  return z * (1.0 + sigmaTr * d) * std::exp(-sigmaTr * d) / (d * d * d);
}

// int_0^R poleTerm r dr, the closed form above.
double poleIntegral(double z, double radius, double sigmaTr) {
  const double d = std::hypot(radius, z);
  return std::exp(-sigmaTr * z) - z * std::exp(-sigmaTr * d) / d;
}

}  // namespace

Dipole::Dipole(double sigmaA, double sigmaSPrime, double eta) {
  sigmaTPrime_ = sigmaA + sigmaSPrime;
  reducedAlbedo_ = sigmaSPrime / sigmaTPrime_;
  sigmaTr_ = std::sqrt(3.0 * sigmaA * sigmaTPrime_);
  boundaryA_ = boundaryMismatch(eta);
  zReal_ = 1.0 / sigmaTPrime_;
  zVirtual_ = zReal_ * (1.0 + 4.0 * boundaryA_ / 3.0);
}

double Dipole::radialReflectance(double r) const {
  const double real = poleTerm(zReal_, std::hypot(r, zReal_), sigmaTr_);
  const double image = poleTerm(zVirtual_, std::hypot(r, zVirtual_), sigmaTr_);
  return reducedAlbedo_ / (4.0 * std::numbers::pi) * (real + image);
}

double Dipole::reflectanceWithin(double radius) const {
  return 0.5 * reducedAlbedo_ * (poleIntegral(zReal_, radius, sigmaTr_) + poleIntegral(zVirtual_, radius, sigmaTr_));
}

double Dipole::totalReflectance() const { return dipoleTotalReflectance(reducedAlbedo_, boundaryA_); }

double dipoleTotalReflectance(double reducedAlbedo, double boundaryA) {
  const double root = std::sqrt(3.0 * (1.0 - reducedAlbedo));
  return 0.5 * reducedAlbedo * (1.0 + std::exp(-4.0 / 3.0 * boundaryA * root)) * std::exp(-root);
}

double reducedAlbedoForReflectance(double totalReflectance, double boundaryA) {
  double low = 0.0, high = 1.0;
  for (int i = 0; i < 60; ++i) {  // 2^-60: below double resolution of alpha'
    const double mid = 0.5 * (low + high);
    (dipoleTotalReflectance(mid, boundaryA) < totalReflectance ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

ReducedCoefficients coefficientsFromReflectance(double totalReflectance, double diffuseMeanFreePath, double eta) {
  const double albedo = reducedAlbedoForReflectance(totalReflectance, boundaryMismatch(eta));
  // sigma_tr = sqrt(3 (1 - alpha')) sigma_t'.
  const double sigmaTPrime = 1.0 / (diffuseMeanFreePath * std::sqrt(3.0 * (1.0 - albedo)));
  return {(1.0 - albedo) * sigmaTPrime, albedo * sigmaTPrime};
}

}  // namespace mq::optics
