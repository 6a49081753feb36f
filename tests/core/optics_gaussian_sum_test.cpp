// Oracles O17 and O18 of ../shared/docs/research/skin-appearance.md: a sum of
// Gaussians fitted by NNLS follows the skin1 dipole; d'Eon's fixed variances
// cannot.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/optics/dipole.h"
#include "core/optics/gaussian_sum.h"
#include "core/optics_test_util.h"

namespace mq::optics {
namespace {

using test::logSimpson;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Jensen's skin1, per channel (sigma_a, sigma_s', eta 1.3).
Dipole skin1(int channel) {
  const double sigmaA[] = {0.032, 0.17, 0.48}, sigmaSPrime[] = {0.74, 0.88, 1.01};
  return Dipole(sigmaA[channel], sigmaSPrime[channel], 1.3);
}

struct FitError {
  double relativeL2, cdf;
};

// Area-weighted relative L2 error and max |CDF error| / R_d, on a grid of
// the test's own.
FitError fitError(const Dipole& dipole, const GaussianSum& fit) {
  const double farOut = 30.0 / dipole.sigmaTr();
  auto squared = [](double x) { return x * x; };
  const double error = logSimpson(
      [&](double r) { return squared(dipole.radialReflectance(r) - fit.radial(r)) * kTwoPi * r; }, 1e-6, farOut, 20000);
  const double norm =
      logSimpson([&](double r) { return squared(dipole.radialReflectance(r)) * kTwoPi * r; }, 1e-6, farOut, 20000);
  double cdf = 0.0;
  for (double r = 1e-3; r < farOut; r *= 1.02)
    cdf = std::max(cdf, std::abs(fit.reflectanceWithin(r) - dipole.reflectanceWithin(r)));
  return {std::sqrt(error / norm), cdf / dipole.totalReflectance()};
}

TEST(OpticsGaussianSum, NnlsRecoversANonNegativeSolution) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd a(30, 6);
  for (int i = 0; i < a.rows(); ++i)
    for (int j = 0; j < a.cols(); ++j) a(i, j) = normal(rng);
  Eigen::VectorXd truth(6);
  truth << 0.5, 0.0, 2.0, 0.0, 1.0, 0.25;
  const Eigen::VectorXd x = solveNonNegativeLeastSquares(a, a * truth);
  EXPECT_LT((x - truth).norm(), 1e-9);
}

TEST(OpticsGaussianSum, NnlsMeetsTheKktConditions) {
  // b chosen so that the unconstrained solution has negative entries.
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd a(40, 8);
  Eigen::VectorXd b(40);
  for (int i = 0; i < a.rows(); ++i) {
    for (int j = 0; j < a.cols(); ++j) a(i, j) = normal(rng);
    b[i] = normal(rng);
  }
  ASSERT_LT(a.colPivHouseholderQr().solve(b).minCoeff(), 0.0);
  const Eigen::VectorXd x = solveNonNegativeLeastSquares(a, b);
  const Eigen::VectorXd gradient = a.transpose() * (b - a * x);  // minus the objective's gradient / 2
  for (int j = 0; j < x.size(); ++j) {
    EXPECT_GE(x[j], 0.0);
    if (x[j] > 0.0) {
      EXPECT_NEAR(gradient[j], 0.0, 1e-9);
    } else {
      EXPECT_LE(gradient[j], 1e-9);
    }
  }
}

TEST(OpticsGaussianSum, EightGaussiansFitTheSkin1Dipole) {  // O17
  for (int c = 0; c < 3; ++c) {
    const Dipole dipole = skin1(c);
    const GaussianSum fit =
        fitGaussianSum([&](double r) { return dipole.radialReflectance(r); }, 8, 0.005, 60.0, 30.0 / dipole.sigmaTr());
    const FitError e = fitError(dipole, fit);
    EXPECT_LE(e.relativeL2, 0.02) << "channel " << c;
    EXPECT_LE(e.cdf, 0.01) << "channel " << c;
  }
}

TEST(OpticsGaussianSum, SixGaussiansFitWithinTheLooserBound) {  // O17, K = 6
  for (int c = 0; c < 3; ++c) {
    const Dipole dipole = skin1(c);
    const GaussianSum fit =
        fitGaussianSum([&](double r) { return dipole.radialReflectance(r); }, 6, 0.005, 60.0, 30.0 / dipole.sigmaTr());
    const FitError e = fitError(dipole, fit);
    EXPECT_LE(e.relativeL2, 0.06) << "channel " << c;
    EXPECT_LE(e.cdf, 0.03) << "channel " << c;
  }
}

TEST(OpticsGaussianSum, DeonWeightsSumToOne) {  // O18
  for (const GaussianSum& channel : deonSkinProfile()) {
    EXPECT_NEAR(channel.totalReflectance(), 1.0, 1e-12);
    EXPECT_EQ(channel.variances.size(), 6u);
  }
}

TEST(OpticsGaussianSum, DeonVariancesCannotFollowTheSkin1RedTail) {  // O18
  const Dipole dipole = skin1(0);
  const GaussianSum deon = deonSkinProfile()[0];
  Eigen::MatrixXd a(600, 6);
  Eigen::VectorXd b(600);
  const double farOut = 30.0 / dipole.sigmaTr();
  for (int i = 0; i < 600; ++i) {
    const double u = (i + 0.5) / 600, r = farOut * u * u, w = std::sqrt(kTwoPi * r * 2.0 * farOut * u / 600);
    for (int k = 0; k < 6; ++k) a(i, k) = w * gaussian2d(deon.variances[k], r);
    b[i] = w * dipole.radialReflectance(r);
  }
  const Eigen::VectorXd weights = solveNonNegativeLeastSquares(a, b);
  const GaussianSum best{deon.variances, std::vector<double>(weights.data(), weights.data() + 6)};
  EXPECT_GE(fitError(dipole, best).cdf, 0.05);
}

}  // namespace
}  // namespace mq::optics
