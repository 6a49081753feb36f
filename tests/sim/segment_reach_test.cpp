// The four-lane edge-edge distance test against the scalar one it stands in
// for: the self-collision search drops the pairs it rejects, so its answer
// must be the scalar answer for every lane, also where the float arithmetic
// is delicate (parallel and point segments, reach at the distance).
#include <gtest/gtest.h>

#include <random>

#include "sim/cloth/collision/segment_reach.h"

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
#endif

}  // namespace
}  // namespace mq::cloth
