// Oracles O1-O4 of ../shared/docs/research/skin-appearance.md: the dipole's
// profile, total and cumulative agree with each other and with Jensen 2001.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/optics/dipole.h"
#include "core/optics/fresnel.h"
#include "core/optics/skin_tone.h"
#include "core/optics_test_util.h"

namespace mq::optics {
namespace {

using test::logSimpson;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct Medium {
  double sigmaA, sigmaSPrime, eta;
};
// Jensen's skin1 channels, a low-albedo medium and an index-matched one.
const Medium kMedia[] = {{0.032, 0.74, 1.3}, {0.17, 0.88, 1.3}, {0.48, 1.01, 1.3},
                         {0.5, 1.0, 1.4},    {0.01, 2.0, 1.0},  {0.013, 1.09, 1.3}};

double integratedProfile(const Dipole& dipole, double radius) {
  return logSimpson([&](double r) { return dipole.radialReflectance(r) * kTwoPi * r; }, 1e-7, radius, 20000);
}

TEST(OpticsDipole, ProfileIntegratesToTheClosedFormTotal) {  // O1
  for (const Medium& m : kMedia) {
    const Dipole dipole(m.sigmaA, m.sigmaSPrime, m.eta);
    const double farOut = 60.0 / dipole.sigmaTr();
    EXPECT_NEAR(integratedProfile(dipole, farOut) / dipole.totalReflectance(), 1.0, 1e-6)
        << m.sigmaA << " " << m.sigmaSPrime;
  }
}

TEST(OpticsDipole, CumulativeClosedFormMatchesQuadrature) {  // O2
  for (const Medium& m : kMedia) {
    const Dipole dipole(m.sigmaA, m.sigmaSPrime, m.eta);
    for (double radius : {0.1, 0.5, 1.0, 3.0, 10.0}) {
      const double quadrature = integratedProfile(dipole, radius);
      EXPECT_NEAR(dipole.reflectanceWithin(radius) / quadrature, 1.0, 1e-6) << "R = " << radius;
    }
    EXPECT_NEAR(dipole.reflectanceWithin(1e6) / dipole.totalReflectance(), 1.0, 1e-12);
  }
}

TEST(OpticsDipole, TotalIsOneWithoutAbsorptionAndIncreasesWithAlbedo) {  // O3
  for (double a : {1.0, 2.60206, 3.2507, 5.0}) {
    EXPECT_DOUBLE_EQ(dipoleTotalReflectance(1.0, a), 1.0);
    double previous = -1.0;
    for (double albedo = 0.0; albedo <= 1.0; albedo += 0.001) {
      const double rd = dipoleTotalReflectance(albedo, a);
      EXPECT_GT(rd, previous) << "alpha' = " << albedo;
      previous = rd;
    }
  }
}

TEST(OpticsDipole, JensensMeasuredSkinReproducesThePapersReflectance) {  // O4
  // Jensen et al. 2001's table: R_d 0.44, 0.22, 0.13 and 0.63, 0.44, 0.34.
  const Rgb paper1 = {0.44, 0.22, 0.13}, paper2 = {0.63, 0.44, 0.34};
  // The brief's recomputation [M], four digits.
  const Rgb recomputed1 = {0.4360, 0.2273, 0.1310}, recomputed2 = {0.6226, 0.4333, 0.3435};
  // 1/sigma_tr [M], two digits.
  const Rgb mfp1 = {3.67, 1.37, 0.68}, mfp2 = {4.82, 1.69, 1.09};
  const SkinOptics skin1 = skinPreset("skin1"), skin2 = skinPreset("skin2");
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(skin1.totalReflectance()[c], paper1[c], 0.01) << "skin1 channel " << c;
    EXPECT_NEAR(skin2.totalReflectance()[c], paper2[c], 0.01) << "skin2 channel " << c;
    EXPECT_NEAR(skin1.totalReflectance()[c], recomputed1[c], 5e-5);
    EXPECT_NEAR(skin2.totalReflectance()[c], recomputed2[c], 5e-5);
    EXPECT_NEAR(skin1.diffuseMeanFreePath()[c], mfp1[c], 0.005);
    EXPECT_NEAR(skin2.diffuseMeanFreePath()[c], mfp2[c], 0.005);
  }
}

TEST(OpticsDipole, AlbedoInversionRoundTrips) {
  for (double a : {1.0, 2.60206, 3.2507}) {
    for (double albedo : {0.1, 0.5, 0.68, 0.9, 0.99, 0.9999}) {
      const double rd = dipoleTotalReflectance(albedo, a);
      EXPECT_NEAR(reducedAlbedoForReflectance(rd, a), albedo, 1e-9);
    }
  }
}

TEST(OpticsDipole, ColourAndRadiusGiveBackTheirDipole) {
  for (double rd : {0.05, 0.3, 0.6, 0.9}) {
    for (double mfp : {0.5, 2.0, 5.0}) {
      const ReducedCoefficients k = coefficientsFromReflectance(rd, mfp, 1.4);
      const Dipole dipole(k.sigmaA, k.sigmaSPrime, 1.4);
      EXPECT_NEAR(dipole.totalReflectance(), rd, 1e-9);
      EXPECT_NEAR(dipole.diffuseMeanFreePath(), mfp, 1e-9 * mfp);
    }
  }
}

}  // namespace
}  // namespace mq::optics
