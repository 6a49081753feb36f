// The self-collision's four-lane computations against the scalar ones they
// stand in for, which define its candidates: the edge-edge distance test
// (the search drops the pairs it rejects), also where the float arithmetic
// is delicate (parallel and point segments, reach at the distance), its
// cheaper screen (never dropping a pair the scalar test keeps), and the
// normal cones' merges (flat patches), bit for bit.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "sim/cloth/collision/segment_reach.h"
#include "sim/cloth/collision/self_collision.h"

namespace mq::cloth {
namespace {

#ifdef MQ_SEGMENT_REACH_SSE
struct SegmentPair {
  glm::vec3 p0, p1, q0, q1;
  float reach;
};

Vec3x4 lanes(const SegmentPair (&pairs)[4], glm::vec3 SegmentPair::*point) {
  Vec3x4 v;
  float x[4], y[4], z[4];
  for (int k = 0; k < 4; ++k) x[k] = (pairs[k].*point).x, y[k] = (pairs[k].*point).y, z[k] = (pairs[k].*point).z;
  v.x = _mm_loadu_ps(x), v.y = _mm_loadu_ps(y), v.z = _mm_loadu_ps(z);
  return v;
}

unsigned fourLaneAnswer(const SegmentPair (&pairs)[4]) {
  float reach[4];
  for (int k = 0; k < 4; ++k) reach[k] = pairs[k].reach;
  return segmentsWithinReach(lanes(pairs, &SegmentPair::p0), lanes(pairs, &SegmentPair::p1),
                             lanes(pairs, &SegmentPair::q0), lanes(pairs, &SegmentPair::q1), _mm_loadu_ps(reach));
}

// Cloth-like segments (1.5 cm) near each other, some of them special: q
// parallel to p, p or q a point, q through p; the reach near the pair's distance.
SegmentPair randomPair(std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), fraction(0.0f, 1.0f);
  auto direction = [&] { return glm::vec3(unit(rng), unit(rng), unit(rng)) * 0.015f; };
  SegmentPair s;
  s.p0 = glm::vec3(unit(rng), unit(rng), unit(rng)) * 0.3f;
  s.p1 = s.p0 + direction();
  s.q0 = s.p0 + direction();
  s.q1 = s.q0 + direction();
  switch (rng() % 6) {
    case 0: s.q1 = s.q0 + (s.p1 - s.p0) * (0.5f + fraction(rng)); break;   // parallel
    case 1: s.p1 = s.p0; break;                                             // p a point
    case 2: s.q1 = s.q0; break;                                             // q a point
    case 3: s.q0 = glm::mix(s.p0, s.p1, fraction(rng)) - 0.5f * direction(), s.q1 = s.q0 + direction(); break;
    default: break;
  }
  const glm::vec2 st = closestSegmentParameters(s.p0, s.p1, s.q0, s.q1);
  const float distance = glm::length(glm::mix(s.p0, s.p1, st.x) - glm::mix(s.q0, s.q1, st.y));
  // Half the pairs with the reach at the distance, to the last bit.
  s.reach = rng() % 2 ? distance : distance * (0.5f + fraction(rng)) + 0.004f * fraction(rng);
  return s;
}

TEST(SegmentReach, FourLanesGiveTheScalarAnswers) {
  std::mt19937 rng(2026);
  int within = 0, apart = 0;
  for (int round = 0; round < 20000; ++round) {
    SegmentPair pairs[4];
    unsigned expected = 0;
    for (int k = 0; k < 4; ++k) {
      pairs[k] = randomPair(rng);
      const bool scalar = segmentsWithinReach(pairs[k].p0, pairs[k].p1, pairs[k].q0, pairs[k].q1, pairs[k].reach);
      expected |= unsigned(scalar) << k;
      (scalar ? within : apart) += 1;
    }
    ASSERT_EQ(fourLaneAnswer(pairs), expected) << "round " << round;
  }
  EXPECT_GT(within, 10000);
  EXPECT_GT(apart, 10000);
}

TEST(SegmentReach, TheMidpointLineBoundRejectsOnlyPairsTheScalarTestRejects) {
  // The edge search's screen (segmentsApart) drops pairs before their exact
  // test: it must never drop one the scalar test keeps, also with the reach
  // at the distance to the last bit, and it must drop most pairs whose
  // distance is well beyond the reach. Its inputs as the search computes them.
  std::mt19937 rng(33);
  int kept = 0, dropped = 0, farDropped = 0, far = 0;
  for (int round = 0; round < 20000; ++round) {
    SegmentPair pairs[4];
    float reach[4];
    float mid[3][4], halfP[3][4], halfQ[3][4];
    for (int k = 0; k < 4; ++k) {
      pairs[k] = randomPair(rng);
      // A quarter of the lanes with a small reach: their segments are far apart.
      if (k == 3) pairs[k].reach *= 0.25f;
      reach[k] = pairs[k].reach;
      const glm::vec3 m = 0.5f * (pairs[k].p0 + pairs[k].p1) - 0.5f * (pairs[k].q0 + pairs[k].q1);
      const glm::vec3 hp = 0.5f * (pairs[k].p1 - pairs[k].p0), hq = 0.5f * (pairs[k].q1 - pairs[k].q0);
      for (int c = 0; c < 3; ++c) mid[c][k] = m[c], halfP[c][k] = hp[c], halfQ[c][k] = hq[c];
    }
    auto lanes3 = [](float (&v)[3][4]) { return Vec3x4{_mm_loadu_ps(v[0]), _mm_loadu_ps(v[1]), _mm_loadu_ps(v[2])}; };
    const unsigned apart = segmentsApart(lanes3(mid), lanes3(halfP), lanes3(halfQ), _mm_loadu_ps(reach));
    for (int k = 0; k < 4; ++k) {
      const bool within = segmentsWithinReach(pairs[k].p0, pairs[k].p1, pairs[k].q0, pairs[k].q1, pairs[k].reach);
      const bool drop = (apart >> k & 1u) != 0;
      ASSERT_FALSE(within && drop) << "round " << round << " lane " << k;
      (drop ? dropped : kept) += 1;
      if (k == 3 && !within) far += 1, farDropped += drop;
    }
  }
  EXPECT_GT(kept, 20000);
  EXPECT_GT(dropped, 10000);
  EXPECT_GT(farDropped, far / 2);
}
#endif

TEST(AabbTree, LeafQueriesTwoLevelsAtATimeFindEveryOverlappingBox) {
  // The vertex-triangle search walks the tree by grandchildren and tests a
  // leaf's four boxes at once: the same boxes as a test of them all, after
  // a build and after a refit (the grandchildren's boxes are copies).
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> position(0.0f, 1.0f), size(0.0f, 0.05f);
  auto randomBoxes = [&](size_t count) {
    std::vector<Box> boxes(count);
    for (Box& b : boxes) {
      b.min = {position(rng), position(rng), position(rng)};
      b.max = b.min + glm::vec3(size(rng), size(rng), size(rng));
    }
    return boxes;
  };
  AabbTree tree;
  const std::vector<Box> built = randomBoxes(3001);
  tree.build(built);
  for (const std::vector<Box>& boxes : {built, randomBoxes(3001)}) {
    tree.refit(boxes);
    for (int q = 0; q < 100; ++q) {
      const glm::vec3 at(position(rng), position(rng), position(rng));
      const Box probe{at, at + glm::vec3(0.1f * position(rng))};
      std::set<uint32_t> expected, found;
      for (uint32_t i = 0; i < boxes.size(); ++i)
        if (boxes[i].overlaps(probe)) expected.insert(i);
      tree.queryLeaves(probe, [&](int32_t leaf) {
        const uint32_t first = tree.nodeInfo(size_t(leaf)).first;
        for (unsigned mask = tree.leafOverlaps(leaf, probe); mask != 0; mask &= mask - 1)
          EXPECT_TRUE(found.insert(tree.primitive(first + uint32_t(__builtin_ctz(mask)))).second);
      }, [](int32_t) { return false; });
      EXPECT_EQ(found, expected);
    }
  }
}

// Cones around random axes, many near the flat limit (45 degrees), some
// wide, some opposite to each other.
NormalCone randomCone(std::mt19937& rng, const glm::vec3& near) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), angle(0.6f, 0.8f);
  NormalCone c;
  if (rng() % 10 == 0) return c;  // wide
  const glm::vec3 axis = rng() % 10 == 0 ? -near : near + 0.4f * glm::vec3(unit(rng), unit(rng), unit(rng));
  c.axis = glm::normalize(axis);
  c.cosine = rng() % 3 == 0 ? 1.0f : angle(rng) + 0.2f * std::abs(unit(rng));
  c.sine = std::sqrt(std::max(0.0f, 1.0f - c.cosine * c.cosine));
  return c;
}

TEST(NormalCones, FourLaneMergesGiveTheScalarCones) {
  std::mt19937 rng(45);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int flat = 0, wide = 0;
  for (int round = 0; round < 20000; ++round) {
    const glm::vec3 near = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + glm::vec3(0.0f, 0.01f, 0.0f));
    NormalCone cones[4], others[4], expected[4];
    const unsigned lanes = unsigned(rng() % 16);
    for (int k = 0; k < 4; ++k) {
      cones[k] = randomCone(rng, near), others[k] = randomCone(rng, near);
      expected[k] = lanes >> k & 1u ? mergedCones(cones[k], others[k]) : cones[k];
      (expected[k].cosine >= 0.7071f ? flat : wide) += 1;
    }
    mergeFourCones(cones, others, lanes);
    for (int k = 0; k < 4; ++k) {
      ASSERT_EQ(cones[k].axis, expected[k].axis) << "round " << round << " lane " << k;
      ASSERT_EQ(cones[k].cosine, expected[k].cosine) << "round " << round << " lane " << k;
      ASSERT_EQ(cones[k].sine, expected[k].sine) << "round " << round << " lane " << k;
    }
  }
  EXPECT_GT(flat, 10000);
  EXPECT_GT(wide, 10000);
}

}  // namespace
}  // namespace mq::cloth
