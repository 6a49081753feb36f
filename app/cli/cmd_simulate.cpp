// mannequin-cli simulate SCENE --frames N [--fps F] [--stats-json OUT] [--export-dir DIR [--export-format obj|pc2]]
// [--layers on|off] Runs the cloth of a scene document headless (the "cloth" section's sheet and the "garments", sewn
// then welded, on the character playing its clip) and reports what the benchmarks compare: wall time, stretch,
// penetrations, bounds over all cloth, and per garment in "garments".
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "app/cli/scene_cloth.h"
#include "app/cli/simulate_garments.h"
#include "app/cli/simulate_hair.h"
#include "core/character/posed_character.h"
#include "core/io/json_fields.h"
#include "core/scene/open_scene.h"
#include "core/util/error.h"
#include "core/util/memory_budget.h"
#include "core/util/process_memory.h"
#include "core/util/thread_pool.h"
#include "sim/cloth/baked_cloth.h"
#include "sim/cloth/cloth_scene_io.h"
#include "sim/cloth/cloth_simulator.h"

namespace {

using nlohmann::json;
using namespace mq;
using cli::makeSheet;
using cli::PosedBody;

json vec3Json(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

struct RunResult {
  double seconds = 0.0;
  double cpuSeconds = 0.0;  // process CPU time (all threads), for a loaded machine
  float maxStretch = 1.0f;
  int maxStretchFrame = 0;  // the frame (from 1) where the cloth stretched most
  int maxPenetrating = 0;   // the most cloth vertices inside the body in any frame
  long long solverIterations = 0;
  int substeps = 0;
  double poseSeconds = 0.0;                           // posing the character (skinning) for the frames
  double phaseSeconds[cloth::kClothPhaseCount] = {};  // the sheet's solver phases (ClothPhase)
  double rssAfterFirstFrame = 0.0;                    // MB: memory must stay flat over long runs
};

// All cloth of the scene, stepped frame by frame on the (animated) body.
struct SceneCloth {
  std::unique_ptr<cloth::ClothSimulator> sheet;
  std::unique_ptr<cli::SimulatedGarments> garments;

  cli::ClothNow now() const {
    cli::ClothNow n;
    if (sheet) n.add(*sheet, sheet->positions().size());
    if (garments) garments->addTo(n);
    return n;
  }
};

// Where the frames go: one OBJ per frame per cloth, or one point cache per
// cloth written after the last frame.
struct FrameExport {
  std::string dir;  // empty: none
  bool pointCache = false;
  cloth::BakedCloth sheet;  // the sheet's frames, for its point cache
};

RunResult run(SceneCloth& cloth, PosedBody& body, float startTime, bool animateBody, int frames, float fps,
              FrameExport& exported) {
  const std::string& exportDir = exported.dir;
  RunResult r;
  std::vector<float> bodyPositions;
  for (int f = 0; f < frames; ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t cpu0 = std::clock();
    const bool posed = !body.empty() && animateBody;
    if (posed) body.pose(startTime + float(f + 1) / fps, bodyPositions, nullptr);
    r.poseSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (cloth.sheet) {
      if (posed) cloth.sheet->updateBody(bodyPositions);
      cloth.sheet->step(1.0f / fps);
      for (int k = 0; k < cloth::kClothPhaseCount; ++k) r.phaseSeconds[k] += cloth.sheet->stats().phaseSeconds[k];
      r.solverIterations += cloth.sheet->stats().solverIterations;
      r.substeps = cloth.sheet->stats().substeps;
    }
    if (cloth.garments) cloth.garments->step(1.0f / fps, posed ? &bodyPositions : nullptr);
    r.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.cpuSeconds += double(std::clock() - cpu0) / CLOCKS_PER_SEC;
    if (cloth.garments) cloth.garments->measureFrame();
    if (f == 0) r.rssAfterFirstFrame = residentMegabytes();
    const cli::ClothNow now = cloth.now();
    if (now.maxStretch > r.maxStretch) r.maxStretch = now.maxStretch, r.maxStretchFrame = f + 1;
    r.maxPenetrating = std::max(r.maxPenetrating, now.penetratingVertices);
    if (exportDir.empty()) continue;
    if (exported.pointCache) {
      if (cloth.sheet) {
        if (f == 0) exported.sheet = cloth::BakedCloth(cloth.sheet->triangles(), fps);
        exported.sheet.addFrame(cloth.sheet->flatPositions());
      }
      if (cloth.garments) cloth.garments->recordFrame(fps);
      continue;
    }
    if (cloth.sheet)
      cloth::writeObj((std::filesystem::path(exportDir) / cloth::objFrameName("cloth", f + 1)).string(),
                      cloth.sheet->flatPositions(), cloth.sheet->triangles());
    if (cloth.garments) cloth.garments->exportFrame(exportDir, f + 1);
  }
  if (exported.pointCache && !exportDir.empty()) {
    if (cloth.sheet) exported.sheet.exportPointCache(exportDir, "cloth");
    if (cloth.garments) cloth.garments->exportPointCaches(exportDir);
  }
  return r;
}

// Where the frames' wall time went: posing the character, then each phase
// of the solvers (summed over the sheet and the garments), ms per frame.
json phaseProfile(const RunResult& r, const SceneCloth& cloth, int frames) {
  json profile = {{"pose_character", 1000.0 * r.poseSeconds / frames}};
  for (int k = 0; k < cloth::kClothPhaseCount; ++k) {
    const double seconds = r.phaseSeconds[k] + (cloth.garments ? cloth.garments->phaseSeconds()[k] : 0.0);
    profile[cloth::clothPhaseName(cloth::ClothPhase(k))] = 1000.0 * seconds / frames;
  }
  return profile;
}

int runSimulate(const std::vector<std::string>& argv) {
  const cli::Args args(argv);
  args.allowOnly({"--frames", "--fps", "--stats-json", "--export-dir", "--export-format", "--layers", "--skinning",
                  "--helper-bones", "--regenerate-weights", "--smooth-weights", "--scale", "--auto-rig", "--clip",
                  "--hair-volume", "--hair-friction", "--hair-crossings", "--hair-wisps"});
  const cli::HairRunOptions hairOptions = cli::hairRunOptions(args);  // checked before anything runs
  const std::string format = args.option("--export-format", "obj");
  if (format != "obj" && format != "pc2") throw Error("--export-format expects obj or pc2");
  const std::string layers = args.option("--layers", "on");
  if (layers != "on" && layers != "off") throw Error("--layers expects on or off");
  if (args.positional().size() != 1) throw Error("simulate needs exactly one SCENE argument");
  const std::string path = args.positional()[0];
  const double framesArg = args.number("--frames", 120);
  if (!(framesArg >= 1) || framesArg != std::floor(framesArg)) throw Error("--frames expects a positive integer");
  if (!isSceneDocumentPath(path)) throw FileError(path, "simulate needs a scene document (.mqscene or .json)");
  LoadedScene scene;
  try {
    scene = openScene(path);  // FileError for unreadable, truncated or invalid documents
  } catch (const json::exception& e) {
    throw FileError(path, "not a valid scene document: " + jsonProblem(e));
  }
  cli::printMotionMatch(scene);
  applyCharacterOptions(args, scene);
  applySkinningOption(args, scene);
  scene.clipIndex = cli::clipOption(args, scene, path);
  const json& garmentsSection = scene.document.garments;
  const bool hasGarments = garmentsSection.is_array() && !garmentsSection.empty();
  if (scene.document.cloth.is_null() && !hasGarments && !scene.document.hair.is_null())
    return cli::simulateHairOnly(scene, path, int(framesArg), args);
  const cloth::ClothSceneSpec spec =
      cloth::parseClothScene(scene.document.cloth, scene.document.colliders, path, hasGarments);
  const float fps = float(args.number("--fps", spec.fps));
  if (!(fps > 0.0f) || !std::isfinite(fps)) throw Error("--fps expects a positive number");

  PosedBody body(scene);
  std::vector<float> bodyPositions;
  std::vector<uint32_t> bodyTriangles;
  if (!body.empty()) body.pose(scene.document.time, bodyPositions, &bodyTriangles);
  SceneCloth cloth;
  cloth.sheet = makeSheet(spec, bodyPositions, bodyTriangles);
  cli::DressingResult dressing;
  if (!garmentsSection.is_null()) {
    // Garments are sewn on the rest pose their patterns were placed around,
    // then the body moves to the scene's pose; the frames start from there.
    std::vector<float> restBody;
    if (!body.empty()) body.pose(0.0f, restBody, nullptr, true);
    cloth.garments =
        std::make_unique<cli::SimulatedGarments>(garmentsSection, spec, restBody, bodyTriangles, path, layers == "on");
    dressing = cloth.garments->dress(restBody, bodyPositions, 1.0f / fps);
  }

  const std::string exportDir = args.option("--export-dir");
  if (!exportDir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(exportDir, ec);
    if (ec) throw FileError(exportDir, "cannot create the directory: " + ec.message());
  }
  const int frames = int(framesArg);
  // A point cache keeps every frame in memory until it is written.
  if (!exportDir.empty() && format == "pc2")
    checkMemoryBudget("a point cache of " + std::to_string(frames) + " frames",
                      12.0 * double(frames) * double(cloth.now().vertices));
  FrameExport exported{exportDir, format == "pc2", {}};
  const RunResult r = run(cloth, body, scene.document.time, spec.animateBody, frames, fps, exported);
  const cli::ClothNow now = cloth.now();
  json stats = {{"scene", path},
                {"frames", frames},
                {"fps", fps},
                {"seconds", r.seconds},
                {"ms_per_frame", 1000.0 * r.seconds / frames},
                {"cpu_ms_per_frame", 1000.0 * r.cpuSeconds / frames},
                {"max_stretch", r.maxStretch},
                {"max_stretch_frame", r.maxStretchFrame},
                {"final_max_stretch", now.maxStretch},
                {"penetrating_vertices", now.penetratingVertices},
                {"max_penetrating_vertices", r.maxPenetrating},
                {"bbox_min", vec3Json(now.boundsMin)},
                {"bbox_max", vec3Json(now.boundsMax)},
                {"vertices", now.vertices},
                {"integrator", cloth::integratorName(spec.settings.integrator)},
                {"substeps_per_frame", r.substeps},
                {"cg_iterations_per_frame", double(r.solverIterations) / frames},
                {"threads", ThreadPool::shared().threadCount()},
                {"rss_mb_after_first_frame", r.rssAfterFirstFrame},
                {"rss_mb_end", residentMegabytes()},
                {"peak_rss_mb", peakResidentMegabytes()}};
  stats["phase_ms_per_frame"] = phaseProfile(r, cloth, frames);
  if (cloth.garments) {
    stats["garments"] = cloth.garments->stats();
    stats["dressing_steps"] = dressing.steps;
    stats["dressing_seconds"] = dressing.seconds;
    stats["layers"] = layers == "on";
    stats["max_inside_inner_vertices"] = cloth.garments->maxInsideInnerVertices();
  }
  if (!scene.document.hair.is_null()) cli::simulateSceneHair(scene, frames, fps, exportDir, hairOptions, stats);
  const std::string statsPath = args.option("--stats-json");
  if (!statsPath.empty()) {
    std::ofstream out(statsPath);
    if (!out) throw FileError(statsPath, "cannot open for writing");
    out << stats.dump(2) << "\n";
  }
  std::cout << "simulated " << frames << " frames of " << now.vertices << " cloth vertices in " << r.seconds << " s ("
            << 1000.0 * r.seconds / frames << " ms/frame), max stretch " << r.maxStretch << ", penetrating vertices "
            << now.penetratingVertices << ", on " << cli::clipLabel(scene, scene.clipIndex) << "\n";
  return 0;
}

const cli::Registration reg(
    {"simulate",
     "SCENE --frames N [--fps F] [--clip NAME|INDEX|rest] [--stats-json OUT] [--export-dir DIR [--export-format "
     "obj|pc2]]\n"
     "         [--layers on|off] [--skinning lbs|dqs|cones] [--helper-bones] [--regenerate-weights] [--smooth-weights] "
     "[--scale S] [--auto-rig]\n"
     "         [--hair-volume V] [--hair-friction F] [--hair-crossings] [--hair-wisps adaptive|all]",
     "run the scene's cloth (sheet and garments) and hair headless; stats as JSON, frames as OBJ/PLY\n"
     "(one file per frame), or with --export-format pc2 one Point Cache 2 file per cloth and its mesh",
     runSimulate,
     "--hair-volume V, --hair-friction F: hair against hair, 0 to 1 (the style's \"dynamics\"): how strongly\n"
     "the hair holds its volume, and its internal friction. --hair-crossings: count, every frame, the pairs of\n"
     "guide segments closer than half the guides' root spacing into the stats, beside the groom's own count.\n"
     "--hair-wisps adaptive: simulate one guide per wisp where the hair moves together (all: every guide;\n"
     "default: the style's \"adaptive_wisps\")."});

}  // namespace
