// Oracle O16 of ../shared/docs/research/skin-appearance.md: Kubelka-Munk limits.
#include <gtest/gtest.h>

#include <cmath>

#include "core/optics/kubelka_munk.h"

namespace mq::optics {
namespace {

TEST(OpticsKubelkaMunk, NoAbsorptionConservesLight) {
  for (double sh : {0.01, 0.5, 3.0, 40.0}) {
    const KubelkaMunkLayer layer = kubelkaMunkLayer(0.0, 2.0, sh / 2.0);
    EXPECT_NEAR(layer.reflectance + layer.transmittance, 1.0, 1e-9);
    EXPECT_NEAR(layer.reflectance, sh / (1.0 + sh), 1e-9);
  }
}

TEST(OpticsKubelkaMunk, ThickLayerIsOpaque) {
  for (double k : {0.01, 0.3, 2.0}) {
    const double s = 1.5, a = 1.0 + k / s, b = std::sqrt(a * a - 1.0);
    const KubelkaMunkLayer layer = kubelkaMunkLayer(k, s, 1e4);
    EXPECT_NEAR(layer.reflectance, a - b, 1e-9);
    EXPECT_NEAR(kubelkaMunkOpaqueReflectance(k, s), a - b, 1e-9);
    EXPECT_NEAR(layer.transmittance, 0.0, 1e-9);
  }
}

TEST(OpticsKubelkaMunk, NoScatteringIsBeerLambert) {
  for (double s : {0.0, 1e-12}) {
    const KubelkaMunkLayer layer = kubelkaMunkLayer(0.7, s, 1.3);
    EXPECT_NEAR(layer.transmittance, std::exp(-0.7 * 1.3), 1e-9) << "S = " << s;
    EXPECT_NEAR(layer.reflectance, 0.0, 1e-9);
  }
}

TEST(OpticsKubelkaMunk, AddingIsAssociativeAndMatchesSplittingALayer) {
  const KubelkaMunkLayer a = kubelkaMunkLayer(0.3, 2.0, 0.2), b = kubelkaMunkLayer(1.0, 0.5, 0.7),
                         c = kubelkaMunkLayer(0.05, 4.0, 1.5);
  const KubelkaMunkLayer left = addLayers(addLayers(a, b), c), right = addLayers(a, addLayers(b, c));
  EXPECT_NEAR(left.reflectance, right.reflectance, 1e-9);
  EXPECT_NEAR(left.transmittance, right.transmittance, 1e-9);
  // Two halves of one layer make the whole layer.
  const KubelkaMunkLayer half = kubelkaMunkLayer(0.4, 3.0, 0.25), whole = kubelkaMunkLayer(0.4, 3.0, 0.5);
  const KubelkaMunkLayer stacked = addLayers(half, half);
  EXPECT_NEAR(stacked.reflectance, whole.reflectance, 1e-9);
  EXPECT_NEAR(stacked.transmittance, whole.transmittance, 1e-9);
}

TEST(OpticsKubelkaMunk, AbsorptionOverScatteringRoundTrips) {
  for (double ratio : {0.001, 0.1, 1.0, 10.0}) {
    const double rInf = kubelkaMunkOpaqueReflectance(ratio * 2.0, 2.0);
    EXPECT_NEAR(kubelkaMunkAbsorptionOverScattering(rInf), ratio, 1e-9 * std::max(1.0, ratio));
  }
}

}  // namespace
}  // namespace mq::optics
