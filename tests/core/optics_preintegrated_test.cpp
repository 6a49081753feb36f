// Pre-integrated skin LUT: oracles O19-O22 of ../shared/docs/research/skin-appearance.md.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/optics/burley.h"
#include "core/optics/gaussian_sum.h"
#include "core/optics/preintegrated.h"
#include "core/optics/skin_tone.h"
#include "core/optics_test_util.h"

namespace mq::optics {
namespace {

using test::simpson;
constexpr double kPi = std::numbers::pi;

// int_{-pi}^{pi} D dtheta; D is even in theta.
double integralOverTheta(const LineSpreadKernel& kernel, double curvature) {
  return 2.0 * simpson([&](double theta) { return preintegratedDiffuse(kernel, theta, curvature); }, 0, kPi, 512);
}

TEST(OpticsPreintegrated, EveryRingIntegratesToTwo) {  // O19
  const LineSpreadKernel burley = burleyKernel({0.8, 0.5});
  const LineSpreadKernel deonRed = gaussianKernel(deonSkinProfile()[0]);
  for (double curvature : {0.0, 0.01, 0.1, 0.5, 1.0, 2.0, 20.0}) {
    EXPECT_NEAR(integralOverTheta(burley, curvature), 2.0, 1e-4) << "curvature " << curvature;
    EXPECT_NEAR(integralOverTheta(deonRed, curvature), 2.0, 1e-4) << "curvature " << curvature;
  }
}

double worstDeviationFromLambert(const LineSpreadKernel& kernel, double radius) {
  double worst = 0.0;
  for (double theta = 0.0; theta <= kPi; theta += kPi / 1440)
    worst =
        std::max(worst, std::abs(preintegratedDiffuse(kernel, theta, 1.0 / radius) - std::max(std::cos(theta), 0.0)));
  return worst;
}

// O20, flat limit. With the line-spread kernel P the blur of max(cos, 0) is
// largest at the terminator, where D = E_P[max(s, 0)] / r to first order in
// 1/r; for a sum of Gaussians E_P[max(s, 0)] = sum w_k sqrt(v_k) / sqrt(2 pi)
// (0.357 mm for d'Eon's red).
TEST(OpticsPreintegrated, FlatSkinTendsToLambertAsOneOverRadius) {  // O20
  const GaussianSum red = deonSkinProfile()[0];
  double halfMean = 0.0;
  for (size_t k = 0; k < red.weights.size(); ++k) halfMean += red.weights[k] * std::sqrt(red.variances[k]);
  halfMean /= std::sqrt(2.0 * kPi);
  const LineSpreadKernel kernel = gaussianKernel(red);
  for (double radius : {100.0, 1000.0})
    EXPECT_NEAR(worstDeviationFromLambert(kernel, radius), halfMean / radius, 0.02 * halfMean / radius) << radius;
}

// O20 as the brief measured it (0.0010 at 100 mm, <= 0.002): Penner's
// original ring, weighted by the radial profile R at the chord distance
// instead of P. This reproduces the brief's number, so the two disagree only
// by the choice of kernel, not by the ring integration.
TEST(OpticsPreintegrated, PennersRadialRingIsFlatWithinTheBriefsBound) {  // O20
  const GaussianSum red = deonSkinProfile()[0];
  const LineSpreadKernel radialRing =
      LineSpreadKernel::fromLineSpread([&](double s) { return red.radial(s); }, 6.0 * std::sqrt(7.41));
  const double worst = worstDeviationFromLambert(radialRing, 100.0);
  EXPECT_LE(worst, 0.002);
  EXPECT_NEAR(worst, 0.0010, 0.0002);
}

TEST(OpticsPreintegrated, TinyRadiusBlursToUniform) {  // O21
  // d'Eon's narrowest red Gaussian alone: sigma = 0.08 mm; radius 0.0008 mm.
  const LineSpreadKernel narrow = gaussianKernel({{0.0064}, {1.0}});
  for (double theta = 0.0; theta <= kPi; theta += kPi / 36)
    EXPECT_NEAR(preintegratedDiffuse(narrow, theta, 1.0 / 0.0008), 1.0 / kPi, 1e-3) << "theta " << theta;
}

TEST(OpticsPreintegrated, BurleyKernelConvergesAtTheTerminator) {  // O22
  // Ring of radius 2 mm, d = 0.5 mm, at the terminator: the brief measured
  // 0.1623 with 64k samples of the line-spread kernel.
  const LineSpreadKernel burley = burleyKernel({1.0, 0.5});
  const double coarse = preintegratedDiffuse(burley, kPi / 2, 0.5, 256);
  const double fine = preintegratedDiffuse(burley, kPi / 2, 0.5, 512);
  EXPECT_LT(std::abs(coarse - fine), 1e-3);
  EXPECT_NEAR(fine, 0.1623, 1e-3);
  for (double theta = 0.0; theta <= kPi; theta += kPi / 18)
    EXPECT_LT(std::abs(preintegratedDiffuse(burley, theta, 1.5, 256) - preintegratedDiffuse(burley, theta, 1.5, 512)),
              1e-3);
}

TEST(OpticsPreintegrated, LutAxesMapAsDocumented) {
  const PreintegratedLut lut = buildPreintegratedLut(skinKernels(skinPreset("skin1")));
  ASSERT_EQ(lut.width, 256);
  ASSERT_EQ(lut.height, 128);
  ASSERT_EQ(lut.rgb.size(), 3u * 256 * 128);
  EXPECT_EQ(lut.nDotLAt(0), -1.0);
  EXPECT_EQ(lut.nDotLAt(255), 1.0);
  EXPECT_EQ(lut.curvatureAt(0), 0.0);
  EXPECT_EQ(lut.curvatureAt(127), 2.0);
  EXPECT_NEAR(lut.textureU(-1.0), 0.5 / 256, 1e-12);
  EXPECT_NEAR(lut.textureU(1.0), 255.5 / 256, 1e-12);
  EXPECT_NEAR(lut.textureV(lut.curvatureAt(40)), 40.5 / 128, 1e-12);
  // Row 0 is flat skin: max(N.L, 0) in every channel.
  for (int c = 0; c < lut.width; ++c)
    for (int channel = 0; channel < 3; ++channel)
      EXPECT_NEAR(lut.value(c, 0, channel), std::max(lut.nDotLAt(c), 0.0), 1e-6);
}

TEST(OpticsPreintegrated, LutValuesAreBoundedMonotoneAndMatchTheEvaluator) {  // O21, and the table = D
  for (const char* preset : {"skin1", "medium"}) {
    const SkinOptics skin = skinPreset(preset);
    const std::array<LineSpreadKernel, 3> kernels = skinKernels(skin);
    const PreintegratedLut lut = buildPreintegratedLut(kernels);
    for (int row = 0; row < lut.height; ++row)
      for (int channel = 0; channel < 3; ++channel)
        for (int c = 0; c < lut.width; ++c) {
          const float d = lut.value(c, row, channel);
          ASSERT_GE(d, 0.0f);
          ASSERT_LE(d, 1.0f);
          if (c > 0) {
            ASSERT_GE(d, lut.value(c - 1, row, channel) - 1e-6f) << preset << " row " << row;
          }
        }
    for (int row : {5, 40, 127})
      for (int c : {0, 100, 128, 140, 255})
        for (int channel = 0; channel < 3; ++channel)
          EXPECT_NEAR(lut.value(c, row, channel),
                      preintegratedDiffuse(kernels[channel], std::acos(lut.nDotLAt(c)), lut.curvatureAt(row)), 1e-3)
              << preset << " row " << row << " column " << c << " channel " << channel;
  }
}

TEST(OpticsPreintegrated, RedWrapsFurtherPastTheTerminatorThanBlue) {
  const PreintegratedLut lut = buildPreintegratedLut(skinKernels(skinPreset("skin1")));
  const int terminator = 128, row = 127;  // N.L just above 0, the most curved row
  EXPECT_GT(lut.value(terminator - 20, row, 0), lut.value(terminator - 20, row, 2));
}

}  // namespace
}  // namespace mq::optics
