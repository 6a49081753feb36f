// Hair against hair (sim/hair/hair_interaction.h): a strand swinging through
// another is stopped by the pressure, a squeezed wisp spreads back to its
// groomed density, friction evens out sliding strands, and the crossing count
// measures segments, not just particles.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/hair/hairstyle.h"
#include "core/hair/strands.h"
#include "sim/hair/hair_bake.h"
#include "sim/hair/hair_interaction.h"
#include "sim/hair/hair_simulator.h"
#include "strand_test_util.h"

namespace mq {
namespace {

using test::addStraightStrand;
using test::pointOf;

constexpr float kDt = 1.0f / 60.0f;

std::vector<glm::vec3> toVec3(const std::vector<float>& points) {
  std::vector<glm::vec3> out(points.size() / 3);
  for (size_t i = 0; i < out.size(); ++i) out[i] = pointOf(points, i);
  return out;
}

std::vector<float> toFloats(const std::vector<glm::vec3>& points) {
  std::vector<float> out;
  for (const glm::vec3& p : points) out.insert(out.end(), {p.x, p.y, p.z});
  return out;
}

// The closest two points of different strands ever get while one strand's
// root is carried through another: strand 0 hangs from the origin, strand 1
// hangs from a root 5 cm higher that moves along x at 0.5 m/s, in the same
// plane, from 10 cm on one side to 10 cm on the other.
struct Sweep {
  float closest = 1e9f;        // metres, particles of the two strands (roots excluded)
  size_t framesCrossing = 0;   // frames with segments closer than 2 mm
  float hangingDisplaced = 0;  // how far the still strand's tip was pushed
};

Sweep sweepThrough(float volume, float friction) {
  constexpr int kPoints = 31;
  Strands strands;
  strands.pointsPerStrand = kPoints;
  addStraightStrand(strands, {0.0f, 0.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.3f);
  addStraightStrand(strands, {-0.1f, 0.05f, 0.001f}, {0.0f, -1.0f, 0.0f}, 0.35f);
  HairSimParams params;
  params.interaction.volume = volume;
  params.interaction.friction = friction;
  params.interaction.radius = 0.02f;
  HairSimulator sim(params);
  sim.setRest(strands);
  Sweep sweep;
  const glm::vec3 restTip = pointOf(strands.points, kPoints - 1);
  const std::vector<glm::quat> rotations(2, glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
  for (int frame = 0; frame < 60; ++frame) {
    const float x = -0.1f + 0.5f * kDt * float(frame + 1);
    sim.step(kDt, {glm::vec3(0.0f), glm::vec3(x, 0.05f, 0.001f)}, rotations);
    const std::vector<float>& p = sim.positions();
    for (int i = 1; i < kPoints; ++i)
      for (int j = 1; j < kPoints; ++j)
        sweep.closest = std::min(sweep.closest, glm::length(pointOf(p, i) - pointOf(p, kPoints + j)));
    if (closeSegmentPairs(p, 2, kPoints, 0.002f) > 0) ++sweep.framesCrossing;
    sweep.hangingDisplaced = std::max(sweep.hangingDisplaced, glm::length(pointOf(p, kPoints - 1) - restTip));
  }
  return sweep;
}

TEST(HairInteraction, AStrandCarriedThroughAnotherPushesItAside) {
  const Sweep free = sweepThrough(0.0f, 0.0f);
  const Sweep held = sweepThrough(0.6f, 0.2f);
  // Without interaction the carried strand passes through the hanging one
  // (1 mm apart); with it, the two stay a quarter of the kernel radius apart
  // (the pressure pushes them out of each other's way) and the hanging
  // strand is pushed aside.
  EXPECT_GT(free.framesCrossing, 0u);
  EXPECT_LT(free.closest, 0.003f);
  EXPECT_EQ(held.framesCrossing, 0u);
  EXPECT_GT(held.closest, 0.004f);
  EXPECT_GT(held.hangingDisplaced, 0.01f);
  EXPECT_LT(free.hangingDisplaced, 1e-4f);
}

// A wisp of parallel strands in a ring, squeezed to half its radius.
struct Wisp {
  std::vector<float> rest, positions;
  std::vector<glm::vec3> predicted;  // of a substep from positions
  size_t strands = 0;
  int points = 12;
  float meanRadius(const std::vector<float>& x) const {
    double sum = 0.0;
    size_t count = 0;
    for (size_t s = 0; s < strands; ++s)
      for (int i = 1; i < points; ++i) {
        const glm::vec3 p = pointOf(x, s * points + i);
        sum += std::hypot(p.x, p.z);
        ++count;
      }
    return float(sum / double(count));
  }
};

Wisp squeezedWisp() {
  Wisp w;
  Strands strands;
  strands.pointsPerStrand = w.points;
  for (int ring = 1; ring <= 3; ++ring)
    for (int k = 0; k < 6 * ring; ++k) {
      const float a = 2.0f * float(M_PI) * float(k) / float(6 * ring);
      addStraightStrand(strands, {0.004f * ring * std::cos(a), 0.0f, 0.004f * ring * std::sin(a)}, {0, -1, 0}, 0.1f);
    }
  w.strands = strands.strandCount();
  w.rest = strands.points;
  w.positions = w.rest;
  for (size_t k = 0; k < w.positions.size() / 3; ++k) {
    if (k % w.points == 0) continue;  // roots stay on the scalp
    w.positions[3 * k] *= 0.5f;
    w.positions[3 * k + 2] *= 0.5f;
  }
  w.predicted = toVec3(w.positions);
  return w;
}

TEST(HairInteraction, ASqueezedWispSpreadsBackToItsGroomedVolume) {
  Wisp wisp = squeezedWisp();
  const float restRadius = wisp.meanRadius(wisp.rest), squeezed = wisp.meanRadius(wisp.positions);
  HairInteraction interaction;
  interaction.setRest(wisp.rest, wisp.strands, wisp.points, {0.5f, 0.0f, 0.012f});
  // Substeps of a wisp at rest: each one's corrected prediction is the next position.
  for (int step = 0; step < 30; ++step) {
    interaction.apply(wisp.predicted, wisp.positions, kDt);
    wisp.positions = toFloats(wisp.predicted);
  }
  const float spread = wisp.meanRadius(wisp.positions);
  EXPECT_GT(spread, squeezed + 0.6f * (restRadius - squeezed));
  EXPECT_LT(spread, 1.5f * restRadius);  // back to the groom's density, not blown apart
  // Roots are never moved.
  for (size_t s = 0; s < wisp.strands; ++s)
    EXPECT_EQ(pointOf(wisp.positions, s * wisp.points), pointOf(wisp.rest, s * wisp.points));
}

TEST(HairInteraction, AWispAtItsRestDensityStaysPut) {
  Wisp wisp = squeezedWisp();
  wisp.positions = wisp.rest;
  wisp.predicted = toVec3(wisp.rest);
  HairInteraction interaction;
  interaction.setRest(wisp.rest, wisp.strands, wisp.points, {0.5f, 0.0f, 0.012f});
  interaction.apply(wisp.predicted, wisp.positions, kDt);
  EXPECT_EQ(interaction.compressedCount(), 0u);
  EXPECT_EQ(wisp.predicted, toVec3(wisp.rest));
}

TEST(HairInteraction, FrictionEvensOutTheVelocitiesOfNeighbours) {
  Wisp wisp = squeezedWisp();
  wisp.positions = wisp.rest;
  // Alternate strands slide up and down along the wisp at 1 m/s.
  std::vector<float> velocities(wisp.rest.size(), 0.0f);
  for (size_t s = 0; s < wisp.strands; ++s)
    for (int i = 1; i < wisp.points; ++i) velocities[3 * (s * wisp.points + i) + 1] = s % 2 ? 1.0f : -1.0f;
  HairInteraction interaction;
  interaction.setRest(wisp.rest, wisp.strands, wisp.points, {0.0f, 0.5f, 0.012f});
  double meanSpeed = 0.0;  // along the wisp, over the moving particles
  for (int step = 0; step < 5; ++step) {
    for (size_t i = 0; i < wisp.predicted.size(); ++i)
      wisp.predicted[i] = pointOf(wisp.positions, i) + kDt * pointOf(velocities, i);
    interaction.apply(wisp.predicted, wisp.positions, kDt);
    meanSpeed = 0.0;
    for (size_t i = 0; i < wisp.predicted.size(); ++i) {
      const glm::vec3 v = (wisp.predicted[i] - pointOf(wisp.positions, i)) / kDt;
      for (int k = 0; k < 3; ++k) velocities[3 * i + k] = v[k];
      if (i % wisp.points) meanSpeed += std::abs(v.y) / double(wisp.strands * (wisp.points - 1));
      // Friction alone moves nothing sideways.
      EXPECT_NEAR(v.x, 0.0f, 1e-4f);
      EXPECT_NEAR(v.z, 0.0f, 1e-4f);
    }
    wisp.positions = toFloats(wisp.predicted);
  }
  // The strands slide apart as they go (their ends leave the others behind),
  // but on average they took up most of their neighbours' motion.
  EXPECT_LT(meanSpeed, 0.5);
}

TEST(HairInteraction, CrossingCountSeesSegmentsPassingBetweenParticles) {
  // Two strands crossing at right angles midway between their particles.
  Strands strands;
  strands.pointsPerStrand = 5;
  addStraightStrand(strands, {-0.2f, 0.0f, 0.0f}, {1, 0, 0}, 0.4f);  // particles every 10 cm
  addStraightStrand(strands, {0.05f, 0.0f, -0.25f}, {0, 0, 1}, 0.4f);
  EXPECT_EQ(closeSegmentPairs(strands.points, 2, 5, 0.001f), 1u);
  strands.points[3 * 5 + 1] = strands.points[3 * 6 + 1] = strands.points[3 * 7 + 1] = strands.points[3 * 8 + 1] =
      strands.points[3 * 9 + 1] = 0.01f;  // 1 cm above
  EXPECT_EQ(closeSegmentPairs(strands.points, 2, 5, 0.005f), 0u);
  EXPECT_EQ(closeSegmentPairs(strands.points, 2, 5, 0.02f), 1u);
  EXPECT_NEAR(meanRootSpacing(strands.points, 2, 5), glm::length(glm::vec3(0.25f, 0.01f, -0.25f)), 1e-6f);
}

TEST(HairInteraction, TheStyleDynamicsReachTheSimulator) {
  HairDynamicsParams dynamics;
  dynamics.volume = 0.4f;
  dynamics.friction = 0.1f;
  const HairSimParams params = characterHairParams(dynamics);
  EXPECT_EQ(params.interaction.volume, 0.4f);
  EXPECT_EQ(params.interaction.friction, 0.1f);
  EXPECT_FALSE(characterHairParams().interaction.enabled());
  // The kernel radius follows the guides: twice their root spacing or half a
  // segment, whichever is larger.
  Strands strands;
  strands.pointsPerStrand = 11;
  addStraightStrand(strands, {0, 0, 0}, {0, -1, 0}, 0.1f);
  addStraightStrand(strands, {0.003f, 0, 0}, {0, -1, 0}, 0.1f);
  HairSimulator sim(params);
  sim.setRest(strands);
  EXPECT_NEAR(sim.interactionRadius(), 0.006f, 1e-6f);
  EXPECT_EQ(HairSimulator(characterHairParams()).interactionRadius(), 0.0f);
}

// The radius may change while the interaction is off; turning it back on
// uses the new one.
TEST(HairInteraction, ARadiusSetWhileOffIsUsedWhenTurnedOn) {
  Strands strands;
  strands.pointsPerStrand = 11;
  addStraightStrand(strands, {0, 0, 0}, {0, -1, 0}, 0.1f);
  addStraightStrand(strands, {0.003f, 0, 0}, {0, -1, 0}, 0.1f);
  HairSimParams params;
  params.interaction.volume = 0.5f;
  HairSimulator sim(params);
  sim.setRest(strands);
  EXPECT_NEAR(sim.interactionRadius(), 0.006f, 1e-6f);
  params.interaction = {0.0f, 0.0f, 0.02f};
  sim.setParams(params);
  EXPECT_EQ(sim.interactionRadius(), 0.0f);  // off
  params.interaction.volume = 0.5f;
  sim.setParams(params);
  EXPECT_EQ(sim.interactionRadius(), 0.02f);
}

TEST(HairInteraction, RootSpacingFromTheGridMatchesTheNearestOfAll) {
  Strands strands;
  strands.pointsPerStrand = 2;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  while (strands.strandCount() < 3000) {
    const glm::vec3 d(uniform(rng), uniform(rng), uniform(rng));
    if (glm::length(d) < 0.1f || glm::length(d) > 1.0f || d.y < 0.0f) continue;
    addStraightStrand(strands, 0.1f * glm::normalize(d), glm::normalize(d), 0.01f);
  }
  addStraightStrand(strands, {0.5f, 0.5f, 0.5f}, {0, 1, 0}, 0.01f);  // a lone root far from the rest
  const size_t count = strands.strandCount();
  double sum = 0.0;
  for (size_t s = 0; s < count; ++s) {
    float nearest = INFINITY;
    for (size_t o = 0; o < count; ++o)
      if (o != s)
        nearest = std::min(nearest, glm::length(pointOf(strands.points, 2 * o) - pointOf(strands.points, 2 * s)));
    sum += nearest;
  }
  EXPECT_NEAR(meanRootSpacing(strands.points, count, 2), float(sum / double(count)), 1e-6f);
}

}  // namespace
}  // namespace mq
