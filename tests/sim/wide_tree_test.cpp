// The body collider's 4-wide tree against brute force: every overlapping
// box exactly once, and the nearest box, after builds and refits.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "sim/cloth/collision/wide_tree.h"

namespace mq::cloth {
namespace {

std::vector<Box> randomBoxes(std::mt19937& random, size_t count) {
  std::uniform_real_distribution<float> where(-1.0f, 1.0f), size(0.0f, 0.1f);
  std::vector<Box> boxes(count);
  for (Box& b : boxes) {
    b.min = {where(random), where(random), where(random)};
    b.max = b.min + glm::vec3(size(random), size(random), size(random));
  }
  return boxes;
}

TEST(WideTree, QueryVisitsEveryOverlappingBoxOnce) {
  std::mt19937 random(3);
  for (size_t count : {1, 3, 5, 17, 1000}) {
    std::vector<Box> boxes = randomBoxes(random, count);
    WideTree tree;
    tree.build(boxes);
    for (int refit = 0; refit < 2; ++refit) {
      for (int q = 0; q < 50; ++q) {
        const Box probe = randomBoxes(random, 1)[0];
        std::multiset<uint32_t> visited, expected;
        tree.query(probe, [&](uint32_t i) { visited.insert(i); });
        for (uint32_t i = 0; i < count; ++i)
          if (boxes[i].overlaps(probe)) expected.insert(i);
        EXPECT_EQ(visited, expected) << count << " boxes";
      }
      boxes = randomBoxes(random, count);  // the same primitives moved
      tree.refit(boxes);
    }
  }
}

TEST(WideTree, NearestFindsTheNearestBoxWithinTheBound) {
  std::mt19937 random(5);
  std::vector<Box> boxes = randomBoxes(random, 2000);
  WideTree tree;
  tree.build(boxes);
  boxes = randomBoxes(random, boxes.size());
  tree.refit(boxes);
  std::uniform_real_distribution<float> where(-1.2f, 1.2f);
  int found = 0;
  for (int q = 0; q < 500; ++q) {
    const glm::vec3 p(where(random), where(random), where(random));
    float best2 = 0.05f * 0.05f, expected2 = best2;
    int64_t nearest = -1, expected = -1;
    // Distance to a box's centre: a primitive inside its box.
    auto centre2 = [&](uint32_t i) {
      const glm::vec3 d = p - 0.5f * (boxes[i].min + boxes[i].max);
      return glm::dot(d, d);
    };
    tree.nearest(p, best2, [&](uint32_t i) {
      EXPECT_LE(squaredDistance(boxes[i], p), best2);
      if (centre2(i) < best2) best2 = centre2(i), nearest = i;
    });
    for (uint32_t i = 0; i < boxes.size(); ++i)
      if (centre2(i) < expected2) expected2 = centre2(i), expected = i;
    EXPECT_EQ(nearest, expected);
    found += nearest >= 0;
  }
  EXPECT_GT(found, 20);  // the bound let some searches find something
}

}  // namespace
}  // namespace mq::cloth
