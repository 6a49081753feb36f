// Perlin noise: zero at the lattice, smooth, in about [-1, 1].
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/math/perlin_noise.h"

namespace mq {
namespace {

TEST(PerlinNoise, ZeroOnTheLatticeAndSmoothBetween) {
  const PerlinNoise perlin(7);
  EXPECT_EQ(perlin.noise(3.0f, -2.0f, 5.0f), 0.0f);
  const float a = perlin.noise(0.5f, 0.25f, 0.75f), b = perlin.noise(0.5f + 1e-3f, 0.25f, 0.75f);
  EXPECT_LT(std::abs(a - b), 1e-2f);
  // Over many cells the values spread over most of [-1, 1] and stay in it.
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> coordinate(-300.0f, 300.0f);
  float lo = 0.0f, hi = 0.0f;
  for (int i = 0; i < 20000; ++i) {
    const float n = perlin.noise(coordinate(rng), coordinate(rng), coordinate(rng));
    lo = std::min(lo, n);
    hi = std::max(hi, n);
  }
  EXPECT_LT(lo, -0.6f);
  EXPECT_GT(hi, 0.6f);
  EXPECT_GE(lo, -1.1f);
  EXPECT_LE(hi, 1.1f);
}

}  // namespace
}  // namespace mq
