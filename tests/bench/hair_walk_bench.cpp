// BM_HairWalk100k: the default mannequin walking with the long_straight
// style grown to 100,000 strands (2,000 simulated guides, 98,000 children,
// 32 points each). A frame is what mannequin-cli simulate times as
// hair_ms_per_frame: the guides' 1/60 s step against the body proxies posed
// on the skeleton, then every child following its guide and kept out of the
// body. The character's poses are computed beforehand (skinning is not hair
// work). Real time on the shared thread pool; cpu_ms sums the threads.
// BM_HairWalk100k/<adaptive wisps>/<hair against hair>: 1 turns each on
// (volume 0.5, friction 0.2 for the interaction); simulated_guides is the
// mean over the timed frames.
#include <benchmark/benchmark.h>

#include <ctime>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/hair/character_groom.h"
#include "core/util/thread_pool.h"
#include "sim/hair/child_follow.h"
#include "sim/hair/hair_bake.h"

namespace {

constexpr float kFps = 60.0f;

struct WalkingHair {
  mq::Character mannequin = mq::makeDefaultMannequin();
  std::unique_ptr<mq::HairGroom> groom;
  mq::HairRig rig;
  std::vector<std::vector<glm::mat4>> walk;  // worldFromBone at each frame

  WalkingHair() {
    groom = mq::makeCharacterGroom(mannequin, mq::ScalpRegion{});
    mq::HairStyle style = mq::builtinHairStyle("long_straight");
    style.guideCount = 2000;
    style.pointsPerStrand = 32;
    groom->grow(style, 100000);
    rig = mq::HairRig::fromProxy(mannequin, groom->proxy());
    const int clip = mannequin.findClip("walk");
    const float duration = clip >= 0 ? mannequin.clips[size_t(clip)].duration() : 1.0f;
    mq::PosedCharacter posed;
    for (int f = 0; f < int(duration * kFps); ++f) {
      posed.evaluate(mannequin, clip, float(f) / kFps, nullptr, &mq::ThreadPool::shared());
      walk.push_back(posed.worldFromBone());
    }
  }
};

void BM_HairWalk100k(benchmark::State& state) {
  WalkingHair hair;
  const mq::Strands& all = hair.groom->strands();
  mq::HairSimParams params = mq::characterHairParams();
  params.adaptiveWisps = state.range(0) != 0;
  if (state.range(1)) params.interaction = {0.5f, 0.2f, 0.0f};
  mq::HairSimulator sim(params);
  sim.setRest(mq::leadingStrands(all, hair.groom->guideCount()));
  std::vector<float> positions;
  size_t frame = 0;
  auto step = [&] {
    const std::vector<glm::mat4>& worldFromBone = hair.walk[frame++ % hair.walk.size()];
    const mq::PosedHairColliders body = hair.rig.body.posed(worldFromBone, sim.params().collisionMargin);
    sim.step(1.0f / kFps, hair.rig.posedFromRest(worldFromBone), &body);
    mq::poseGroomedStrands(all, sim, positions, &body);
  };
  for (int f = 0; f < 30; ++f) step();  // settle onto the body
  const std::clock_t start = std::clock();
  double simulated = 0.0;
  for (auto _ : state) {
    step();
    simulated += double(sim.simulatedStrands());
    benchmark::DoNotOptimize(positions.data());
  }
  state.counters["simulated_guides"] = simulated / double(state.iterations());
  state.counters["cpu_ms"] = 1e3 * double(std::clock() - start) / CLOCKS_PER_SEC / double(state.iterations());
  state.counters["strands"] = double(all.strandCount());
  state.counters["guides"] = double(hair.groom->guideCount());
}
BENCHMARK(BM_HairWalk100k)
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
