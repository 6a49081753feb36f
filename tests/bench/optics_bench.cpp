// BM_PreintegratedLut/<preset>: the pre-integrated skin table (256 N.L x 128
// curvatures x RGB) built from a skin, kernels included, on the calling
// thread: 0 = skin1 (measured, dipole kernels by Abel projection),
// 1 = medium (tone model, Burley kernels). Target: under 100 ms.
// BM_McSlab: 20000 random-walk paths in Jensen's skin1 red channel
// (half-space, g 0.85, eta 1.3) on two threads.
#include <benchmark/benchmark.h>

#include <limits>

#include "core/optics/mc_slab.h"
#include "core/optics/preintegrated.h"
#include "core/optics/skin_tone.h"

namespace {

void BM_PreintegratedLut(benchmark::State& state) {
  const mq::optics::SkinOptics skin = mq::optics::skinPreset(state.range(0) == 0 ? "skin1" : "medium");
  for (auto _ : state) {
    const mq::optics::PreintegratedLut lut = mq::optics::buildPreintegratedLut(mq::optics::skinKernels(skin));
    benchmark::DoNotOptimize(lut.rgb.data());
  }
}
BENCHMARK(BM_PreintegratedLut)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_McSlab(benchmark::State& state) {
  const double g = 0.85;
  const std::vector<mq::optics::SlabLayer> halfSpace = {
      {0.032, 0.74 / (1.0 - g), g, std::numeric_limits<double>::infinity(), 1.3}};
  mq::optics::SlabSettings settings;
  settings.paths = 20000;
  for (auto _ : state) benchmark::DoNotOptimize(mq::optics::simulateSlab(halfSpace, settings).reflected);
}
BENCHMARK(BM_McSlab)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
