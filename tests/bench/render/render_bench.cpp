// Render-side costs per frame: copying a posed character into the VTK
// arrays, and whole offscreen frames (software Mesa under Xvfb, so these are
// worst-case numbers; a GPU is far faster at the drawing itself).
#include <benchmark/benchmark.h>

#include <cstdlib>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/io/character_import.h"
#include "core/util/thread_pool.h"
#include "render/offscreen.h"
#include "render/scene_view.h"

namespace {

const mq::Character& mannequin() {
  static const mq::Character character = mq::makeDefaultMannequin();
  return character;
}

void BM_UpdatePose(benchmark::State& state) {
  const mq::Character& character = mannequin();
  mq::render::SceneView view;
  view.setCharacter(character);
  mq::PosedCharacter posed;
  posed.evaluate(character, character.findClip("walk"), 0.3f, nullptr, &mq::ThreadPool::shared());
  for (auto _ : state) view.updatePose(posed);
  state.counters["vertices"] = double(character.vertexCount());
}
BENCHMARK(BM_UpdatePose)->Unit(benchmark::kMicrosecond);

// arg 0: plain; 1: with ambient occlusion; 2: the skin look (no occlusion).
// Each frame poses, syncs and draws.
void BM_OffscreenFrame(benchmark::State& state) {
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
  const mq::Character& character = mannequin();
  const int clip = character.findClip("walk");
  mq::render::SceneView view;
  view.setCharacter(character);
  view.setAmbientOcclusion(state.range(0) == 1);
  if (state.range(0) == 2) view.setLookMode(mq::render::LookMode::Skin);
  view.frameAll(4.0 / 3.0);
  mq::render::OffscreenRenderer renderer(view, 640, 480);
  mq::PosedCharacter posed;
  float t = 0.0f;
  for (auto _ : state) {
    posed.evaluate(character, clip, t, nullptr, &mq::ThreadPool::shared());
    view.updatePose(posed);
    benchmark::DoNotOptimize(renderer.capture());
    t += 1.0f / 30.0f;
  }
}
BENCHMARK(BM_OffscreenFrame)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// Pose sync with the skin look: adds the per-vertex compression (wrinkles).
void BM_UpdatePoseSkin(benchmark::State& state) {
  const mq::Character& character = mannequin();
  mq::render::SceneView view;
  view.setCharacter(character);
  view.setLookMode(mq::render::LookMode::Skin);
  mq::PosedCharacter posed;
  posed.evaluate(character, character.findClip("walk"), 0.3f, nullptr, &mq::ThreadPool::shared());
  for (auto _ : state) view.updatePose(posed);
}
BENCHMARK(BM_UpdatePoseSkin)->Unit(benchmark::kMicrosecond);

// An imported character with its own texture on the physically based path
// (image-based lighting), walking: what the editor draws per frame for it.
// arg 0: its material (auto look); 1: the plain look, for comparison.
void BM_OffscreenFrameTextured(benchmark::State& state) {
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
  const mq::Character character =
      mq::importCharacter(std::string(MANNEQUIN_SHARED_DIR) + "/assets/characters/CesiumMan/glTF-Binary/CesiumMan.glb");
  mq::render::SceneView view;
  view.setCharacter(character);
  view.setLookMode(state.range(0) == 0 ? mq::render::LookMode::Auto : mq::render::LookMode::Plain);
  view.frameAll(4.0 / 3.0);
  mq::render::OffscreenRenderer renderer(view, 640, 480);
  mq::PosedCharacter posed;
  renderer.capture();  // the environment's one-off precomputation stays out of the frames
  float t = 0.0f;
  for (auto _ : state) {
    posed.evaluate(character, 0, t, nullptr, &mq::ThreadPool::shared());
    view.updatePose(posed);
    benchmark::DoNotOptimize(renderer.capture());
    t += 1.0f / 30.0f;
  }
}
BENCHMARK(BM_OffscreenFrameTextured)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
