// Cloth benchmarks: the scenes of tests/bench/scenes, which match Blender's
// cloth_drape.py / cloth_pinned.py in ../shared/peers/blender (1 m square,
// N x N vertices, Cotton preset 0.3 kg per vertex, 24 fps, 120 frames; see the
// "_comment" of each scene for how the stiffnesses were matched). One
// iteration = the whole 120-frame run; counters give wall ms per frame
// (ms_per_frame), process CPU ms per frame over all threads (cpu_ms_per_frame:
// what a loaded machine inflates least), the largest stretch over all frames
// and the penetrating vertices at the last frame. BM_ClothDrapeSelf64 is
// drape_64 with self-collisions on. BM_ClothSheetOnMannequin/<N>: an N x N
// sheet (N = 100: 10,000 vertices, the size of the T-shirt) dropped onto the
// default mannequin's triangle mesh with self-collisions, 24 frames (1 s):
// the body collider and self-collision costs a garment has.
// BM_ClothImplicitSolve/<preconditioner>: pinned_64 at 100 x 100 vertices
// (the T-shirt's size), no elongation limit, the CG always at its cap of 100
// iterations: wall and CPU ms per CG iteration (what the solver costs per
// iteration; the step's force evaluation is a few percent of it).
//
//   mannequin-bench --benchmark_filter=Cloth
//
// Blender 3.4 on this machine (README there): drape 244 ms/frame at N=64,
// 1085 at N=128; pinned 127 and 578.
#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "sim/cloth/cloth_scene_io.h"
#include "sim/cloth/cloth_simulator.h"

namespace {

using namespace mq::cloth;

ClothSceneSpec loadScene(const std::string& name) {
  const std::string path = std::string(MANNEQUIN_SOURCE_DIR) + "/tests/bench/scenes/" + name + ".json";
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json doc = nlohmann::json::parse(text.str());
  return parseClothScene(doc["cloth"], doc.value("colliders", nlohmann::json()), path);
}

void runScene(benchmark::State& state, const std::string& name, int frames, bool selfCollisions = false) {
  ClothSceneSpec spec = loadScene(name);
  if (selfCollisions) spec.settings.selfCollisions = true;
  float maxStretch = 1.0f;
  int penetrating = 0;
  double stepSeconds = 0.0, cpuSeconds = 0.0;
  long long framesRun = 0;
  for (auto _ : state) {
    state.PauseTiming();
    std::vector<uint32_t> pinned;
    ClothSimulator sim(buildClothMesh(spec, pinned), spec.fabric, spec.settings);
    for (const auto& c : spec.colliders) sim.addCollider(c);
    for (uint32_t v : pinned) sim.pinVertex(v);
    state.ResumeTiming();
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    for (int f = 0; f < frames; ++f) {
      sim.step(1.0f / spec.fps);
      maxStretch = std::max(maxStretch, sim.stats().maxStretch);
    }
    stepSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    cpuSeconds += double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    framesRun += frames;
    penetrating = sim.penetratingVertices();
  }
  state.counters["ms_per_frame"] = 1000.0 * stepSeconds / double(std::max(1LL, framesRun));     // wall time
  state.counters["cpu_ms_per_frame"] = 1000.0 * cpuSeconds / double(std::max(1LL, framesRun));  // all threads
  state.counters["max_stretch"] = maxStretch;
  state.counters["penetrating"] = penetrating;
}

void BM_ClothSheetOnMannequin(benchmark::State& state) {
  const mq::Character mannequin = mq::makeDefaultMannequin();
  mq::PosedCharacter posed;
  posed.evaluate(mannequin, -1, 0.0f, nullptr, nullptr);  // rest pose
  const std::vector<float> body = concatenatedPositions(posed.meshes());
  const std::vector<uint32_t> triangles = concatenatedTriangles(mannequin);
  ClothSceneSpec spec = loadScene("drape_64");
  spec.sheet.columns = spec.sheet.rows = int(state.range(0));
  spec.sheet.center = glm::vec3(0.0f, 1.85f, 0.0f);
  spec.massPerVertex = 0.0f;  // cotton's mass per area
  spec.settings.selfCollisions = true;
  constexpr int kFrames = 24;
  float maxStretch = 1.0f;
  int penetrating = 0;
  double stepSeconds = 0.0, cpuSeconds = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    std::vector<uint32_t> pinned;
    ClothSimulator sim(buildClothMesh(spec, pinned), spec.fabric, spec.settings);
    sim.setBody(body, triangles);
    state.ResumeTiming();
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    for (int f = 0; f < kFrames; ++f) {
      sim.step(1.0f / spec.fps);
      maxStretch = std::max(maxStretch, sim.stats().maxStretch);
    }
    stepSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    cpuSeconds += double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    penetrating = sim.penetratingVertices();
  }
  const double frames = double(kFrames) * double(state.iterations());
  state.counters["ms_per_frame"] = 1000.0 * stepSeconds / frames;
  state.counters["cpu_ms_per_frame"] = 1000.0 * cpuSeconds / frames;
  state.counters["max_stretch"] = maxStretch;
  state.counters["penetrating"] = penetrating;
}
BENCHMARK(BM_ClothSheetOnMannequin)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

void BM_ClothImplicitSolve(benchmark::State& state) {
  ClothSceneSpec spec = loadScene("pinned_64");
  spec.sheet.columns = spec.sheet.rows = 100;
  spec.settings.stretchLimit = StretchLimitMode::Off;
  spec.settings.cgMaxIterations = 100;
  spec.settings.cgTolerance = 1e-9f;
  spec.settings.cgPreconditioner = state.range(0) ? CgPreconditioner::TwoLevel : CgPreconditioner::BlockJacobi;
  constexpr int kFrames = 12;
  double stepSeconds = 0.0, cpuSeconds = 0.0;
  long long iterations = 0;
  for (auto _ : state) {
    state.PauseTiming();
    std::vector<uint32_t> pinned;
    ClothSimulator sim(buildClothMesh(spec, pinned), spec.fabric, spec.settings);
    for (uint32_t v : pinned) sim.pinVertex(v);
    state.ResumeTiming();
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    for (int f = 0; f < kFrames; ++f) {
      sim.step(1.0f / spec.fps);
      iterations += sim.stats().solverIterations;
    }
    stepSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    cpuSeconds += double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
  }
  state.counters["ms_per_iteration"] = 1000.0 * stepSeconds / double(std::max(1LL, iterations));
  state.counters["cpu_ms_per_iteration"] = 1000.0 * cpuSeconds / double(std::max(1LL, iterations));
  state.counters["iterations_per_frame"] = double(iterations) / (double(kFrames) * double(state.iterations()));
}
BENCHMARK(BM_ClothImplicitSolve)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->UseRealTime();

void BM_ClothDrape64(benchmark::State& s) { runScene(s, "drape_64", 120); }
void BM_ClothDrape128(benchmark::State& s) { runScene(s, "drape_128", 120); }
void BM_ClothPinned64(benchmark::State& s) { runScene(s, "pinned_64", 120); }
void BM_ClothPinned128(benchmark::State& s) { runScene(s, "pinned_128", 120); }
void BM_ClothDrapeSelf64(benchmark::State& s) { runScene(s, "drape_64", 120, true); }

BENCHMARK(BM_ClothDrape64)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_ClothDrape128)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_ClothPinned64)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_ClothPinned128)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_ClothDrapeSelf64)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

}  // namespace
