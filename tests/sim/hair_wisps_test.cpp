// Adaptive wisps: calm hair merges into few simulated guides, a shaken head
// splits them again, and on the walk the hair looks as when every guide is
// simulated (mean tip distance under 1 cm) with fewer guides simulated.

#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/hair/character_groom.h"
#include "sim/hair/child_follow.h"
#include "sim/hair/hair_bake.h"
#include "sim/hair/hair_simulator.h"

namespace mq {
namespace {

constexpr float kDt = 1.0f / 60.0f;

glm::vec3 pointAt(const std::vector<float>& points, size_t k) {
  return {points[3 * k], points[3 * k + 1], points[3 * k + 2]};
}

// The default mannequin's long_straight guides (no children) and its rig.
struct MannequinGuides {
  Character mannequin = makeDefaultMannequin();
  std::unique_ptr<HairGroom> groom;
  HairRig rig;
  Strands guides;
  MannequinGuides() {
    groom = makeCharacterGroom(mannequin, ScalpRegion{});
    HairStyle style = builtinHairStyle("long_straight");
    style.guideCount = 600;
    style.pointsPerStrand = 24;
    groom->grow(style, 600);
    rig = HairRig::fromProxy(mannequin, groom->proxy());
    guides = leadingStrands(groom->strands(), groom->guideCount());
  }
};

HairSimParams adaptive() {
  HairSimParams params = characterHairParams();
  params.adaptiveWisps = true;
  return params;
}

// Steps a simulator on the mannequin at `clip` (-1: the rest pose) from time 0.
struct HairRun {
  const MannequinGuides& hair;
  HairSimulator sim;
  PosedCharacter posed;
  int clip;
  HairRun(const MannequinGuides& h, const HairSimParams& params, int clipIndex)
      : hair(h), sim(params), clip(clipIndex) {
    sim.setRest(h.guides);
  }
  void step(float time) {
    posed.evaluate(hair.mannequin, clip, time, nullptr, nullptr);
    const PosedHairColliders body = hair.rig.body.posed(posed.worldFromBone(), sim.params().collisionMargin);
    sim.step(kDt, hair.rig.posedFromRest(posed.worldFromBone()), &body);
  }
};

TEST(HairWisps, CalmHairMergesAndAShakenHeadSplitsIt) {
  const MannequinGuides hair;
  HairRun run(hair, adaptive(), -1);
  for (int f = 0; f < 180; ++f) run.step(0.0f);
  const size_t calm = run.sim.simulatedStrands();
  EXPECT_LT(calm, hair.guides.strandCount() / 2) << "still hair should be simulated by few wisps";
  EXPECT_GT(calm, 0u);

  // Shake the head: turn the whole character back and forth fast.
  HairSimulator& sim = run.sim;
  size_t shaken = 0;
  for (int f = 0; f < 30; ++f) {
    const float angle = 0.6f * std::sin(float(f) * kDt * 2.0f * float(M_PI) * 2.0f);
    run.posed.evaluate(hair.mannequin, -1, 0.0f, nullptr, nullptr);
    std::vector<glm::mat4> worldFromBone = run.posed.worldFromBone();
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), angle, glm::vec3(0.0f, 1.0f, 0.0f));
    for (glm::mat4& m : worldFromBone) m = turn * m;
    const PosedHairColliders body = hair.rig.body.posed(worldFromBone, sim.params().collisionMargin);
    sim.step(kDt, hair.rig.posedFromRest(worldFromBone), &body);
    shaken = std::max(shaken, sim.simulatedStrands());
  }
  EXPECT_GT(shaken, calm + calm / 2) << "swinging hair should split its wisps";
}

TEST(HairWisps, WalkLooksAsWithEveryGuideSimulatedWithFewerGuides) {
  const MannequinGuides hair;
  const int walk = hair.mannequin.findClip("walk");
  ASSERT_GE(walk, 0);
  HairRun full(hair, characterHairParams(), walk), wisps(hair, adaptive(), walk);
  const size_t guides = hair.guides.strandCount();
  const int n = hair.guides.pointsPerStrand;
  double tipDistanceSum = 0.0, simulatedSum = 0.0;
  float worstFrameMean = 0.0f, worstLengthError = 0.0f;
  int frames = 0;
  for (int f = 0; f < 180; ++f) {
    const float time = float(f) * kDt;
    full.step(time);
    wisps.step(time);
    if (f < 30) continue;  // both settle first
    double frameSum = 0.0;
    for (size_t g = 0; g < guides; ++g) {
      const size_t tip = g * n + n - 1;
      frameSum += glm::distance(pointAt(full.sim.positions(), tip), pointAt(wisps.sim.positions(), tip));
    }
    worstFrameMean = std::max(worstFrameMean, float(frameSum / double(guides)));
    tipDistanceSum += frameSum / double(guides);
    simulatedSum += double(wisps.sim.simulatedStrands());
    ++frames;
    // No guide, simulated or following, inside the body.
    const PosedHairColliders exact = hair.rig.body.posed(wisps.posed.worldFromBone(), 0.0f);
    for (size_t k = 0; k < guides * n; ++k) {
      if (k % n == 0) continue;  // roots ride the scalp
      ASSERT_FALSE(exact.contains(pointAt(wisps.sim.positions(), k), 1e-4f)) << "frame " << f;
      // Followers keep their segments' lengths as simulated guides do.
      const float rest = glm::distance(pointAt(hair.guides.points, k), pointAt(hair.guides.points, k - 1));
      const float now = glm::distance(pointAt(wisps.sim.positions(), k), pointAt(wisps.sim.positions(), k - 1));
      worstLengthError = std::max(worstLengthError, std::abs(now - rest) / rest);
    }
  }
  const double meanTipDistance = tipDistanceSum / frames, meanSimulated = simulatedSum / frames;
  RecordProperty("mean_tip_distance_mm", int(1000.0 * meanTipDistance));
  RecordProperty("mean_simulated_guides", int(meanSimulated));
  EXPECT_LT(meanTipDistance, 0.01) << "worst frame " << worstFrameMean;
  EXPECT_LT(meanSimulated, 0.8 * double(guides));
  EXPECT_LT(worstLengthError, 0.02f);
}

}  // namespace
}  // namespace mq
