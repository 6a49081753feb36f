#pragma once
// Pre-integrated skin diffuse (Penner and Borshukov, GPU Pro 2, 2011). The
// survey's BSSRDF (§1.5.2) is too costly per pixel; on a surface curved with
// radius r = 1/curvature, lit at angle theta, the diffuse light after
// scattering is the irradiance max(cos, 0) convolved around the ring:
//
//   D(theta, 1/r) = int_{-pi}^{pi} max(cos(theta + x), 0) K(2 r sin(x/2)) dx
//                   / int_{-pi}^{pi} K(2 r sin(x/2)) dx
//
// Penner uses the radial profile R for K. A profile singular at r = 0
// (Burley's 1/r) makes that integral diverge logarithmically as the ring is
// sampled more finely, so K here is the line-spread projection
// P(s) = int R(sqrt(s^2 + t^2)) dt, the exact response of a cylinder's
// cross-section, which is finite to integrate. Each ring cell is weighted by
// the kernel's integral over the cell (from a tabulated cumulative), so the
// logarithmic singularity of Burley's P costs no accuracy.
//
// D carries no albedo: it is a normalised blur of N.L; the shader multiplies
// by the skin's diffuse colour.

#include <array>
#include <functional>
#include <vector>

namespace mq::optics {

struct BurleyProfile;
struct GaussianSum;
class Dipole;

// A symmetric line-spread kernel P(s), normalised, tabulated as its
// cumulative fraction over s in [0, maxDistance].
class LineSpreadKernel {
 public:
  // From P itself (it may be singular at 0, if integrable).
  static LineSpreadKernel fromLineSpread(const std::function<double(double)>& lineSpread, double maxDistance);
  // From a radial profile R(r), finite at 0, by a numerical Abel projection.
  static LineSpreadKernel fromRadialProfile(const std::function<double(double)>& radial, double maxRadius);

  // int_0^s P / int_0^maxDistance P.
  double fractionWithin(double s) const;
  double maxDistance() const { return maxDistance_; }

 private:
  double maxDistance_ = 0;
  std::vector<double> cumulative_;  // at s = maxDistance (i / (n - 1))^2
};

LineSpreadKernel burleyKernel(const BurleyProfile& profile);  // closed-form P, support 60 d
LineSpreadKernel gaussianKernel(const GaussianSum& profile);  // closed-form P, support 6 sigma
LineSpreadKernel dipoleKernel(const Dipole& profile);         // Abel projection, support 24/sigma_tr

// D(theta, curvature) for one kernel; curvature in mm^-1 (0: flat),
// ringCells cells over each half of the ring.
double preintegratedDiffuse(const LineSpreadKernel& kernel, double theta, double curvature, int ringCells = 256);

struct PreintegratedLutSettings {
  int width = 256;            // N.L samples
  int height = 128;           // curvature samples
  double maxCurvature = 2.0;  // mm^-1
  int ringCells = 256;
};

// The table the renderer uploads as an RGB float texture.
//
// Layout: rgb[3 * (row * width + column) + channel], channel 0, 1, 2 = R, G, B,
// row 0 first; values D in [0, 1].
// Column c holds N.L = -1 + 2 c / (width - 1).
// Row r holds curvature = maxCurvature (r / (height - 1))^2 (a square-root
// axis: more rows where skin is nearly flat, up to a 0.5 mm radius).
// With clamp-to-edge and linear filtering, sample at texture coordinates
// textureU(N.L), textureV(curvature), which put those values on texel centres.
struct PreintegratedLut {
  int width = 0, height = 0;
  double maxCurvature = 0;
  std::vector<float> rgb;

  double nDotLAt(int column) const { return -1.0 + 2.0 * column / (width - 1); }
  double curvatureAt(int row) const;
  double textureU(double nDotL) const;
  double textureV(double curvature) const;
  float value(int column, int row, int channel) const { return rgb[3 * (size_t(row) * width + column) + channel]; }
};

// One kernel per channel (R, G, B). Builds in well under 100 ms on one core.
PreintegratedLut buildPreintegratedLut(const std::array<LineSpreadKernel, 3>& kernels,
                                       const PreintegratedLutSettings& settings = {});

}  // namespace mq::optics
