// Oracle O10 of ../shared/docs/research/skin-appearance.md: Burley's profile,
// its CDF and its line-spread projection all carry the albedo A.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/optics/burley.h"
#include "core/optics_test_util.h"

namespace mq::optics {
namespace {

using test::logSimpson;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
const BurleyProfile kProfiles[] = {{0.8, 0.5}, {0.3, 0.1}, {0.95, 2.0}};

TEST(OpticsBurley, ProfileIntegratesToTheAlbedo) {
  for (const BurleyProfile& p : kProfiles) {
    const double total = logSimpson([&](double r) { return p.radial(r) * kTwoPi * r; }, 1e-9, 150.0 * p.shape, 20000);
    EXPECT_NEAR(total / p.albedo, 1.0, 1e-6);
  }
}

TEST(OpticsBurley, CdfAtSixteenShapeDistancesIsCyclesTruncation) {
  for (const BurleyProfile& p : kProfiles) EXPECT_NEAR(p.fractionWithin(16.0 * p.shape), 0.99637900937, 1e-9);
}

TEST(OpticsBurley, CdfMatchesTheIntegratedProfile) {
  const BurleyProfile p = kProfiles[0];
  for (double radius : {0.05, 0.5, 2.0, 8.0}) {
    const double within = logSimpson([&](double r) { return p.radial(r) * kTwoPi * r; }, 1e-12, radius, 20000);
    EXPECT_NEAR(within / p.albedo, p.fractionWithin(radius), 1e-6) << "r = " << radius;
  }
}

TEST(OpticsBurley, LineSpreadIntegratesToTheAlbedo) {
  for (const BurleyProfile& p : kProfiles) {
    // Symmetric: twice the half line; log spacing handles the K0 singularity.
    const double total = 2.0 * logSimpson([&](double s) { return p.lineSpread(s); }, 1e-12, 150.0 * p.shape, 20000);
    EXPECT_NEAR(total, p.albedo, 1e-4 * p.albedo);
  }
}

TEST(OpticsBurley, LineSpreadIsTheAbelProjectionOfTheProfile) {
  const BurleyProfile p = kProfiles[0];
  for (double s : {0.05, 0.3, 1.0, 3.0}) {
    const double projected =
        2.0 * logSimpson([&](double t) { return p.radial(std::hypot(s, t)); }, 1e-9, 200.0 * p.shape, 20000);
    EXPECT_NEAR(projected / p.lineSpread(s), 1.0, 1e-4) << "s = " << s;
  }
}

TEST(OpticsBurley, SampledRadiusInvertsTheCdf) {
  const BurleyProfile p = kProfiles[0];
  double previous = -1.0;
  for (double xi = 0.0; xi < 0.9999; xi += 0.001) {
    const double r = p.sampleRadius(xi);
    EXPECT_NEAR(p.fractionWithin(r), xi, 1e-10);
    EXPECT_GT(r, previous);
    previous = r;
  }
  // Mean radius of the normalised profile: d/4 + (3/4)(3d) = 2.5 d.
  const int n = 100000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += p.sampleRadius((i + 0.5) / n);
  EXPECT_NEAR(sum / n, 2.5 * p.shape, 1e-3 * p.shape);
}

TEST(OpticsBurley, ScalingFactorsFollowTheFits) {
  EXPECT_DOUBLE_EQ(burleyScaleSearchlightMfp(0.8), 1.05);
  EXPECT_DOUBLE_EQ(burleyScaleDiffuseMfp(0.8), 1.1);
  EXPECT_DOUBLE_EQ(burleyScaleSearchlightDiffuseMfp(0.33), 3.5);
  const BurleyProfile p = burleyFromDiffuseMfp(0.33, 7.0);
  EXPECT_DOUBLE_EQ(p.shape, 2.0);
  EXPECT_DOUBLE_EQ(p.albedo, 0.33);
}

}  // namespace
}  // namespace mq::optics
