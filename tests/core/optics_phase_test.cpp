// Oracle O13 of ../shared/docs/research/skin-appearance.md: the phase
// functions are normalised, HG's mean cosine is g, sampling reproduces it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/optics/phase.h"
#include "core/optics_test_util.h"

namespace mq::optics {
namespace {

using test::simpson;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

TEST(OpticsPhase, HenyeyGreensteinIsNormalisedWithMeanCosineG) {
  for (double g : {0.0, 0.3, 0.79, 0.85, -0.5}) {
    const double total = kTwoPi * simpson([g](double mu) { return henyeyGreenstein(mu, g); }, -1, 1, 200000);
    const double meanCos = kTwoPi * simpson([g](double mu) { return mu * henyeyGreenstein(mu, g); }, -1, 1, 200000);
    EXPECT_NEAR(total, 1.0, 1e-6) << "g = " << g;
    EXPECT_NEAR(meanCos, g, 1e-6) << "g = " << g;
  }
}

TEST(OpticsPhase, HenyeyGreensteinIsotropicAtZero) {
  EXPECT_NEAR(henyeyGreenstein(0.3, 0.0), 1.0 / (4.0 * std::numbers::pi), 1e-15);
}

TEST(OpticsPhase, SchlickIsNormalisedAndForwardForPositiveG) {
  for (double g : {0.0, 0.5, 0.85, -0.3}) {
    const double total = kTwoPi * simpson([g](double mu) { return schlickPhase(mu, g); }, -1, 1, 200000);
    EXPECT_NEAR(total, 1.0, 1e-6) << "g = " << g;
  }
  EXPECT_GT(schlickPhase(0.9, 0.85), schlickPhase(-0.9, 0.85));
}

TEST(OpticsPhase, SampledMeanCosineIsG) {
  std::mt19937_64 rng(12111);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const int n = 200000;
  for (double g : {0.0, 0.5, 0.85, -0.6}) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += sampleHenyeyGreenstein(g, uniform(rng));
    const double secondMoment =
        kTwoPi * simpson([g](double mu) { return mu * mu * henyeyGreenstein(mu, g); }, -1, 1, 200000);
    const double sigma = std::sqrt((secondMoment - g * g) / n);
    EXPECT_NEAR(sum / n, g, 4.0 * sigma) << "g = " << g;
  }
}

TEST(OpticsPhase, SampledHistogramFollowsTheDensity) {
  // 10 bins in cos psi: each count within 4 sigma of 2 pi int p over the bin.
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double g = 0.85;
  const int n = 200000, bins = 10;
  std::vector<int> counts(bins, 0);
  for (int i = 0; i < n; ++i) {
    const double mu = sampleHenyeyGreenstein(g, uniform(rng));
    ++counts[std::min(int((mu + 1.0) / 2.0 * bins), bins - 1)];
  }
  for (int b = 0; b < bins; ++b) {
    const double lo = -1.0 + 2.0 * b / bins, hi = lo + 2.0 / bins;
    const double p = kTwoPi * simpson([g](double mu) { return henyeyGreenstein(mu, g); }, lo, hi, 20000);
    EXPECT_NEAR(double(counts[b]) / n, p, 4.0 * test::standardError(p, n)) << "bin " << b;
  }
}

}  // namespace
}  // namespace mq::optics
