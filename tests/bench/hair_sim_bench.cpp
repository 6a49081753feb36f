// BM_HairSimStep/<guides>/<interaction>: one 1/60 s step of <guides> strands
// x 32 particles with the head (ellipsoid) and neck/shoulder capsules as
// colliders, the head swaying, on the shared thread pool; interaction 1: hair
// against hair on (volume 0.5, friction 0.2). items_per_second = steps per
// second.
// BM_HairChildrenFollow/<children>: children following 2,000 guides.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "sim/hair/child_follow.h"
#include "sim/hair/hair_colliders.h"
#include "sim/hair/hair_simulator.h"

namespace {

constexpr int kPoints = 32;
constexpr float kDt = 1.0f / 60.0f;

// Strands rooted on the upper part of a head ellipsoid, growing out along
// the normal and then falling: they drape over the head and shoulders.
mq::Strands headStrands(int count, unsigned seed) {
  mq::Strands strands;
  strands.pointsPerStrand = kPoints;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  const glm::vec3 radii(0.08f, 0.1f, 0.095f);
  while (int(strands.strandCount()) < count) {
    glm::vec3 n(uniform(rng), uniform(rng), uniform(rng));
    if (glm::length(n) > 1.0f || glm::length(n) < 0.1f) continue;
    n = glm::normalize(n);
    if (n.y < 0.0f || n.z > 0.6f) continue;
    glm::vec3 p = n * radii * 1.01f;
    const float segment = 0.35f / float(kPoints - 1);
    for (int i = 0; i < kPoints; ++i) {
      strands.points.insert(strands.points.end(), {p.x, p.y, p.z});
      const float t = float(i) / float(kPoints - 1);
      p += segment * glm::normalize(glm::mix(n, glm::vec3(0.0f, -1.0f, 0.0f), t));
    }
    strands.rootNormals.insert(strands.rootNormals.end(), {n.x, n.y, n.z});
  }
  return strands;
}

mq::HairColliders headAndShoulders() {
  mq::HairColliders colliders;
  colliders.addEllipsoid(0, glm::vec3(0.0f), glm::vec3(0.08f, 0.1f, 0.095f));
  colliders.addCapsule(0, glm::vec3(0.0f, -0.2f, -0.01f), glm::vec3(0.0f, -0.08f, 0.0f), 0.05f);
  colliders.addCapsule(-1, glm::vec3(-0.18f, -0.25f, 0.0f), glm::vec3(0.18f, -0.25f, 0.0f), 0.07f);
  return colliders;
}

glm::mat4 swayingHead(int step) {
  const float s = std::sin(float(step) * kDt * 2.0f * float(M_PI) * 1.5f);
  return glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.03f * s, 0.0f, 0.0f)), 0.4f * s,
                     glm::vec3(0.0f, 1.0f, 0.0f));
}

void BM_HairSimStep(benchmark::State& state) {
  const mq::HairColliders colliders = headAndShoulders();
  mq::HairSimParams params;
  if (state.range(1)) params.interaction = {0.5f, 0.2f, 0.0f};
  mq::HairSimulator sim(params);
  sim.setRest(headStrands(int(state.range(0)), 12111));
  int step = 0;
  for (int i = 0; i < 30; ++i, ++step) {  // settle onto the head first
    const glm::mat4 head = swayingHead(step);
    const mq::PosedHairColliders body = colliders.posed({head}, 0.002f);
    sim.step(kDt, head, &body);
  }
  for (auto _ : state) {
    const glm::mat4 head = swayingHead(step++);
    const mq::PosedHairColliders body = colliders.posed({head}, 0.002f);
    sim.step(kDt, head, &body);
    benchmark::DoNotOptimize(sim.positions().data());
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["particles"] = double(sim.positions().size() / 3);
}
// Process CPU time: the cost summed over the pool's threads, which a loaded
// machine does not inflate the way it inflates wall time.
BENCHMARK(BM_HairSimStep)
    ->Args({2000, 0})
    ->Args({2000, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

void BM_HairChildrenFollow(benchmark::State& state) {
  const mq::Strands guides = headStrands(2000, 12111);
  mq::Strands children = headStrands(int(state.range(0)), 99);
  children.guideOf.resize(children.strandCount());
  for (size_t c = 0; c < children.strandCount(); ++c) children.guideOf[c] = int(c % guides.strandCount());
  mq::HairSimulator sim;
  sim.setRest(guides);
  sim.step(kDt, swayingHead(10));
  std::vector<float> out;
  for (auto _ : state) {
    mq::followGuides(children, sim, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * int64_t(children.strandCount()));
}
BENCHMARK(BM_HairChildrenFollow)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
