// The one dressing every path uses (sim/garment/dressing.h): each garment
// sews and drapes on its own, then all settle together; the same input gives
// the same cloth, bit for bit.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "garment_test_garments.h"
#include "sim/garment/dressing.h"
#include "sim/garment/garment_layers.h"
#include "sim/garment/garment_scene.h"

namespace mq::cloth {
namespace {

struct TwoGarments {
  ClothSceneSpec spec = parseClothScene(nlohmann::json::object(), nullptr, "scene.json", true);
  std::vector<std::unique_ptr<GarmentSimulation>> owned;
  std::vector<GarmentSimulation*> simulations;
  TwoGarments() {
    for (float y : {1.0f, 1.5f}) {
      owned.push_back(makeGarmentSimulation(test::twoSewnSquares(y), spec, {}, {}, "garments[0]"));
      simulations.push_back(owned.back().get());
    }
  }
  std::vector<DrapeSteps> dress() {
    return dressGarments(simulations, {0, 1}, {}, {}, 1.0f / spec.fps, [](size_t) { return true; });
  }
};

TEST(Dressing, EachGarmentSewsOnTheRestBodyThenIsCarriedToThePose) {
  TwoGarments two;
  const float dt = 1.0f / two.spec.fps;
  const DrapeSteps steps = drapeOnto(*two.simulations[0], {}, {}, dt);
  EXPECT_TRUE(two.simulations[0]->welded());
  EXPECT_GE(steps.sewing, int(DrapeSchedule::kMinSewingSeconds / dt));                // sews at least this long
  EXPECT_GE(steps.total - steps.sewing, int(DrapeSchedule::kBlendSeconds / dt) - 1);  // then moves
  EXPECT_LE(steps.total, DrapeSchedule{}.maxSteps(dt));
}

TEST(Dressing, TheSameSceneGivesTheSameClothBitForBit) {
  TwoGarments a, b;
  const std::vector<DrapeSteps> stepsA = a.dress(), stepsB = b.dress();
  for (size_t g = 0; g < 2; ++g) {
    EXPECT_EQ(stepsA[g].total, stepsB[g].total);
    EXPECT_EQ(a.simulations[g]->positions(), b.simulations[g]->positions());
  }
}

TEST(Dressing, IsDrapingEachThenSettlingTogether) {
  TwoGarments whole, parts;
  whole.dress();
  const float dt = 1.0f / parts.spec.fps;
  for (GarmentSimulation* sim : parts.simulations) drapeOnto(*sim, {}, {}, dt);
  wearInLayers(parts.simulations, {0, 1}, true);
  ASSERT_TRUE(settleTogether(parts.simulations, {0, 1}, {}, dt));
  for (size_t g = 0; g < 2; ++g) EXPECT_EQ(whole.simulations[g]->positions(), parts.simulations[g]->positions());
  // A cancelled settle stops at once.
  EXPECT_FALSE(settleTogether(parts.simulations, {0, 1}, {}, dt, [] { return true; }));
}

}  // namespace
}  // namespace mq::cloth
