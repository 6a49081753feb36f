// The dynamics used for hair on a character (characterHairParams): a long
// groom settling on the default mannequin keeps its shape better than with
// the plain defaults, and stays out of the body.
#include <gtest/gtest.h>

#include <cmath>

#include "core/character/default_mannequin.h"
#include "core/hair/character_groom.h"
#include "sim/hair/child_follow.h"
#include "sim/hair/hair_bake.h"

namespace mq {
namespace {

// Mean distance of the guides' points from their groomed rest after one
// second of settling at the rest pose; points inside the body counted.
struct Settled {
  double meanDrift = 0.0;
  size_t inside = 0;
};

Settled settle(const Character& character, const HairGroom& groom, const HairSimParams& params) {
  const Strands guides = leadingStrands(groom.strands(), groom.guideCount());
  const HairRig rig = HairRig::fromProxy(character, groom.proxy());
  HairSimulator sim(params);
  sim.setRest(guides);
  const std::vector<glm::mat4> worldFromBone = character.skeleton.worldTransforms(character.skeleton.restPose());
  const PosedHairColliders body = rig.body.posed(worldFromBone, params.collisionMargin);
  for (int step = 0; step < 60; ++step) sim.step(1.0f / 60.0f, rig.posedFromRest(worldFromBone), &body);
  Settled out;
  const PosedHairColliders bare = rig.body.posed(worldFromBone);
  const std::vector<float>& now = sim.positions();
  for (size_t k = 0; k < now.size(); k += 3) {
    const glm::vec3 p(now[k], now[k + 1], now[k + 2]), r(guides.points[k], guides.points[k + 1], guides.points[k + 2]);
    out.meanDrift += glm::length(p - r) / double(now.size() / 3);
    if ((k / 3) % size_t(sim.pointsPerStrand()) != 0) out.inside += bare.contains(p, 1e-4f);
  }
  return out;
}

TEST(HairCharacterParams, LongGroomKeepsItsShapeOnTheShoulders) {
  const Character character = makeDefaultMannequin();
  const std::unique_ptr<HairGroom> groom = makeCharacterGroom(character, ScalpRegion{});
  groom->grow(builtinHairStyle("long_straight"), 3000);
  const Settled styled = settle(character, *groom, characterHairParams());
  const Settled plain = settle(character, *groom, HairSimParams{});
  EXPECT_EQ(styled.inside, 0u);
  EXPECT_LT(styled.meanDrift, 0.6 * plain.meanDrift)
      << "styled " << styled.meanDrift << " m, plain " << plain.meanDrift;
  EXPECT_LT(styled.meanDrift, 0.02);  // within 2 cm of the groom on average
}

}  // namespace
}  // namespace mq
