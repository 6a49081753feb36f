// Fresnel terms and the boundary constant A of the dipole.
#include <gtest/gtest.h>

#include <cmath>

#include "core/optics/fresnel.h"
#include "core/optics_test_util.h"

namespace mq::optics {
namespace {

TEST(OpticsFresnel, NormalIncidenceIsTheSquaredIndexRatio) {
  for (double eta : {1.3, 1.4, 1.0 / 1.4}) {
    const double expected = std::pow((eta - 1.0) / (eta + 1.0), 2.0);
    EXPECT_NEAR(fresnelDielectric(1.0, eta), expected, 1e-14);
  }
  EXPECT_EQ(fresnelDielectric(0.37, 1.0), 0.0);
}

TEST(OpticsFresnel, TotalInternalReflectionBeyondTheCriticalAngle) {
  // From skin (1.4) into air: critical sin = 1/1.4 = 0.714; cos 0.5 is past it.
  EXPECT_EQ(fresnelDielectric(0.5, 1.0 / 1.4), 1.0);
  EXPECT_LT(fresnelDielectric(0.8, 1.0 / 1.4), 1.0);
  EXPECT_EQ(refractedCos(0.5, 1.0 / 1.4), -1.0);
}

TEST(OpticsFresnel, SameReflectanceBothWaysAlongOnePath) {
  for (double cosI : {0.2, 0.5, 0.9}) {
    const double cosT = refractedCos(cosI, 1.4);
    EXPECT_NEAR(fresnelDielectric(cosI, 1.4), fresnelDielectric(cosT, 1.0 / 1.4), 1e-14);
  }
}

TEST(OpticsFresnel, DiffuseReflectanceMatchesTheBriefsValues) {
  // skin-appearance.md §2, [M]: F_dr(1.3) = 0.44476, A = 2.60206; F_dr(1.4) = 0.52949, A = 3.25070.
  EXPECT_NEAR(diffuseFresnelReflectance(1.3), 0.44476, 1e-5);
  EXPECT_NEAR(boundaryMismatch(1.3), 2.60206, 1e-5);
  EXPECT_NEAR(diffuseFresnelReflectance(1.4), 0.52949, 1e-5);
  EXPECT_NEAR(boundaryMismatch(1.4), 3.25070, 1e-5);
  EXPECT_EQ(diffuseFresnelReflectance(1.0), 0.0);
  EXPECT_EQ(boundaryMismatch(1.0), 1.0);
}

TEST(OpticsFresnel, DiffuseReflectanceFitIsCloseToTheHemisphericalIntegral) {
  // F_dr(eta) is a fit of 2 int_0^1 F(mu) mu dmu for light inside the medium;
  // an empirical fit, so allow 0.01.
  for (double eta : {1.2, 1.3, 1.4, 1.5}) {
    const double integral =
        2.0 * test::simpson([eta](double mu) { return fresnelDielectric(mu, 1.0 / eta) * mu; }, 0, 1, 20000);
    EXPECT_NEAR(diffuseFresnelReflectance(eta), integral, 0.01) << "eta = " << eta;
  }
}

}  // namespace
}  // namespace mq::optics
