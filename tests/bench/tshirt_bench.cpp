// The pieces of the 10k-vertex T-shirt step (tests/bench/scenes/tshirt_walk_10k.json)
// that dominate its cost, on a real state: the shirt's panels placed around
// the default mannequin (rest pose) and sewn for 12 frames (set up once, a
// few seconds, not timed).
//
//  - BM_TShirtSelfCollision: one SelfCollision::resolve (broad phase over the
//    step's motion, then up to 20 passes) from the state before the last
//    frame to the state after it.
//  - BM_TShirtSelfCollisionSwinging: the same step with the sleeves swung as
//    on the walk: each turned 3 degrees about its shoulder (up to ~1.5 cm at
//    the cuff, blended into the torso) and the whole shirt moved 6 mm
//    forward; the candidates are counters.
//  - BM_TShirtStretchPinch: the elongation limit where a patch of the shirt
//    is pulled 3 cm off the rest and its centre held heavy, as a body part
//    pinching the cloth does (the armpit of the walk): passes and the max
//    stretch after them are counters.
//
//   mannequin-bench --benchmark_filter=TShirt
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "sim/cloth/collision/self_collision.h"
#include "sim/cloth/constraints/stretch_limit.h"
#include "sim/garment/garment_scene.h"
#include "tests/bench/tshirt_scene.h"

namespace {

using namespace mq::cloth;

struct ShirtStates {
  ClothState before, after;  // the sewing solver's state before and after the last frame
  std::vector<uint32_t> triangles;
  ClothSettings settings;
  std::unique_ptr<mq::cloth::GarmentSimulation> sim;  // keeps the springs the limiter points at
};

const ShirtStates& shirtStates() {
  static const ShirtStates states = [] {
    ShirtStates out;
    const mq::bench::TShirtScene scene = mq::bench::loadTShirtScene();
    const std::vector<mq::Garment>& garments = scene.garments;
    const ClothSceneSpec& spec = scene.spec;
    const mq::Character mannequin = mq::makeDefaultMannequin();
    mq::PosedCharacter posed;
    posed.evaluate(mannequin, -1, 0.0f, nullptr, nullptr);  // rest pose
    const std::vector<float> body = mq::concatenatedPositions(posed.meshes());
    const std::vector<uint32_t> bodyTriangles = mq::concatenatedTriangles(mannequin);
    out.sim = makeGarmentSimulation(garments.at(0), spec, body, bodyTriangles, "garments[0]");
    const float dt = 1.0f / spec.fps;
    for (int f = 0; f < 11; ++f) out.sim->step(dt);
    out.before = out.sim->simulator().state();
    out.sim->step(dt);
    out.after = out.sim->simulator().state();
    out.triangles = out.sim->simulator().triangles();
    out.settings = out.sim->simulator().settings();
    return out;
  }();
  return states;
}

void BM_TShirtSelfCollision(benchmark::State& state) {
  const ShirtStates& shirt = shirtStates();
  if (shirt.before.size() != shirt.after.size()) return state.SkipWithError("the shirt welded during the setup");
  SelfCollision selfCollision(shirt.triangles, shirt.after.size());
  int contacts = 0;
  for (auto _ : state) {
    state.PauseTiming();
    ClothState s = shirt.after;
    state.ResumeTiming();
    contacts = selfCollision.resolve(s, shirt.before.x, shirt.settings.selfThickness, 20);
  }
  state.counters["vertices"] = double(shirt.after.size());
  state.counters["contacts"] = contacts;
}
// CPU time of all the threads (the broad phase runs on the pool): on a shared
// machine it moves less than the wall time.
BENCHMARK(BM_TShirtSelfCollision)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

// The shirt after the last frame with its sleeves swung (see the top).
ClothState swungSleeves(const ClothState& after) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& p : after.x) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const float centre = 0.5f * (lo.x + hi.x), halfWidth = 0.5f * (hi.x - lo.x);
  const float shoulder = centre + 0.45f * halfWidth, blend = 0.15f * halfWidth, angle = 0.0524f;
  ClothState swung = after;
  for (glm::vec3& p : swung.x) {
    const float side = p.x >= centre ? 1.0f : -1.0f;
    const float out = side * (p.x - centre) - (shoulder - centre);
    const float w = std::clamp(out / blend, 0.0f, 1.0f);
    // About the axis along z through the shoulder point (at the top of the shirt).
    const glm::vec2 r(p.x - (centre + side * (shoulder - centre)), p.y - hi.y);
    const float a = side * angle * w;
    const glm::vec2 turned(std::cos(a) * r.x - std::sin(a) * r.y, std::sin(a) * r.x + std::cos(a) * r.y);
    p.x += turned.x - r.x;
    p.y += turned.y - r.y;
    p.z += 0.006f;
  }
  return swung;
}

void BM_TShirtSelfCollisionSwinging(benchmark::State& state) {
  const ShirtStates& shirt = shirtStates();
  if (shirt.before.size() != shirt.after.size()) return state.SkipWithError("the shirt welded during the setup");
  const ClothState swung = swungSleeves(shirt.after);
  SelfCollision selfCollision(shirt.triangles, swung.size());
  int contacts = 0;
  for (auto _ : state) {
    state.PauseTiming();
    ClothState s = swung;
    state.ResumeTiming();
    contacts = selfCollision.resolve(s, shirt.before.x, shirt.settings.selfThickness, 20);
  }
  state.counters["contacts"] = contacts;
  state.counters["vertex_triangle"] = double(selfCollision.vertexTriangleCandidates());
  state.counters["edge_edge"] = double(selfCollision.edgeEdgeCandidates());
}
BENCHMARK(BM_TShirtSelfCollisionSwinging)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_TShirtStretchPinch(benchmark::State& state) {
  const ShirtStates& shirt = shirtStates();
  const ClothSimulator& sim = shirt.sim->simulator();
  const auto& springs = sim.forces().springs().springs();
  StretchLimiter limiter(springs, sim.forces().structuralCount(), shirt.after.size());
  // The patch: the vertices within 3 cm of the middle vertex, pulled 3 cm
  // along x; those within 1 cm are 20 times heavier (in contact).
  ClothState pinched = shirt.after;
  const glm::vec3 centre = pinched.x[pinched.size() / 2];
  for (size_t i = 0; i < pinched.size(); ++i) {
    const float d = glm::length(pinched.x[i] - centre);
    if (d < 0.03f) pinched.x[i] += glm::vec3(0.03f * (1.0f - d / 0.03f), 0.0f, 0.0f);
    if (d < 0.01f) pinched.invMass[i] *= 0.05f;
  }
  const int budget = 20 * shirt.settings.stretchIterations;
  StretchLimitResult result;
  for (auto _ : state) {
    state.PauseTiming();
    ClothState s = pinched;
    state.ResumeTiming();
    result = limiter.limitByPositions(s, shirt.settings.maxStretch, budget, 1.0f / 30.0f);
  }
  state.counters["passes"] = result.passes;
  state.counters["stretch_before"] = result.maxStretchBefore;
  state.counters["stretch_after"] = result.maxStretchAfter;
}
BENCHMARK(BM_TShirtStretchPinch)->Unit(benchmark::kMillisecond);

}  // namespace
