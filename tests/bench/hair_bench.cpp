// Hair grooming on the default mannequin (real time: the work runs on the
// shared thread pool).
//   BM_HairGroomFull/<strands>: everything from the scalp and the proxy:
//     panel matrix LU, Poisson-disk roots, guide neighbours, 2000 guides
//     traced through the flow, the children interpolated; 32 points.
//   BM_HairRegrowGuides: a source moves, the flow is re-solved and the 2000
//     guides retraced (what the editor does while a handle is dragged).
//   BM_HairGrowChildren: the 98,000 children re-interpolated from the guides.
//   BM_HairPoissonRoots/<count>: root sampling alone.
// The counter cpu_ms is the process CPU time per iteration over all threads:
// on a machine loaded by other work the real time overstates what the code
// needs, and cpu_ms / threads is what an idle machine would take.
#include <benchmark/benchmark.h>

#include <ctime>

#include "core/character/default_mannequin.h"
#include "core/hair/character_groom.h"
#include "core/hair/root_sampling.h"

namespace {

struct MannequinHair {
  std::unique_ptr<mq::HairGroom> groom;
  mq::HairStyle style;
  MannequinHair() {
    groom = mq::makeCharacterGroom(mq::makeDefaultMannequin(), mq::ScalpRegion{});
    style = mq::builtinHairStyle("long_straight");
    style.guideCount = 2000;
    style.pointsPerStrand = 32;
  }
};

// Process CPU time (all threads) between construction and report().
class CpuClock {
 public:
  CpuClock() : start_(std::clock()) {}
  void report(benchmark::State& state) const {
    state.counters["cpu_ms"] = 1e3 * double(std::clock() - start_) / CLOCKS_PER_SEC / double(state.iterations());
  }

 private:
  std::clock_t start_;
};

MannequinHair& mannequinHair() {
  static MannequinHair hair;
  return hair;
}

void BM_HairGroomFull(benchmark::State& state) {
  MannequinHair& hair = mannequinHair();
  const size_t strands = size_t(state.range(0));
  const CpuClock cpu;
  for (auto _ : state) {
    mq::HairGroom groom(hair.groom->scalp(), hair.groom->proxy());
    groom.grow(hair.style, strands);
    benchmark::DoNotOptimize(groom.strands().points.data());
    state.counters["guides_ms"] = groom.timings().guides * 1e3;
    state.counters["children_ms"] = groom.timings().children * 1e3;
    state.counters["roots_ms"] = groom.timings().roots * 1e3;
  }
  cpu.report(state);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(strands));
}
BENCHMARK(BM_HairGroomFull)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_HairRegrowGuides(benchmark::State& state) {
  MannequinHair& hair = mannequinHair();
  hair.groom->grow(hair.style, 100000);
  mq::HairStyle moving = hair.style;
  float offset = 0.0f;
  const CpuClock cpu;
  for (auto _ : state) {
    offset = offset > 0.02f ? -0.02f : offset + 0.004f;
    moving.primitives.sources[0].position = hair.style.primitives.sources[0].position + glm::vec3(offset, 0.0f, 0.0f);
    hair.groom->regrowGuides(moving);
    benchmark::DoNotOptimize(hair.groom->strands().points.data());
  }
  cpu.report(state);
  state.counters["guides"] = double(hair.groom->guideCount());
}
BENCHMARK(BM_HairRegrowGuides)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_HairGrowChildren(benchmark::State& state) {
  MannequinHair& hair = mannequinHair();
  hair.groom->grow(hair.style, 100000);
  const CpuClock cpu;
  for (auto _ : state) {
    hair.groom->growChildren(hair.style);
    benchmark::DoNotOptimize(hair.groom->strands().points.data());
  }
  cpu.report(state);
  state.counters["children"] = double(hair.groom->childRoots().size());
}
BENCHMARK(BM_HairGrowChildren)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_HairPoissonRoots(benchmark::State& state) {
  MannequinHair& hair = mannequinHair();
  const CpuClock cpu;
  for (auto _ : state) {
    const mq::HairRoots roots = mq::sampleRoots(hair.groom->scalp(), size_t(state.range(0)), 1);
    benchmark::DoNotOptimize(roots.positions.data());
  }
  cpu.report(state);
}
BENCHMARK(BM_HairPoissonRoots)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
