#include "core/optics/hair_bsdf.h"

#include <algorithm>
#include <cmath>

#include "core/optics/fresnel.h"
#include "core/util/error.h"

namespace mq::optics {

namespace {

constexpr double kPi = 3.14159265358979323846;

double safeSqrt(double x) { return std::sqrt(std::max(0.0, x)); }

// I0 by its power series sum (x/2)^{2k} / (k!)^2, to convergence (x <= ~20 here).
double besselI0(double x) {
  const double q = 0.25 * x * x;
  double term = 1.0, sum = 1.0;
  for (int k = 1; k < 100 && term > 1e-17 * sum; ++k) {
    term *= q / double(k * k);
    sum += term;
  }
  return sum;
}

// log I0, past 12 by the asymptotic series
//   I0(x) ~ e^x / sqrt(2 pi x) (1 + 1/(8x) + 9/(128x^2) + 225/(3072x^3) + 11025/(98304x^4)),
// within 1e-6 there. (Keeping only 1/(16x) in the logarithm, as is often
// done, is 0.5 % off at 12, which the lobe's normalisation shows.)
double logBesselI0(double x) {
  if (x > 12.0) {
    const double y = 1.0 / x;
    return x - 0.5 * std::log(2.0 * kPi * x) +
           std::log(1.0 + y * (1.0 / 8.0 + y * (9.0 / 128.0 + y * (225.0 / 3072.0 + y * 11025.0 / 98304.0))));
  }
  return std::log(besselI0(x));
}

double logisticCdf(double x, double s) { return 1.0 / (1.0 + std::exp(-x / s)); }

// The lobe's shift on theta_h and its variance as a multiple of v.
double lobeShift(int p, double alpha) {
  switch (p) {
    case 0:
      return alpha;
    case 1:
      return -0.5 * alpha;
    case 2:
      return -1.5 * alpha;
    default:
      return 0.0;
  }
}
constexpr double kLobeVarianceScale[4] = {1.0, 0.25, 4.0, 4.0};

// The angles of a direction in the fibre frame.
struct FibreAngles {
  double sinTheta, cosTheta, phi;
};
FibreAngles anglesOf(const glm::dvec3& w) {
  const double sinTheta = std::clamp(w.x, -1.0, 1.0);
  return {sinTheta, safeSqrt(1.0 - sinTheta * sinTheta), std::atan2(w.z, w.y)};
}

// M_p for lobe p: the exit angle shifted by -2 alpha_p (see the header).
double shiftedLongitudinal(int p, const FibreAngles& i, const FibreAngles& o, double v, double alpha) {
  const double twoAlpha = 2.0 * lobeShift(p, alpha);
  const double sinO = o.sinTheta * std::cos(twoAlpha) - o.cosTheta * std::sin(twoAlpha);
  const double cosO = std::abs(o.cosTheta * std::cos(twoAlpha) + o.sinTheta * std::sin(twoAlpha));
  return hairLongitudinal(i.sinTheta, i.cosTheta, sinO, cosO, v * kLobeVarianceScale[p]);
}

// gamma_t for an exit at sin theta_o and offset h.
double refractedGamma(double sinThetaO, double h, double eta) {
  const double cosThetaO = safeSqrt(1.0 - sinThetaO * sinThetaO);
  const double etaPrime = safeSqrt(eta * eta - sinThetaO * sinThetaO) / std::max(cosThetaO, 1e-9);
  return std::asin(std::clamp(h / etaPrime, -1.0, 1.0));
}

// Offsets h = sin gamma at the midpoints of gamma in [-pi/2, pi/2]; the
// weights (dh / 2 = cos gamma dgamma / 2) scaled to sum to exactly 1.
struct OffsetNode {
  double gamma, h, weight;
};
std::vector<OffsetNode> offsetNodes(int samples) {
  std::vector<OffsetNode> nodes(size_t(std::max(samples, 1)));
  double total = 0.0;
  for (size_t k = 0; k < nodes.size(); ++k) {
    const double gamma = -0.5 * kPi + (double(k) + 0.5) * kPi / double(nodes.size());
    nodes[k] = {gamma, std::sin(gamma), std::cos(gamma)};
    total += nodes[k].weight;
  }
  for (OffsetNode& node : nodes) node.weight /= total;
  return nodes;
}

double alphaRadians(const HairFibre& fibre) { return fibre.alphaDegrees * kPi / 180.0; }

}  // namespace

// ---- The terms ----

double hairLongitudinalVariance(double betaM) {
  const double r = 0.726 * betaM + 0.812 * betaM * betaM + 3.7 * std::pow(betaM, 20.0);
  return r * r;
}

double hairAzimuthalScale(double betaN) {
  return std::sqrt(kPi / 8.0) * (0.265 * betaN + 1.194 * betaN * betaN + 5.372 * std::pow(betaN, 22.0));
}

double hairLongitudinal(double sinThetaI, double cosThetaI, double sinThetaO, double cosThetaO, double v) {
  const double a = cosThetaI * cosThetaO / v, b = sinThetaI * sinThetaO / v;
  // csch(1/v) / (2v) overflows for small v: its logarithm, with
  // csch(1/v) ~ 2 e^{-1/v}, is exact to e^{-20} at v = 0.1.
  if (v <= 0.1) return std::exp(logBesselI0(a) - b - 1.0 / v + std::log(2.0) + std::log(1.0 / (2.0 * v)));
  return std::exp(-b) * besselI0(a) / (2.0 * v * std::sinh(1.0 / v));
}

double trimmedLogistic(double x, double s) {
  const double e = std::exp(-std::abs(x) / s);
  return e / (s * (1.0 + e) * (1.0 + e)) / (logisticCdf(kPi, s) - logisticCdf(-kPi, s));
}

double hairAzimuthal(double phi, int p, double s, double gammaO, double gammaT) {
  const double exit = 2.0 * p * gammaT - 2.0 * gammaO + p * kPi;
  return trimmedLogistic(std::remainder(phi - exit, 2.0 * kPi), s);
}

std::array<Rgb, 4> hairAttenuation(double sinThetaO, double h, double eta, const Rgb& sigmaA) {
  const double cosThetaO = safeSqrt(1.0 - sinThetaO * sinThetaO);
  const double cosGammaO = safeSqrt(1.0 - h * h);
  const double f = fresnelDielectric(cosThetaO * cosGammaO, eta);
  const double sinThetaT = sinThetaO / eta;
  const double cosThetaT = safeSqrt(1.0 - sinThetaT * sinThetaT);
  const double cosGammaT = std::cos(refractedGamma(sinThetaO, h, eta));
  std::array<Rgb, 4> a{};
  for (int c = 0; c < 3; ++c) {
    const double t = std::exp(-sigmaA[c] * 2.0 * cosGammaT / cosThetaT);
    a[0][c] = f;
    a[1][c] = (1.0 - f) * (1.0 - f) * t;
    a[2][c] = a[1][c] * f * t;
    a[3][c] = a[2][c] * f * t / (1.0 - f * t);
  }
  return a;
}

// ---- The fibre ----

Rgb hairScattering(const HairFibre& fibre, const glm::dvec3& wi, const glm::dvec3& wo, double h) {
  const FibreAngles i = anglesOf(wi), o = anglesOf(wo);
  const std::array<Rgb, 4> a = hairAttenuation(o.sinTheta, h, fibre.eta, fibre.sigmaA);
  const double v = hairLongitudinalVariance(fibre.longitudinalRoughness);
  const double s = hairAzimuthalScale(fibre.azimuthalRoughness);
  const double gammaO = std::asin(std::clamp(h, -1.0, 1.0));
  const double gammaT = refractedGamma(o.sinTheta, h, fibre.eta);
  const double phi = i.phi - o.phi;
  const double alpha = alphaRadians(fibre);
  Rgb sum{0.0, 0.0, 0.0};
  for (int p = 0; p < 4; ++p) {
    if (!(fibre.lobes & (1u << p))) continue;
    const double m = shiftedLongitudinal(p, i, o, v, alpha);
    const double n = p < 3 ? hairAzimuthal(phi, p, s, gammaO, gammaT) : 1.0 / (2.0 * kPi);
    for (int c = 0; c < 3; ++c) sum[c] += m * a[p][c] * n;
  }
  return sum;
}

Rgb hairScatteringFarField(const HairFibre& fibre, const glm::dvec3& wi, const glm::dvec3& wo, int samples) {
  Rgb sum{0.0, 0.0, 0.0};
  const std::vector<OffsetNode> nodes = offsetNodes(samples);
  for (const OffsetNode& node : nodes) {
    const Rgb s = hairScattering(fibre, wi, wo, node.h);
    for (int c = 0; c < 3; ++c) sum[c] += node.weight * s[c];
  }
  return sum;
}

Rgb HairAzimuthalTable::lookup(int p, double phi, double sinThetaO) const {
  const double x = std::abs(std::remainder(phi, 2.0 * kPi)) / kPi * (phiCount - 1);
  const double y = std::min(std::abs(sinThetaO), 1.0) * (thetaCount - 1);
  const int k = std::min(int(x), phiCount - 2), t = std::min(int(y), thetaCount - 2);
  const double fx = x - k, fy = y - t;
  auto at = [&](int tt, int kk) { return lobes[size_t((p * thetaCount + tt) * phiCount + kk)]; };
  Rgb out{};
  for (int c = 0; c < 3; ++c)
    out[c] = (1 - fy) * ((1 - fx) * at(t, k)[c] + fx * at(t, k + 1)[c]) +
             fy * ((1 - fx) * at(t + 1, k)[c] + fx * at(t + 1, k + 1)[c]);
  return out;
}

Rgb HairAzimuthalTable::residualAt(double sinThetaO) const {
  const double y = std::min(std::abs(sinThetaO), 1.0) * (thetaCount - 1);
  const int t = std::min(int(y), thetaCount - 2);
  const double fy = y - t;
  Rgb out{};
  for (int c = 0; c < 3; ++c) out[c] = (1 - fy) * residual[size_t(t)][c] + fy * residual[size_t(t + 1)][c];
  return out;
}

HairAzimuthalTable hairAzimuthalTable(const HairFibre& fibre, int phiCount, int thetaCount, int samples) {
  if (phiCount < 2 || thetaCount < 2 || samples < 1) throw Error("hair table: need at least 2 x 2 nodes");
  HairAzimuthalTable table;
  table.phiCount = phiCount;
  table.thetaCount = thetaCount;
  table.lobes.assign(size_t(3 * thetaCount * phiCount), Rgb{0.0, 0.0, 0.0});
  table.residual.assign(size_t(thetaCount), Rgb{0.0, 0.0, 0.0});
  const double s = hairAzimuthalScale(fibre.azimuthalRoughness);
  const std::vector<OffsetNode> nodes = offsetNodes(samples);
  for (int t = 0; t < thetaCount; ++t) {
    // Grazing exits (cos theta_o = 0) have no refracted path: stop short.
    const double sinThetaO = std::min(double(t) / (thetaCount - 1), 0.999);
    for (const OffsetNode& node : nodes) {
      const double gammaO = node.gamma, h = node.h, weight = node.weight;
      const std::array<Rgb, 4> a = hairAttenuation(sinThetaO, h, fibre.eta, fibre.sigmaA);
      const double gammaT = refractedGamma(sinThetaO, h, fibre.eta);
      for (int p = 0; p < 3; ++p)
        for (int k = 0; k < phiCount; ++k) {
          const double n = weight * hairAzimuthal(kPi * k / (phiCount - 1), p, s, gammaO, gammaT);
          Rgb& cell = table.lobes[size_t((p * thetaCount + t) * phiCount + k)];
          for (int c = 0; c < 3; ++c) cell[c] += n * a[p][c];
        }
      for (int c = 0; c < 3; ++c) table.residual[size_t(t)][c] += weight * a[3][c];
    }
  }
  return table;
}

Rgb hairScatteringFromTable(const HairFibre& fibre, const HairAzimuthalTable& table, const glm::dvec3& wi,
                            const glm::dvec3& wo) {
  const FibreAngles i = anglesOf(wi), o = anglesOf(wo);
  const double v = hairLongitudinalVariance(fibre.longitudinalRoughness);
  const double alpha = alphaRadians(fibre);
  const double phi = i.phi - o.phi;
  Rgb sum{0.0, 0.0, 0.0};
  for (int p = 0; p < 4; ++p) {
    if (!(fibre.lobes & (1u << p))) continue;
    const double m = shiftedLongitudinal(p, i, o, v, alpha);
    Rgb n = p < 3 ? table.lookup(p, phi, o.sinTheta) : table.residualAt(o.sinTheta);
    if (p == 3)
      for (double& x : n) x /= 2.0 * kPi;
    for (int c = 0; c < 3; ++c) sum[c] += m * n[c];
  }
  return sum;
}

Rgb hairMeanAlbedo(const HairFibre& fibre) {
  // w_o uniform on the sphere: sin theta_o uniform in [-1, 1] (A_p is even
  // in it, so [0, 1]); h uniform in [-1, 1], by gamma as above.
  constexpr int kThetaSamples = 64;
  Rgb sum{0.0, 0.0, 0.0};
  const std::vector<OffsetNode> nodes = offsetNodes(64);
  for (int t = 0; t < kThetaSamples; ++t) {
    const double sinThetaO = (t + 0.5) / kThetaSamples;
    for (const OffsetNode& node : nodes) {
      const double weight = node.weight / kThetaSamples;
      const std::array<Rgb, 4> a = hairAttenuation(sinThetaO, node.h, fibre.eta, fibre.sigmaA);
      for (int p = 0; p < 4; ++p)
        if (fibre.lobes & (1u << p))
          for (int c = 0; c < 3; ++c) sum[c] += weight * a[p][c];
    }
  }
  return sum;
}

Rgb hairVolumeReflectance(const Rgb& meanAlbedo) {
  Rgb r{};
  for (int c = 0; c < 3; ++c) {
    const double root = std::sqrt(std::max(0.0, 1.0 - std::clamp(meanAlbedo[c], 0.0, 1.0)));
    r[c] = (1.0 - root) / (1.0 + root);
  }
  return r;
}

// ---- Pigments ----

Rgb hairSigmaAFromPigment(const HairPigment& pigment) {
  const Rgb eumelanin{0.419, 0.697, 1.37}, pheomelanin{0.187, 0.4, 1.05};
  Rgb sigmaA{};
  for (int c = 0; c < 3; ++c) sigmaA[c] = pigment.eumelanin * eumelanin[c] + pigment.pheomelanin * pheomelanin[c];
  return sigmaA;
}

Rgb hairSigmaAFromColor(const Rgb& color, double betaN) {
  const double b = betaN;
  const double d =
      5.969 - 0.215 * b + 2.532 * b * b - 10.73 * b * b * b + 5.574 * std::pow(b, 4.0) + 0.245 * std::pow(b, 5.0);
  Rgb sigmaA{};
  for (int c = 0; c < 3; ++c) {
    const double l = std::log(std::clamp(color[c], 1e-4, 1.0)) / d;
    sigmaA[c] = l * l;
  }
  return sigmaA;
}

// Concentrations in Chiang et al.'s units. Their figure 6 spans eumelanin 0
// (white) to 8 (black); the choices between are ours, picked by eye for the
// names (no measured source: a measured one would give melanin per fibre
// mass, which these units do not convert from).
HairPigment hairPigmentPreset(const std::string& name) {
  if (name == "black") return {8.0, 0.0};
  if (name == "brown") return {1.3, 0.1};
  if (name == "blond") return {0.3, 0.05};
  if (name == "red") return {0.3, 1.6};
  if (name == "grey") return {0.04, 0.0};
  throw Error("unknown hair pigment preset '" + name + "' (black, brown, blond, red or grey)");
}

std::vector<std::string> hairPigmentPresetNames() { return {"black", "brown", "blond", "red", "grey"}; }

}  // namespace mq::optics
