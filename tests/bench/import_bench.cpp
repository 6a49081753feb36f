// Import and export costs: the sample characters, a long BVH, and writing a
// posed mesh.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "core/character/posed_character.h"
#include "core/io/bvh_import.h"
#include "core/io/character_import.h"
#include "core/io/mesh_export.h"

namespace {

const std::string kAssets = std::string(MANNEQUIN_SHARED_DIR) + "/assets/";

void importFile(benchmark::State& state, const std::string& relative) {
  const std::string path = kAssets + relative;
  for (auto _ : state) benchmark::DoNotOptimize(mq::importCharacter(path));
}

BENCHMARK_CAPTURE(importFile, cesium_gltf, std::string("characters/CesiumMan/glTF/CesiumMan.gltf"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(importFile, cesium_glb, std::string("characters/CesiumMan/glTF-Binary/CesiumMan.glb"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(importFile, fbx,
                  std::string("characters/assimp_fbx_animation_with_skeleton/animation_with_skeleton.fbx"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(importFile, dae_clips,
                  std::string("characters/assimp_collada_library_animation_clips/library_animation_clips.dae"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(importFile, bvh_cmu_2752_frames, std::string("motion/cmu_01_01.bvh"))->Unit(benchmark::kMillisecond);

void retargetCmuOntoItself(benchmark::State& state) {
  const mq::Character target = mq::loadBvhCharacter(kAssets + "motion/cmu_01_01.bvh");
  for (auto _ : state) benchmark::DoNotOptimize(mq::importBvhMotion(kAssets + "motion/cmu_01_01.bvh", target));
}
BENCHMARK(retargetCmuOntoItself)->Unit(benchmark::kMillisecond);

void exportCesium(benchmark::State& state, const char* extension) {
  const mq::Character c = mq::importCharacter(kAssets + "characters/CesiumMan/glTF-Binary/CesiumMan.glb");
  mq::PosedCharacter posed;
  posed.evaluate(c, 0, 1.0f, nullptr, nullptr);
  const std::string out =
      (std::filesystem::temp_directory_path() / (std::string("mq_bench_export.") + extension)).string();
  for (auto _ : state) mq::exportPosedCharacter(c, posed, out);
  std::filesystem::remove(out);
}
BENCHMARK_CAPTURE(exportCesium, obj, "obj")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(exportCesium, ply, "ply")->Unit(benchmark::kMillisecond);

}  // namespace
