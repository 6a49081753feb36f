// Hair self-shadowing on the CPU: the exact per-column count against opacity
// shadow maps, on the default mannequin's default groom (100,000 strands x 32
// points), for one key light direction.
#include <benchmark/benchmark.h>

#include "core/character/default_mannequin.h"
#include "core/hair/character_groom.h"
#include "core/optics/hair_self_shadow.h"

namespace {

const mq::Strands& groomedStrands() {
  static const mq::Strands strands = [] {
    const mq::Character character = mq::makeDefaultMannequin();
    auto groom = mq::makeCharacterGroom(character, mq::ScalpRegion{});
    groom->grow(mq::builtinHairStyle("long_straight"), 100000);
    return groom->strands();
  }();
  return strands;
}

// arg 0: exact count; n > 0: n opacity maps.
void BM_HairSelfShadow(benchmark::State& state) {
  const mq::Strands& strands = groomedStrands();
  mq::optics::HairShadowSettings settings;
  if (state.range(0) > 0) {
    settings.method = mq::optics::HairShadowMethod::OpacityMaps;
    settings.opacityMapCount = int(state.range(0));
  }
  const glm::vec3 light = glm::normalize(glm::vec3(0.4f, 1.0f, 0.6f));
  for (auto _ : state) benchmark::DoNotOptimize(mq::optics::hairSelfShadow(strands, light, settings));
  state.counters["points"] = double(strands.points.size() / 3);
}
BENCHMARK(BM_HairSelfShadow)->Arg(0)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);

}  // namespace
