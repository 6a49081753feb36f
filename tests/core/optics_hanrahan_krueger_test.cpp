// Hanrahan-Krueger single scattering: the BRDF's albedo against the 1-D
// closed forms of oracles O11 and O12 (../shared/docs/research/skin-appearance.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/optics/hanrahan_krueger.h"
#include "core/optics/phase.h"
#include "core/optics_test_util.h"

namespace mq::optics {
namespace {

using test::simpson;
constexpr double kPi = std::numbers::pi;

glm::dvec3 direction(double cosTheta, double phi) {
  const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// int f_r cos(theta_r) d omega_r over the hemisphere, light from straight above.
double singleScatterAlbedo(const ScatteringLayer& layer) {
  return simpson(
      [&](double mu) {
        return mu * simpson(
                        [&](double phi) {
                          return hanrahanKruegerBrdf(layer, {0, 0, 1}, direction(mu, phi));
                        },
                        0, 2 * kPi, 64);
      },
      1e-9, 1.0, 4000);
}

// 2 pi W int_0^1 p(-mu) mu / (1 + mu) (1 - e^{-tau (1 + 1/mu)}) dmu.
double expectedAlbedo(double albedo, double g, double opticalDepth) {
  return 2 * kPi * albedo *
         simpson(
             [&](double mu) {
               return henyeyGreenstein(-mu, g) * mu / (1 + mu) * -std::expm1(-opticalDepth * (1 + 1 / mu));
             },
             1e-9, 1.0, 20000);
}

TEST(OpticsHanrahanKrueger, IsotropicHalfSpaceAlbedoIsSeeligersClosedForm) {  // O11
  const ScatteringLayer layer{0.05, 0.95, 0.0, 1e30, 1.0};
  const double closedForm = 0.95 * (1.0 - std::log(2.0)) / 2.0;
  EXPECT_NEAR(closedForm, 0.14576, 5e-6);  // the brief's number
  EXPECT_NEAR(singleScatterAlbedo(layer), closedForm, 1e-6);
}

TEST(OpticsHanrahanKrueger, AnisotropicAndFiniteLayersMatchTheOneDimensionalForm) {  // O11, O12
  for (double g : {0.0, 0.85, -0.3})
    for (double tau : {0.1, 1.0, 1e30}) {
      const ScatteringLayer layer{0.05 * tau, 0.95 * tau, g, 1.0, 1.0};
      EXPECT_NEAR(singleScatterAlbedo(layer), expectedAlbedo(0.95, g, tau), 1e-5) << "g " << g << " tau " << tau;
    }
}

TEST(OpticsHanrahanKrueger, IsReciprocal) {
  const ScatteringLayer layer{0.3, 2.0, 0.8, 0.5, 1.4};
  const glm::dvec3 a = direction(0.8, 0.3), b = direction(0.35, 2.5);
  EXPECT_NEAR(hanrahanKruegerBrdf(layer, a, b), hanrahanKruegerBrdf(layer, b, a), 1e-14);
}

TEST(OpticsHanrahanKrueger, FresnelLowersIt) {
  const ScatteringLayer matched{0.3, 2.0, 0.8, 0.5, 1.0}, skin{0.3, 2.0, 0.8, 0.5, 1.4};
  const glm::dvec3 light = direction(0.9, 0.0), viewer = direction(0.7, 3.0);
  EXPECT_GT(hanrahanKruegerBrdf(matched, light, viewer), 0.0);
  EXPECT_NE(hanrahanKruegerBrdf(matched, light, viewer), hanrahanKruegerBrdf(skin, light, viewer));
}

}  // namespace
}  // namespace mq::optics
