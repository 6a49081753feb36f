// Body vertices against the cloth triangles of the 10k-vertex T-shirt
// (tests/bench/scenes/tshirt_walk_10k.json): one BodyFeatureContact::resolve
// on a real state, the shirt's panels placed around the default mannequin
// and sewn for 12 frames at the rest pose (set up once, a few seconds, not
// timed), then the body
//  - Arg(0): at the rest pose (the shirt resting on it), or
//  - Arg(1): 0.3 s into the walk, reached over one frame (the arms swung
//    through the sleeves: pierced triangles, moving body vertices).
// Each iteration resolves a fresh copy of the same state (the tree over the
// cloth refitted, as every call of a simulation).
//
//   mannequin-bench --benchmark_filter=BodyFeature
#include <benchmark/benchmark.h>

#include <memory>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "sim/cloth/collision/body_feature_contact.h"
#include "sim/garment/garment_scene.h"
#include "tests/bench/tshirt_scene.h"

namespace {

using namespace mq::cloth;

struct SewnShirt {
  ClothState state;
  std::vector<uint32_t> triangles, bodyTriangles;
  std::vector<float> restBody, walkingBody;
  float thickness = 0.0f;
};

const SewnShirt& sewnShirt() {
  static const SewnShirt shirt = [] {
    SewnShirt out;
    const mq::bench::TShirtScene scene = mq::bench::loadTShirtScene();
    const std::vector<mq::Garment>& garments = scene.garments;
    const ClothSceneSpec& spec = scene.spec;
    const mq::Character mannequin = mq::makeDefaultMannequin();
    mq::PosedCharacter posed;
    posed.evaluate(mannequin, -1, 0.0f, nullptr, nullptr);
    out.restBody = mq::concatenatedPositions(posed.meshes());
    posed.evaluate(mannequin, mannequin.findClip("walk"), 0.3f, nullptr, nullptr);
    out.walkingBody = mq::concatenatedPositions(posed.meshes());
    out.bodyTriangles = mq::concatenatedTriangles(mannequin);
    auto sim = makeGarmentSimulation(garments.at(0), spec, out.restBody, out.bodyTriangles, "garments[0]");
    for (int f = 0; f < 12; ++f) sim->step(1.0f / spec.fps);
    out.state = sim->simulator().state();
    out.triangles = sim->simulator().triangles();
    out.thickness = sim->simulator().settings().collisionThickness;
    return out;
  }();
  return shirt;
}

void BM_TShirtBodyFeatureContact(benchmark::State& state) {
  const SewnShirt& shirt = sewnShirt();
  BodyCollider body;
  body.setMesh(shirt.restBody, shirt.bodyTriangles, 0.02f);
  if (state.range(0) == 1) {
    body.setTarget(shirt.walkingBody, 1.0f / 30.0f);
    body.moveTo(1.0f);
  }
  BodyFeatureContact features(shirt.triangles, shirt.state.x);
  std::vector<uint8_t> touched(shirt.state.size(), 0);
  int contacts = 0;
  for (auto _ : state) {
    state.PauseTiming();
    ClothState s = shirt.state;
    state.ResumeTiming();
    contacts = features.resolve(s, body, shirt.thickness, touched, 1, 2);
  }
  state.counters["contacts"] = contacts;
}
// CPU time of all the threads (the search runs on the pool).
BENCHMARK(BM_TShirtBodyFeatureContact)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

}  // namespace
