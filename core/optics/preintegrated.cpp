#include "core/optics/preintegrated.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/optics/burley.h"
#include "core/optics/dipole.h"
#include "core/optics/gaussian_sum.h"

namespace mq::optics {

namespace {

constexpr int kKernelSamples = 512;
constexpr double kPi = std::numbers::pi;

// Three-point Gauss-Legendre rule on [a, b].
template <class F>
double gaussLegendre3(const F& f, double a, double b) {
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b), offset = half * std::sqrt(0.6);
  return half * (5.0 * f(mid - offset) + 8.0 * f(mid) + 5.0 * f(mid + offset)) / 9.0;
}

// The ring cells over x in [0, halfAngle]: midpoints and kernel weights
// (normalised so both halves sum to 1).
struct RingCells {
  std::vector<double> cosX, sinX, weight;
};

double ringHalfAngle(double maxDistance, double radius) {
  return maxDistance >= 2.0 * radius ? kPi : 2.0 * std::asin(maxDistance / (2.0 * radius));
}

// The weight of cell [xa, xb] is int K(s(x)) dx with s = 2 r sin(x/2),
// ds = r cos(x/2) dx: the kernel's cumulative difference over the cell
// divided by r cos(x_mid/2).
std::vector<double> ringWeights(const LineSpreadKernel& kernel, double radius, double halfAngle, int cells) {
  std::vector<double> weight(cells);
  double sum = 0.0;
  const double step = halfAngle / cells;
  double previous = 0.0;
  for (int j = 0; j < cells; ++j) {
    const double xb = (j + 1) * step, xMid = (j + 0.5) * step;
    const double next = kernel.fractionWithin(2.0 * radius * std::sin(0.5 * xb));
    weight[j] = (next - previous) / (radius * std::cos(0.5 * xMid));
    previous = next;
    sum += weight[j];
  }
  for (double& w : weight) w /= 2.0 * sum;
  return weight;
}

// D at cos(theta), sin(theta) from a ring's midpoints and weights.
double ringConvolution(double cosTheta, double sinTheta, const std::vector<double>& cosX,
                       const std::vector<double>& sinX, const std::vector<double>& weight) {
  double d = 0.0;
  for (size_t j = 0; j < weight.size(); ++j) {
    const double a = cosTheta * cosX[j], b = sinTheta * sinX[j];
    d += weight[j] * (std::max(a - b, 0.0) + std::max(a + b, 0.0));
  }
  return d;
}

void cellMidpoints(double halfAngle, int cells, std::vector<double>& cosX, std::vector<double>& sinX) {
  cosX.resize(cells);
  sinX.resize(cells);
  for (int j = 0; j < cells; ++j) {
    const double x = (j + 0.5) * halfAngle / cells;
    cosX[j] = std::cos(x);
    sinX[j] = std::sin(x);
  }
}

}  // namespace

LineSpreadKernel LineSpreadKernel::fromLineSpread(const std::function<double(double)>& lineSpread, double maxDistance) {
  // s = maxDistance u^2: the integrand P(s) 2 maxDistance u stays finite at u = 0
  // even when P has a logarithmic singularity there.
  LineSpreadKernel kernel;
  kernel.maxDistance_ = maxDistance;
  kernel.cumulative_.assign(kKernelSamples, 0.0);
  const double du = 1.0 / (kKernelSamples - 1);
  auto integrand = [&](double u) { return lineSpread(maxDistance * u * u) * 2.0 * maxDistance * u; };
  for (int i = 1; i < kKernelSamples; ++i)
    kernel.cumulative_[i] = kernel.cumulative_[i - 1] + gaussLegendre3(integrand, (i - 1) * du, i * du);
  const double total = kernel.cumulative_.back();
  for (double& c : kernel.cumulative_) c /= total;
  return kernel;
}

LineSpreadKernel LineSpreadKernel::fromRadialProfile(const std::function<double(double)>& radial, double maxRadius) {
  // P(s) = 2 int_0^{sqrt(R^2 - s^2)} R(sqrt(s^2 + t^2)) dt, composite Simpson.
  auto lineSpread = [&](double s) {
    const double tMax = std::sqrt(std::max(0.0, maxRadius * maxRadius - s * s));
    constexpr int intervals = 96;
    const double h = tMax / intervals;
    double sum = radial(s) + radial(std::hypot(s, tMax));
    for (int k = 1; k < intervals; ++k) sum += (k % 2 ? 4.0 : 2.0) * radial(std::hypot(s, k * h));
    return 2.0 * sum * h / 3.0;
  };
  return fromLineSpread(lineSpread, maxRadius);
}

double LineSpreadKernel::fractionWithin(double s) const {
  if (s >= maxDistance_) return 1.0;
  const double position = std::sqrt(std::max(0.0, s) / maxDistance_) * (kKernelSamples - 1);
  const int i = std::min(int(position), kKernelSamples - 2);
  const double t = position - i;
  return cumulative_[i] + t * (cumulative_[i + 1] - cumulative_[i]);
}

LineSpreadKernel burleyKernel(const BurleyProfile& profile) {
  return LineSpreadKernel::fromLineSpread([profile](double s) { return profile.lineSpread(s); },
                                          60.0 * profile.shape);  // e^{-20} of the slow lobe
}

LineSpreadKernel gaussianKernel(const GaussianSum& profile) {
  double widest = 0.0;
  for (size_t k = 0; k < profile.variances.size(); ++k)
    if (profile.weights[k] > 0.0) widest = std::max(widest, profile.variances[k]);
  return LineSpreadKernel::fromLineSpread([profile](double s) { return profile.lineSpread(s); },
                                          6.0 * std::sqrt(widest));
}

LineSpreadKernel dipoleKernel(const Dipole& profile) {
  return LineSpreadKernel::fromRadialProfile([profile](double r) { return profile.radialReflectance(r); },
                                             24.0 / profile.sigmaTr());
}

double preintegratedDiffuse(const LineSpreadKernel& kernel, double theta, double curvature, int ringCells) {
  if (curvature <= 0.0) return std::max(std::cos(theta), 0.0);
  const double radius = 1.0 / curvature;
  const double halfAngle = ringHalfAngle(kernel.maxDistance(), radius);
  std::vector<double> cosX, sinX;
  cellMidpoints(halfAngle, ringCells, cosX, sinX);
  const std::vector<double> weight = ringWeights(kernel, radius, halfAngle, ringCells);
  return ringConvolution(std::cos(theta), std::sin(theta), cosX, sinX, weight);
}

double PreintegratedLut::curvatureAt(int row) const {
  const double v = double(row) / (height - 1);
  return maxCurvature * v * v;
}

double PreintegratedLut::textureU(double nDotL) const {
  const double column = 0.5 * (std::clamp(nDotL, -1.0, 1.0) + 1.0) * (width - 1);
  return (column + 0.5) / width;
}

double PreintegratedLut::textureV(double curvature) const {
  const double row = std::sqrt(std::clamp(curvature / maxCurvature, 0.0, 1.0)) * (height - 1);
  return (row + 0.5) / height;
}

PreintegratedLut buildPreintegratedLut(const std::array<LineSpreadKernel, 3>& kernels,
                                       const PreintegratedLutSettings& settings) {
  PreintegratedLut lut{settings.width, settings.height, settings.maxCurvature, {}};
  lut.rgb.assign(size_t(3) * lut.width * lut.height, 0.0f);
  std::vector<double> cosTheta(lut.width), sinTheta(lut.width);
  for (int c = 0; c < lut.width; ++c) {
    cosTheta[c] = lut.nDotLAt(c);
    sinTheta[c] = std::sqrt(std::max(0.0, 1.0 - cosTheta[c] * cosTheta[c]));
  }
  const double widest = std::max({kernels[0].maxDistance(), kernels[1].maxDistance(), kernels[2].maxDistance()});
  std::vector<double> cosX, sinX;
  for (int row = 0; row < lut.height; ++row) {
    const double curvature = lut.curvatureAt(row);
    float* out = &lut.rgb[3 * size_t(row) * lut.width];
    if (curvature <= 0.0) {
      for (int c = 0; c < lut.width; ++c)
        for (int channel = 0; channel < 3; ++channel) out[3 * c + channel] = float(std::max(cosTheta[c], 0.0));
      continue;
    }
    // One set of ring cells for the three channels, spanning the widest
    // kernel, so the cos(theta +- x) terms are shared.
    const double radius = 1.0 / curvature;
    const double halfAngle = ringHalfAngle(widest, radius);
    cellMidpoints(halfAngle, settings.ringCells, cosX, sinX);
    std::array<std::vector<double>, 3> weight;
    for (int channel = 0; channel < 3; ++channel)
      weight[channel] = ringWeights(kernels[channel], radius, halfAngle, settings.ringCells);
    for (int c = 0; c < lut.width; ++c) {
      double d[3] = {0.0, 0.0, 0.0};
      for (int j = 0; j < settings.ringCells; ++j) {
        const double a = cosTheta[c] * cosX[j], b = sinTheta[c] * sinX[j];
        const double lit = std::max(a - b, 0.0) + std::max(a + b, 0.0);
        for (int channel = 0; channel < 3; ++channel) d[channel] += weight[channel][j] * lit;
      }
      for (int channel = 0; channel < 3; ++channel) out[3 * c + channel] = float(std::clamp(d[channel], 0.0, 1.0));
    }
  }
  return lut;
}

}  // namespace mq::optics
