// mannequin-cli simulate SCENE --frames N [--fps F] [--stats-json OUT] [--export-dir DIR]
// Runs the cloth simulation of a scene document headless and reports what
// the benchmarks compare: wall time, stretch, penetrations, bounds.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/simulate_hair.h"
#include "core/character/posed_character.h"
#include "core/scene/open_scene.h"
#include "core/util/error.h"
#include "core/util/thread_pool.h"
#include "sim/cloth/baked_cloth.h"
#include "sim/cloth/cloth_scene_io.h"
#include "sim/cloth/cloth_simulator.h"

namespace {

using nlohmann::json;
using namespace mq;

// The body the cloth collides with: all of the character's meshes, posed.
class PosedBody {
 public:
  PosedBody(const LoadedScene& scene) : scene_(scene) {}
  bool empty() const { return scene_.character.meshes.empty(); }
  void pose(float time, std::vector<float>& positions, std::vector<uint32_t>* triangles) {
    posed_.evaluate(scene_.character, scene_.clipIndex, time, &scene_.edits, &ThreadPool::shared());
    positions.clear();
    if (triangles) triangles->clear();
    for (size_t m = 0; m < posed_.meshes().size(); ++m) {
      const uint32_t offset = uint32_t(positions.size() / 3);
      const auto& p = posed_.meshes()[m].positions;
      positions.insert(positions.end(), p.begin(), p.end());
      if (triangles)
        for (uint32_t t : scene_.character.meshes[m].triangles) triangles->push_back(t + offset);
    }
  }

 private:
  const LoadedScene& scene_;
  PosedCharacter posed_;
};

json vec3Json(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

struct RunResult {
  double seconds = 0.0;
  float maxStretch = 1.0f;
  long long solverIterations = 0;
  int substeps = 0;
};

RunResult run(cloth::ClothSimulator& sim, PosedBody& body, float startTime, bool animateBody, int frames, float fps,
               const std::string& exportDir) {
  RunResult r;
  std::vector<float> bodyPositions;
  for (int f = 0; f < frames; ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    if (!body.empty() && animateBody) {
      body.pose(startTime + float(f + 1) / fps, bodyPositions, nullptr);
      sim.updateBody(bodyPositions);
    }
    sim.step(1.0f / fps);
    r.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.maxStretch = std::max(r.maxStretch, sim.stats().maxStretch);
    r.solverIterations += sim.stats().solverIterations;
    r.substeps = sim.stats().substeps;
    if (!exportDir.empty())
      cloth::writeObj((std::filesystem::path(exportDir) / cloth::objFrameName("cloth", f + 1)).string(),
                      sim.flatPositions(), sim.triangles());
  }
  return r;
}

int runSimulate(const std::vector<std::string>& argv) {
  const cli::Args args(argv);
  args.allowOnly({"--frames", "--fps", "--stats-json", "--export-dir"});
  if (args.positional().size() != 1) throw Error("simulate needs exactly one SCENE argument");
  const std::string path = args.positional()[0];
  const double framesArg = args.number("--frames", 120);
  if (!(framesArg >= 1) || framesArg != std::floor(framesArg)) throw Error("--frames expects a positive integer");
  if (!isSceneDocumentPath(path)) throw FileError(path, "simulate needs a scene document (.mqscene or .json)");
  LoadedScene scene;
  try {
    scene = openScene(path);  // FileError for unreadable, truncated or invalid documents
  } catch (const json::exception& e) {
    throw FileError(path, std::string("not a valid scene document: ") + e.what());
  }
  if (scene.document.cloth.is_null() && !scene.document.hair.is_null())
    return cli::simulateHairOnly(scene, path, int(framesArg), args);
  const cloth::ClothSceneSpec spec = cloth::parseClothScene(scene.document.cloth, scene.document.colliders, path);
  const float fps = float(args.number("--fps", spec.fps));
  if (!(fps > 0.0f) || !std::isfinite(fps)) throw Error("--fps expects a positive number");

  std::vector<uint32_t> pinned;
  cloth::ClothSimulator sim(cloth::buildClothMesh(spec, pinned), spec.fabric, spec.settings);
  for (const auto& c : spec.colliders) sim.addCollider(c);
  for (uint32_t v : pinned) sim.pinVertex(v);
  PosedBody body(scene);
  if (!body.empty()) {
    std::vector<float> positions;
    std::vector<uint32_t> triangles;
    body.pose(scene.document.time, positions, &triangles);
    sim.setBody(positions, triangles);
  }

  const std::string exportDir = args.option("--export-dir");
  if (!exportDir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(exportDir, ec);
    if (ec) throw FileError(exportDir, "cannot create the directory: " + ec.message());
  }
  const int frames = int(framesArg);
  const RunResult r = run(sim, body, scene.document.time, spec.animateBody, frames, fps, exportDir);
  const cloth::ClothStats& st = sim.stats();
  json stats = {{"scene", path},
                {"frames", frames},
                {"fps", fps},
                {"seconds", r.seconds},
                {"ms_per_frame", 1000.0 * r.seconds / frames},
                {"max_stretch", r.maxStretch},
                {"final_max_stretch", st.maxStretch},
                {"penetrating_vertices", st.penetratingVertices},
                {"bbox_min", vec3Json(st.boundsMin)},
                {"bbox_max", vec3Json(st.boundsMax)},
                {"vertices", sim.positions().size()},
                {"integrator", cloth::integratorName(spec.settings.integrator)},
                {"substeps_per_frame", r.substeps},
                {"cg_iterations_per_frame", double(r.solverIterations) / frames},
                {"threads", ThreadPool::shared().threadCount()}};
  if (!scene.document.hair.is_null()) cli::simulateSceneHair(scene, frames, fps, exportDir, stats);
  const std::string statsPath = args.option("--stats-json");
  if (!statsPath.empty()) {
    std::ofstream out(statsPath);
    if (!out) throw FileError(statsPath, "cannot open for writing");
    out << stats.dump(2) << "\n";
  }
  std::cout << "simulated " << frames << " frames of " << sim.positions().size() << " vertices in " << r.seconds
            << " s (" << 1000.0 * r.seconds / frames << " ms/frame), max stretch " << r.maxStretch
            << ", penetrating vertices " << st.penetratingVertices << "\n";
  return 0;
}

const cli::Registration reg({"simulate", "SCENE --frames N [--fps F] [--stats-json OUT] [--export-dir DIR]",
                             "run the scene's cloth and hair simulation headless; stats as JSON, frames as OBJ/PLY", runSimulate});

}  // namespace
