// A hair frame with each shading model: the default mannequin's default
// groom (20,000 strands x 32 points) drawn offscreen at 640 x 480 with
// Kajiya-Kay (arg 0) or the physical fibre (arg 1, brown). The self-shadow
// is computed once before timing; each iteration draws and reads back a
// frame (software Mesa under Xvfb: the fragment shader's cost shows fully).
#include <benchmark/benchmark.h>

#include <cstdlib>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/hair/character_groom.h"
#include "render/hair_actor.h"
#include "render/offscreen.h"
#include "render/scene_view.h"

namespace {

void BM_HairFrame(benchmark::State& state) {
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
  static const mq::Character character = mq::makeDefaultMannequin();
  static const mq::Strands strands = [] {
    auto groom = mq::makeCharacterGroom(character, mq::ScalpRegion{});
    groom->grow(mq::builtinHairStyle("long_straight"), 20000);
    return groom->strands();
  }();
  mq::render::SceneView view;
  view.setCharacter(character);
  mq::PosedCharacter posed;
  posed.evaluate(character, -1, 0.0f, nullptr, nullptr);
  view.updatePose(posed);
  mq::render::HairActor hair;
  mq::HairShadingParams fibre;
  if (state.range(0) == 1) fibre.model = mq::HairShadingModel::Physical;
  hair.setFibre(fibre);
  hair.setStrands(strands);
  view.add(hair);
  view.frameAll(4.0 / 3.0);
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (size_t k = 0; k + 2 < strands.points.size(); k += 3) {
    const glm::vec3 p(strands.points[k], strands.points[k + 1], strands.points[k + 2]);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::vec3 centre = 0.5f * (lo + hi);
  view.setCamera(centre + glm::vec3(0.45f, 0.15f, 0.75f), centre);
  mq::render::OffscreenRenderer renderer(view, 640, 480);
  benchmark::DoNotOptimize(renderer.capture());  // shaders compiled, shadow computed
  for (auto _ : state) benchmark::DoNotOptimize(renderer.capture());
  state.SetLabel(state.range(0) == 1 ? "physical" : "kajiya-kay");
}
BENCHMARK(BM_HairFrame)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace
