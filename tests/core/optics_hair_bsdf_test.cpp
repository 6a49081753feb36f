// The hair fibre's scattering function: each term normalised, the white
// furnace on the sphere, absorption, symmetries, the lobes where Marschner
// puts them, the shader's table against the far field, the pigment presets.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>

#include "core/optics/hair_bsdf.h"
#include "core/optics_test_util.h"

namespace mq::optics {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::dvec3 direction(double thetaDegrees, double phi) {
  const double t = thetaDegrees * kPi / 180.0;
  return {std::sin(t), std::cos(t) * std::cos(phi), std::cos(t) * std::sin(phi)};
}

// integral over the sphere of f(w_i) dw_i, deterministic: midpoints in
// u = sin theta_i (dw = du dphi) and in phi.
template <class F>
Rgb sphereIntegral(const F& f, int uCount = 600, int phiCount = 720) {
  Rgb sum{0.0, 0.0, 0.0};
  const double du = 2.0 / uCount, dphi = 2.0 * kPi / phiCount;
  for (int a = 0; a < uCount; ++a) {
    const double u = -1.0 + (a + 0.5) * du, c = std::sqrt(1.0 - u * u);
    for (int b = 0; b < phiCount; ++b) {
      const double phi = -kPi + (b + 0.5) * dphi;
      const Rgb s = f(glm::dvec3(u, c * std::cos(phi), c * std::sin(phi)));
      for (int k = 0; k < 3; ++k) sum[k] += s[k] * du * dphi;
    }
  }
  return sum;
}

double luminance(const Rgb& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

TEST(OpticsHairBsdf, LongitudinalLobeIntegratesToOne) {
  // Both branches (v <= 0.1 in logarithms), narrow to broad.
  for (double beta : {0.1, 0.2, 0.3, 0.5, 0.8}) {
    for (double scale : {0.25, 1.0, 4.0}) {
      const double v = hairLongitudinalVariance(beta) * scale;
      for (double thetaO : {-1.2, -0.3, 0.0, 0.7, 1.4}) {
        const double integral = test::simpson(
            [&](double t) {
              return hairLongitudinal(std::sin(t), std::cos(t), std::sin(thetaO), std::cos(thetaO), v) * std::cos(t);
            },
            -kPi / 2, kPi / 2, 4000);
        EXPECT_NEAR(integral, 1.0, 2e-3) << "beta " << beta << " v " << v << " theta_o " << thetaO;
      }
    }
  }
  // The two branches meet at v = 0.1.
  const double below = hairLongitudinal(0.2, std::sqrt(0.96), -0.3, std::sqrt(0.91), 0.1);
  const double above = hairLongitudinal(0.2, std::sqrt(0.96), -0.3, std::sqrt(0.91), 0.1 + 1e-12);
  EXPECT_NEAR(below, above, 1e-6 * above);
}

TEST(OpticsHairBsdf, AzimuthalLobeIntegratesToOne) {
  for (double beta : {0.1, 0.3, 0.6, 0.9}) {
    const double s = hairAzimuthalScale(beta);
    EXPECT_NEAR(test::simpson([&](double x) { return trimmedLogistic(x, s); }, -kPi, kPi, 20000), 1.0, 1e-6);
    for (int p = 0; p < 3; ++p)
      EXPECT_NEAR(test::simpson([&](double phi) { return hairAzimuthal(phi, p, s, 0.4, 0.25); }, -kPi, kPi, 20000), 1.0,
                  1e-6);
  }
}

TEST(OpticsHairBsdf, AttenuationSumsToOneWithoutAbsorption) {
  for (double sinThetaO : {0.0, 0.5, 0.95})
    for (double h : {-0.99, -0.4, 0.0, 0.7}) {
      const auto a = hairAttenuation(sinThetaO, h, 1.55, {0.0, 0.0, 0.0});
      EXPECT_NEAR(a[0][0] + a[1][0] + a[2][0] + a[3][0], 1.0, 1e-12);
      const auto absorbed = hairAttenuation(sinThetaO, h, 1.55, {0.5, 1.0, 2.0});
      EXPECT_EQ(absorbed[0][2], a[0][2]);  // the surface reflection is not absorbed
      EXPECT_LT(absorbed[1][2], absorbed[1][0]);
    }
}

// pbrt's white furnace: sigma_a = 0, light 1 from everywhere; the fibre
// returns it all, for any exit direction and offset.
TEST(OpticsHairBsdf, WhiteFurnaceReturnsAllTheLight) {
  for (double beta : {0.2, 0.3, 0.5, 0.7, 0.9}) {
    HairFibre fibre;
    fibre.longitudinalRoughness = fibre.azimuthalRoughness = beta;
    for (const auto& [wo, h] : {std::pair{direction(10.0, 0.3), -0.6}, std::pair{direction(-40.0, 2.0), 0.3}}) {
      const Rgb e = sphereIntegral([&](const glm::dvec3& wi) { return hairScattering(fibre, wi, wo, h); });
      std::printf("furnace beta %.1f theta_o %+5.1f h %+.1f: %.6f\n", beta, std::asin(wo.x) * 180.0 / kPi, h, e[0]);
      EXPECT_NEAR(e[0], 1.0, 0.01) << "beta " << beta << " h " << h;
      EXPECT_NEAR(e[2], e[0], 1e-12);
    }
  }
}

// The same through the shader's table (the far field, h averaged).
TEST(OpticsHairBsdf, WhiteFurnaceThroughTheShaderTable) {
  for (double beta : {0.2, 0.3, 0.6}) {
    HairFibre fibre;
    fibre.longitudinalRoughness = fibre.azimuthalRoughness = beta;
    const HairAzimuthalTable table = hairAzimuthalTable(fibre);
    const glm::dvec3 wo = direction(25.0, 0.0);
    const Rgb e =
        sphereIntegral([&](const glm::dvec3& wi) { return hairScatteringFromTable(fibre, table, wi, wo); }, 400, 360);
    std::printf("furnace (table) beta %.1f: %.6f\n", beta, e[0]);
    EXPECT_NEAR(e[0], 1.0, 0.01);
  }
}

TEST(OpticsHairBsdf, AbsorbingFibreReturnsLessAndLessBlue) {
  HairFibre fibre;
  fibre.sigmaA = hairSigmaAFromPigment(hairPigmentPreset("brown"));
  const glm::dvec3 wo = direction(10.0, 0.3);
  const Rgb e = sphereIntegral([&](const glm::dvec3& wi) { return hairScattering(fibre, wi, wo, 0.2); }, 300, 360);
  for (int c = 0; c < 3; ++c) EXPECT_LE(e[c], 1.0);
  EXPECT_GT(e[0], e[1]);
  EXPECT_GT(e[1], e[2]);
  // At least the surface reflection comes back.
  EXPECT_GT(e[2], 0.03);
}

// Mirroring the azimuths (phi -> -phi) and the offset (h -> -h) mirrors the
// fibre: S is unchanged. The far field is therefore even in phi.
TEST(OpticsHairBsdf, MirrorSymmetry) {
  HairFibre fibre;
  fibre.sigmaA = {0.3, 0.6, 1.2};
  const glm::dvec3 wi = direction(20.0, 2.3), wo = direction(-5.0, 0.4);
  const glm::dvec3 wiMirror(wi.x, wi.y, -wi.z), woMirror(wo.x, wo.y, -wo.z);
  for (double h : {-0.8, 0.1, 0.55}) {
    const Rgb a = hairScattering(fibre, wi, wo, h), b = hairScattering(fibre, wiMirror, woMirror, -h);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-12 * (1.0 + a[c]));
  }
  const Rgb a = hairScatteringFarField(fibre, wi, wo), b = hairScatteringFarField(fibre, wiMirror, woMirror);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-9 * (1.0 + a[c]));
}

// Reciprocity: without the cuticle tilt, on the mirror cone (theta_i =
// -theta_o, where the lobes live) the far-field fibre scatters the same both
// ways. The tilt breaks it, as in Marschner's model.
TEST(OpticsHairBsdf, ReciprocalOnTheMirrorConeWithoutTilt) {
  HairFibre fibre;
  fibre.sigmaA = {0.4, 0.8, 1.6};
  fibre.alphaDegrees = 0.0;
  for (double theta : {5.0, 30.0, 60.0})
    for (double phi : {0.2, 1.5, 3.0}) {
      const glm::dvec3 wi = direction(theta, phi), wo = direction(-theta, 0.0);
      const Rgb a = hairScatteringFarField(fibre, wi, wo), b = hairScatteringFarField(fibre, wo, wi);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-9 * (1.0 + a[c]));
    }
  // Any longitudinal pair at all, for M alone.
  const double v = hairLongitudinalVariance(0.3);
  EXPECT_NEAR(hairLongitudinal(0.3, std::sqrt(0.91), -0.6, 0.8, v),
              hairLongitudinal(-0.6, 0.8, 0.3, std::sqrt(0.91), v), 1e-12);
}

// Each lobe peaks where Marschner's table puts it: theta_h = alpha_p with
// alpha_R = alpha, alpha_TT = -alpha/2, alpha_TRT = -3alpha/2; with alpha < 0
// the white R toward the root (theta_h < 0) and the coloured TRT toward the
// tip.
TEST(OpticsHairBsdf, LobesPeakAtTheirShiftedHalfAngle) {
  HairFibre fibre;
  fibre.longitudinalRoughness = 0.15;
  fibre.alphaDegrees = -3.0;
  const double thetaO = 20.0;
  const double expected[3] = {-3.0, 1.5, 4.5};
  for (int p = 0; p < 3; ++p) {
    fibre.lobes = 1u << p;
    // The azimuth where the lobe sends light: R and TRT back, TT through.
    const double phi = p == 1 ? kPi : 0.0;
    double bestTheta = 0.0, best = -1.0;
    for (double thetaI = -89.0; thetaI <= 89.0; thetaI += 0.05) {
      const double s = hairScatteringFarField(fibre, direction(thetaI, phi), direction(thetaO, 0.0), 32)[0];
      if (s > best) best = s, bestTheta = thetaI;
    }
    EXPECT_NEAR(0.5 * (bestTheta + thetaO), expected[p], 0.3) << "lobe " << p;
  }
}

// The table the shader reads reproduces the far field at its nodes and stays
// close between them.
TEST(OpticsHairBsdf, ShaderTableMatchesTheFarField) {
  HairFibre fibre;
  fibre.sigmaA = hairSigmaAFromPigment(hairPigmentPreset("blond"));
  const HairAzimuthalTable table = hairAzimuthalTable(fibre);
  double worst = 0.0, peak = 0.0;
  for (double sinThetaO : {0.0, 2.0 / 7.0, 0.3, 0.55})
    for (double phi = 0.0; phi <= kPi; phi += kPi / 45.0)
      for (double thetaI : {-40.0, -15.0, 0.0, 10.0}) {
        const double thetaO = std::asin(sinThetaO) * 180.0 / kPi;
        const glm::dvec3 wi = direction(thetaI, phi), wo = direction(thetaO, 0.0);
        const Rgb exact = hairScatteringFarField(fibre, wi, wo), tabled = hairScatteringFromTable(fibre, table, wi, wo);
        for (int c = 0; c < 3; ++c) {
          worst = std::max(worst, std::abs(exact[c] - tabled[c]));
          peak = std::max(peak, exact[c]);
        }
      }
  EXPECT_LT(worst, 0.05 * peak);
}

TEST(OpticsHairBsdf, PresetsOrderedByMelanin) {
  auto albedo = [](const std::string& name) {
    HairFibre fibre;
    fibre.sigmaA = hairSigmaAFromPigment(hairPigmentPreset(name));
    return hairMeanAlbedo(fibre);
  };
  const Rgb black = albedo("black"), brown = albedo("brown"), blond = albedo("blond"), grey = albedo("grey"),
            red = albedo("red");
  std::printf("mean albedo: black %.3f brown %.3f blond %.3f grey %.3f red %.3f (luminance)\n", luminance(black),
              luminance(brown), luminance(blond), luminance(grey), luminance(red));
  EXPECT_LT(luminance(black), luminance(brown));
  EXPECT_LT(luminance(brown), luminance(blond));
  EXPECT_LT(luminance(blond), luminance(grey));
  EXPECT_GT(red[0], 1.5 * red[2]);    // red: red over blue
  EXPECT_LT(grey[0], 1.3 * grey[2]);  // grey: nearly neutral
  HairFibre white;
  EXPECT_NEAR(luminance(hairMeanAlbedo(white)), 1.0, 1e-9);
  EXPECT_THROW(hairPigmentPreset("green"), std::exception);
}

TEST(OpticsHairBsdf, AbsorptionFromAColour) {
  const Rgb sigma = hairSigmaAFromColor({0.6, 0.4, 0.2}, 0.3);
  EXPECT_LT(sigma[0], sigma[1]);
  EXPECT_LT(sigma[1], sigma[2]);
  EXPECT_EQ(hairSigmaAFromColor({1.0, 1.0, 1.0}, 0.3)[1], 0.0);
}

}  // namespace
}  // namespace mq::optics
