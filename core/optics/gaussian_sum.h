#pragma once
// A diffusion profile as a sum of 2-D Gaussians (d'Eon and Luebke, GPU Gems 3
// ch. 14): R(r) = sum_k w_k G(v_k, r), G(v, r) = e^{-r^2/(2v)} / (2 pi v).
// It approximates the survey's BSSRDF diffusion term (§1.5.2) with kernels
// that blur separably. Each Gaussian integrates to 1 over the plane, so the
// total reflectance is sum w_k, the reflectance within R is
// sum w_k (1 - e^{-R^2/(2v_k)}), and its line-spread projection is
// sum w_k e^{-s^2/(2v_k)} / sqrt(2 pi v_k).

#include <array>
#include <functional>
#include <vector>

#include <Eigen/Dense>

namespace mq::optics {

double gaussian2d(double variance, double r);

struct GaussianSum {
  std::vector<double> variances;  // mm^2
  std::vector<double> weights;

  double radial(double r) const;  // mm^-2
  double reflectanceWithin(double radius) const;
  double totalReflectance() const;
  double lineSpread(double s) const;  // mm^-1
};

// Lawson-Hanson active-set solution of min |A x - b| subject to x >= 0.
Eigen::VectorXd solveNonNegativeLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b);

// Fits `count` Gaussians with log-spaced variances in [minVariance,
// maxVariance] (mm^2) to a radial profile R(r) on [0, maxRadius] (mm),
// minimising the area-weighted squared error int (R - fit)^2 2 pi r dr with
// non-negative weights. The samples are denser near r = 0, where the narrow
// Gaussians live.
GaussianSum fitGaussianSum(const std::function<double(double)>& profile, int count, double minVariance,
                           double maxVariance, double maxRadius, int samples = 800);

// d'Eon and Luebke's six-Gaussian skin profile (GPU Gems 3, table in ch. 14,
// a fit to a three-layer multipole skin model), red, green, blue. The
// published weights are rounded to three digits.
std::array<GaussianSum, 3> deonSkinProfile();

}  // namespace mq::optics
