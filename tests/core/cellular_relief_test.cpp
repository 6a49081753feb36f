// The skin micro-relief's height and gradient (oracle O26): the bump leaves
// the mean normal alone, its gradient is the height's derivative, and it
// fades out where cells get smaller than 4 pixels.
#include <gtest/gtest.h>

#include "core/geometry/cellular_relief.h"

namespace mq {
namespace {

TEST(CellularRelief, MeanBumpedNormalIsTheBaseNormal) {
  // A 100 x 100 cell patch of a plane, 8 samples per cell along each axis.
  const glm::vec3 normal(0.0f, 0.0f, 1.0f);
  for (float strength : {0.15f, 0.4f}) {
    glm::dvec3 sum(0.0);
    for (int j = 0; j < 800; ++j)
      for (int i = 0; i < 800; ++i) {
        const glm::vec3 p(0.125f * i + 0.06f, 0.125f * j + 0.03f, 0.37f);
        sum += glm::dvec3(bumpedNormal(normal, cellularRelief(p).gradient, strength));
      }
    const glm::dvec3 mean = glm::normalize(sum);
    EXPECT_LT(glm::length(glm::dvec2(mean.x, mean.y)), 0.02) << "strength " << strength;
  }
}

TEST(CellularRelief, GradientIsTheHeightsDerivative) {
  int checked = 0;
  for (int i = 0; i < 400; ++i) {
    const glm::vec3 p(0.731f * i, 0.377f * i + 0.1f, -0.213f * i);
    const ReliefSample s = cellularRelief(p);
    EXPECT_GE(s.height, 0.0f);
    EXPECT_LE(s.height, 1.0f);
    const float e = 1e-3f;
    glm::vec3 numeric;
    bool smooth = true;
    for (int k = 0; k < 3; ++k) {
      glm::vec3 d(0.0f);
      d[k] = e;
      const float hp = cellularRelief(p + d).height, hm = cellularRelief(p - d).height;
      numeric[k] = (hp - hm) / (2 * e);
      // Skip points next to a kink (a furrow's floor, a change of neighbour).
      if (std::abs(hp + hm - 2 * s.height) > 1e-4f) smooth = false;
    }
    if (!smooth) continue;
    ++checked;
    EXPECT_NEAR(glm::length(numeric - s.gradient), 0.0f, 0.02f * (1.0f + glm::length(numeric)));
  }
  EXPECT_GT(checked, 200);
}

TEST(CellularRelief, FadesBelowFourPixelsPerCell) {
  EXPECT_EQ(reliefFade(1.0f), 0.0f);
  EXPECT_EQ(reliefFade(4.0f), 0.0f);
  EXPECT_GT(reliefFade(5.0f), 0.0f);
  EXPECT_LT(reliefFade(8.0f), 1.0f);
  EXPECT_EQ(reliefFade(12.0f), 1.0f);
  // Faded to nothing, the normal is the base normal exactly.
  const glm::vec3 n(0.0f, 1.0f, 0.0f);
  EXPECT_EQ(bumpedNormal(n, cellularRelief({0.3f, 0.2f, 0.1f}).gradient, 0.3f * reliefFade(3.0f)), n);
}

}  // namespace
}  // namespace mq
