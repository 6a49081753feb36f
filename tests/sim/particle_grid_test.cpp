// The hair interaction's particle grid: every pair within the radius is
// found through the 9 row ranges, over clustered particles, a spread wider
// than the grid's cap (cells widen) and particles that are not finite.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "sim/hair/particle_grid.h"

namespace mq {
namespace {

// The neighbours within `radius` of each particle, through the grid and by
// brute force, as sets of (particle, neighbour) pairs.
void expectGridFindsEveryNeighbour(const std::vector<glm::vec3>& points, float radius) {
  ParticleGrid grid;
  grid.build(points, radius);
  ASSERT_EQ(grid.order().size(), points.size());
  std::set<std::pair<uint32_t, uint32_t>> found, expected;
  const float radius2 = radius * radius;
  ParticleGrid::Range ranges[9];
  for (size_t e = 0; e < points.size(); ++e) {
    const uint32_t i = grid.order()[e];
    const int count = grid.neighbourRanges(grid.cellAt(e), ranges);
    ASSERT_LE(count, 9);
    for (int r = 0; r < count; ++r)
      for (uint32_t f = ranges[r].first; f < ranges[r].second; ++f) {
        const uint32_t j = grid.order()[f];
        const glm::vec3 d = points[i] - points[j];
        if (j == i || !(glm::dot(d, d) < radius2)) continue;
        EXPECT_TRUE(found.insert({i, j}).second) << "pair seen twice";
      }
    for (uint32_t j = 0; j < points.size(); ++j) {
      const glm::vec3 d = points[i] - points[j];
      if (j != i && glm::dot(d, d) < radius2) expected.insert({i, j});
    }
  }
  EXPECT_EQ(found, expected);
  EXPECT_FALSE(expected.empty());
}

TEST(ParticleGrid, FindsEveryPairWithinTheRadius) {
  std::mt19937 rng(4);
  std::normal_distribution<float> cluster(0.0f, 0.03f);
  std::uniform_real_distribution<float> box(-0.2f, 0.2f);
  std::vector<glm::vec3> points;
  for (int i = 0; i < 1500; ++i) points.emplace_back(cluster(rng), cluster(rng) + 0.1f, cluster(rng));
  for (int i = 0; i < 1500; ++i) points.emplace_back(box(rng), box(rng), box(rng));
  expectGridFindsEveryNeighbour(points, 0.01f);
}

TEST(ParticleGrid, WiderThanItsCellCapAndNotFinite) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> line(0.0f, 1.0f);
  std::vector<glm::vec3> points;
  // 1,000 radii along x: more than kMaxCellsPerAxis cells of one radius.
  for (int i = 0; i < 3000; ++i) points.emplace_back(10.0f * line(rng), 0.01f * line(rng), 0.0f);
  points.emplace_back(std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f);
  points.emplace_back(std::numeric_limits<float>::infinity(), 0.0f, 0.0f);
  expectGridFindsEveryNeighbour(points, 0.01f);
}

}  // namespace
}  // namespace mq
