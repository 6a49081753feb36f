#include "core/optics/gaussian_sum.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mq::optics {

double gaussian2d(double variance, double r) {
  return std::exp(-r * r / (2.0 * variance)) / (2.0 * std::numbers::pi * variance);
}

double GaussianSum::radial(double r) const {
  double sum = 0.0;
  for (size_t k = 0; k < weights.size(); ++k) sum += weights[k] * gaussian2d(variances[k], r);
  return sum;
}

double GaussianSum::reflectanceWithin(double radius) const {
  double sum = 0.0;
  for (size_t k = 0; k < weights.size(); ++k) sum += weights[k] * -std::expm1(-radius * radius / (2.0 * variances[k]));
  return sum;
}

double GaussianSum::totalReflectance() const {
  double sum = 0.0;
  for (double w : weights) sum += w;
  return sum;
}

double GaussianSum::lineSpread(double s) const {
  double sum = 0.0;
  for (size_t k = 0; k < weights.size(); ++k)
    sum += weights[k] * std::exp(-s * s / (2.0 * variances[k])) / std::sqrt(2.0 * std::numbers::pi * variances[k]);
  return sum;
}

Eigen::VectorXd solveNonNegativeLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  const Eigen::Index n = a.cols();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<bool> passive(n, false);
  const double tolerance = 1e-12 * a.norm() * b.norm();

  auto solvePassive = [&]() {
    std::vector<Eigen::Index> columns;
    for (Eigen::Index j = 0; j < n; ++j)
      if (passive[j]) columns.push_back(j);
    Eigen::MatrixXd sub(a.rows(), Eigen::Index(columns.size()));
    for (size_t c = 0; c < columns.size(); ++c) sub.col(Eigen::Index(c)) = a.col(columns[c]);
    const Eigen::VectorXd solution = sub.colPivHouseholderQr().solve(b);
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    for (size_t c = 0; c < columns.size(); ++c) z[columns[c]] = solution[Eigen::Index(c)];
    return z;
  };

  for (int outer = 0; outer < 3 * n; ++outer) {
    const Eigen::VectorXd gradient = a.transpose() * (b - a * x);
    Eigen::Index best = -1;
    for (Eigen::Index j = 0; j < n; ++j)
      if (!passive[j] && gradient[j] > tolerance && (best < 0 || gradient[j] > gradient[best])) best = j;
    if (best < 0) break;
    passive[best] = true;
    for (int inner = 0; inner < 3 * n; ++inner) {
      const Eigen::VectorXd z = solvePassive();
      // Step back along x -> z until the first passive weight reaches zero.
      double step = 1.0;
      for (Eigen::Index j = 0; j < n; ++j)
        if (passive[j] && z[j] <= 0.0) step = std::min(step, x[j] / (x[j] - z[j]));
      x += step * (z - x);
      if (step >= 1.0) break;
      for (Eigen::Index j = 0; j < n; ++j)
        if (passive[j] && x[j] <= 1e-15) {
          passive[j] = false;
          x[j] = 0.0;
        }
    }
  }
  return x;
}

GaussianSum fitGaussianSum(const std::function<double(double)>& profile, int count, double minVariance,
                           double maxVariance, double maxRadius, int samples) {
  GaussianSum fit;
  for (int k = 0; k < count; ++k) {
    const double t = count > 1 ? double(k) / (count - 1) : 0.0;
    fit.variances.push_back(minVariance * std::pow(maxVariance / minVariance, t));
  }
  // r = maxRadius u^2 with u uniform: dr = 2 maxRadius u du, and the area
  // element 2 pi r dr becomes the least-squares row weight.
  Eigen::MatrixXd a(samples, count);
  Eigen::VectorXd b(samples);
  const double du = 1.0 / samples;
  for (int i = 0; i < samples; ++i) {
    const double u = (i + 0.5) * du;
    const double r = maxRadius * u * u;
    const double area = 2.0 * std::numbers::pi * r * 2.0 * maxRadius * u * du;
    const double rowWeight = std::sqrt(area);
    for (int k = 0; k < count; ++k) a(i, k) = rowWeight * gaussian2d(fit.variances[k], r);
    b[i] = rowWeight * profile(r);
  }
  const Eigen::VectorXd weights = solveNonNegativeLeastSquares(a, b);
  fit.weights.assign(weights.data(), weights.data() + weights.size());
  return fit;
}

std::array<GaussianSum, 3> deonSkinProfile() {
  const std::vector<double> variances = {0.0064, 0.0484, 0.187, 0.567, 1.99, 7.41};
  return {GaussianSum{variances, {0.233, 0.100, 0.118, 0.113, 0.358, 0.078}},
          GaussianSum{variances, {0.455, 0.336, 0.198, 0.007, 0.004, 0.0}},
          GaussianSum{variances, {0.649, 0.344, 0.0, 0.007, 0.0, 0.0}}};
}

}  // namespace mq::optics
