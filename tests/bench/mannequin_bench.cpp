// The default mannequin is built at every start of the editor and the CLI:
// it must stay well under a second.
#include <benchmark/benchmark.h>

#include "core/character/default_mannequin.h"
#include "core/mesh/marching_cubes.h"

namespace {

void BM_MakeDefaultMannequin(benchmark::State& state) {
  size_t vertices = 0;
  for (auto _ : state) {
    mq::Character c = mq::makeDefaultMannequin();
    vertices = c.vertexCount();
    benchmark::DoNotOptimize(c);
  }
  state.counters["vertices"] = double(vertices);
}
BENCHMARK(BM_MakeDefaultMannequin)->Unit(benchmark::kMillisecond)->UseRealTime();

// Marching cubes alone on a sphere sampled on a 160^3 grid.
void BM_ExtractIsoSurfaceSphere(benchmark::State& state) {
  const int n = 160;
  mq::ScalarGrid grid;
  grid.dims = glm::ivec3(n);
  grid.cellSize = 1.0f / n;
  grid.origin = glm::vec3(-0.5f);
  grid.values.resize(size_t(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) grid.values[grid.index(i, j, k)] = glm::length(grid.point(i, j, k)) - 0.4f;
  for (auto _ : state) benchmark::DoNotOptimize(mq::extractIsoSurface(grid, 0.0f));
}
BENCHMARK(BM_ExtractIsoSurfaceSphere)->Unit(benchmark::kMillisecond);

}  // namespace
