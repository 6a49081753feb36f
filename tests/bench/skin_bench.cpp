// BM_SkinDeform/<vertices>: linear blend skinning of positions and normals,
// 4 influences per vertex, 64 bones, on the shared thread pool.
// BM_SkinDQS/<vertices>: dual quaternion skinning of the same workload.
// BM_SkinMannequin/<method>: the default mannequin (30k vertices) posed at
// its walk's frame 0.25 s with LBS (0), DQS (1) or cones (2): palette, skin,
// and for cones the joint creases and the moved vertices' normals.
// BM_BindSectionCones: fitting the mannequin's cones and creases.
// BM_RegenerateWeights/<smooth>: rebuilding the mannequin's weights (cones,
// rigid assignment with visibility, blend; then smoothing when 1).
#include <benchmark/benchmark.h>

#include <random>

#include <glm/gtc/quaternion.hpp>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/skinning/dual_quaternion_skinning.h"
#include "core/skinning/section_cones.h"
#include "core/skinning/skin_deformer.h"
#include "core/skinning/weight_regeneration.h"
#include "core/util/thread_pool.h"

namespace {

struct SkinWorkload {
  mq::SkinBinding skin;
  std::vector<float> positions, normals, outPositions, outNormals, palette;
  mq::DualQuaternionPalette dualPalette;
};

SkinWorkload makeWorkload(size_t vertices, int bones) {
  SkinWorkload w;
  std::mt19937 rng(12111);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_int_distribution<int> bone(0, bones - 1);
  w.skin.influencesPerVertex = 4;
  w.skin.joints.resize(4 * vertices);
  w.skin.weights.resize(4 * vertices);
  w.positions.resize(3 * vertices);
  w.normals.resize(3 * vertices);
  for (size_t v = 0; v < vertices; ++v) {
    float sum = 0;
    for (int i = 0; i < 4; ++i) {
      w.skin.joints[4 * v + i] = static_cast<uint16_t>(bone(rng));
      sum += w.skin.weights[4 * v + i] = 0.1f + std::abs(unit(rng));
    }
    for (int i = 0; i < 4; ++i) w.skin.weights[4 * v + i] /= sum;
    glm::vec3 n(unit(rng), unit(rng), unit(rng));
    n = glm::normalize(n + glm::vec3(0, 0, 2));
    for (int d = 0; d < 3; ++d) {
      w.positions[3 * v + d] = unit(rng);
      w.normals[3 * v + d] = n[d];
    }
  }
  std::vector<glm::mat4> worldFromBone(bones);
  for (int b = 0; b < bones; ++b) {
    w.skin.jointBones.push_back(b);
    w.skin.inverseBind.push_back(glm::mat4(1.0f));
    const glm::quat q = glm::normalize(glm::quat(1.0f, unit(rng), unit(rng), unit(rng)));
    worldFromBone[b] = glm::mat4_cast(q);
    worldFromBone[b][3] = glm::vec4(unit(rng), unit(rng), unit(rng), 1.0f);
  }
  mq::buildSkinPalette(w.skin, worldFromBone, w.palette);
  mq::buildDualQuaternionPalette(w.skin, worldFromBone, w.dualPalette);
  w.outPositions.resize(w.positions.size());
  w.outNormals.resize(w.normals.size());
  return w;
}

void BM_SkinDeform(benchmark::State& state) {
  const size_t vertices = static_cast<size_t>(state.range(0));
  SkinWorkload w = makeWorkload(vertices, 64);
  mq::ThreadPool& pool = mq::ThreadPool::shared();
  for (auto _ : state) {
    mq::skinVertices(w.skin, w.palette, w.positions.data(), w.normals.data(), vertices, w.outPositions.data(),
                     w.outNormals.data(), &pool);
    benchmark::DoNotOptimize(w.outPositions.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(vertices));
  state.counters["threads"] = pool.threadCount();
}
BENCHMARK(BM_SkinDeform)->Arg(10000)->Arg(100000)->Arg(1000000)->UseRealTime()->Unit(benchmark::kMillisecond);

void BM_SkinDQS(benchmark::State& state) {
  const size_t vertices = static_cast<size_t>(state.range(0));
  SkinWorkload w = makeWorkload(vertices, 64);
  mq::ThreadPool& pool = mq::ThreadPool::shared();
  for (auto _ : state) {
    mq::skinVerticesDualQuaternion(w.skin, w.dualPalette, w.positions.data(), w.normals.data(), vertices,
                                   w.outPositions.data(), w.outNormals.data(), &pool);
    benchmark::DoNotOptimize(w.outPositions.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(vertices));
  state.counters["threads"] = pool.threadCount();
}
BENCHMARK(BM_SkinDQS)->Arg(10000)->Arg(100000)->Arg(1000000)->UseRealTime()->Unit(benchmark::kMillisecond);

void BM_SkinMannequin(benchmark::State& state) {
  static const mq::Character mannequin = mq::makeDefaultMannequin();
  mq::Character character = mannequin;
  character.skinning = mq::SkinningMethod(state.range(0));
  mq::prepareSkinning(character);
  const int walk = character.findClip("walk");
  const mq::Pose pose = mq::samplePose(character, walk, 0.25f);
  mq::PosedCharacter posed;
  mq::ThreadPool& pool = mq::ThreadPool::shared();
  for (auto _ : state) {
    posed.evaluate(character, pose, {}, &pool);
    benchmark::DoNotOptimize(posed.meshes()[0].positions.data());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(character.vertexCount()));
  state.SetLabel(mq::skinningMethodName(character.skinning));
}
void BM_BindSectionCones(benchmark::State& state) {
  static const mq::Character mannequin = mq::makeDefaultMannequin();
  for (auto _ : state) {
    auto cones = mq::bindSectionCones(mannequin.meshes[0], mannequin.skeleton);
    benchmark::DoNotOptimize(cones.get());
  }
}
BENCHMARK(BM_BindSectionCones)->UseRealTime()->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_RegenerateWeights(benchmark::State& state) {
  static const mq::Character mannequin = mq::makeDefaultMannequin();
  mq::WeightSettings settings;
  settings.regenerate = true;
  settings.smooth = state.range(0) != 0;
  for (auto _ : state) {
    mq::Character c = mannequin;
    const mq::WeightReport report = mq::regenerateWeights(c, settings, &mq::ThreadPool::shared());
    benchmark::DoNotOptimize(report.blendedAfter);
  }
  state.SetLabel(settings.smooth ? "regenerate + smooth" : "regenerate");
}
BENCHMARK(BM_RegenerateWeights)->Arg(0)->Arg(1)->UseRealTime()->Unit(benchmark::kMillisecond)->Iterations(3);

BENCHMARK(BM_SkinMannequin)->Arg(0)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
