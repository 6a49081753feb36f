// Hair grooming on the default mannequin (real time: the work runs on the
// shared thread pool).
//   BM_HairGroomFull/<strands>: everything from the scalp and the proxy:
//     panel matrix LU, Poisson-disk roots, guide neighbours, 2000 guides
//     traced through the flow, the children interpolated; 32 points.
//   BM_HairRegrowGuides: a source moves, the flow is re-solved and the 2000
//     guides retraced (what the editor does while a handle is dragged).
//   BM_HairGrowChildren: the 98,000 children re-interpolated from the guides.
//   BM_HairPoissonRoots/<count>: root sampling alone.
//   BM_HairStrokeReplay/<strokes>: that many brush strokes (comb, puff,
//     smooth, clump, frizz, mirrored, 40 dabs each over the top and back of
//     the head) replayed on the 2000 traced guides, as a regrow after a
//     flow edit does; items are dabs.
// The counter cpu_ms is the process CPU time per iteration over all threads:
// on a machine loaded by other work the real time overstates what the code
// needs, and cpu_ms / threads is what an idle machine would take.
#include <benchmark/benchmark.h>

#include <ctime>

#include "core/character/default_mannequin.h"
#include "core/hair/character_groom.h"
#include "core/hair/groom_stroke.h"
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

// Strokes from the crown down the back and sides of the head, each a few
// centimetres from the last, in head space.
std::vector<mq::GroomStroke> strokesOverTheHead(int count) {
  const mq::GroomBrush brushes[] = {mq::GroomBrush::Comb, mq::GroomBrush::Puff, mq::GroomBrush::Smooth,
                                    mq::GroomBrush::Clump, mq::GroomBrush::Frizz};
  std::vector<mq::GroomStroke> strokes;
  for (int i = 0; i < count; ++i) {
    mq::GroomStroke stroke;
    stroke.brush = brushes[i % 5];
    stroke.radius = 0.03f;
    stroke.strength = 0.3f;
    stroke.mirror = true;
    const float side = 0.02f + 0.06f * float(i % 7) / 6.0f;
    const float from = float(i % 11) / 10.0f;
    for (int d = 0; d < 40; ++d) {
      const float a = 0.3f + 2.2f * (from * 0.3f + float(d) / 40.0f);  // over the crown, down the back
      stroke.dabs.push_back(
          {glm::vec3(side, 0.11f * std::cos(a), -0.11f * std::sin(a)), glm::vec3(0.0f, -0.005f, -0.002f)});
    }
    strokes.push_back(std::move(stroke));
  }
  return strokes;
}

void BM_HairStrokeReplay(benchmark::State& state) {
  MannequinHair& hair = mannequinHair();
  hair.groom->grow(hair.style, 2000);
  const std::vector<mq::GroomStroke> strokes = strokesOverTheHead(int(state.range(0)));
  const mq::Strands traced = hair.groom->strands();
  const glm::vec3 headCenter = hair.groom->proxy().headCenter();
  const CpuClock cpu;
  for (auto _ : state) {
    mq::Strands strands = traced;
    mq::applyGroomStrokes(strokes, 0, strokes.size(), headCenter, hair.groom->proxy(), 0.002f, 1, strands,
                          hair.groom->guideCount());
    benchmark::DoNotOptimize(strands.points.data());
  }
  cpu.report(state);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(strokes.size()) * 80);
}
BENCHMARK(BM_HairStrokeReplay)->Arg(200)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
