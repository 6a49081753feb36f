#include "app/cli/simulate_hair.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>

#include "app/cli/scene_hair.h"
#include "core/hair/strands_io.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "core/util/process_memory.h"
#include "core/util/thread_pool.h"
#include "sim/hair/hair_interaction.h"

namespace mq::cli {
namespace {

constexpr float kSettleSeconds = 0.5f;

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string plyFrameName(int frameNumber) {
  char name[32];
  std::snprintf(name, sizeof name, "hair_%04d.ply", frameNumber);
  return name;
}

nlohmann::json boundsJson(const std::vector<float>& points, bool upper) {
  float v[3];
  for (int d = 0; d < 3; ++d) v[d] = upper ? -std::numeric_limits<float>::max() : std::numeric_limits<float>::max();
  for (size_t k = 0; k + 2 < points.size(); k += 3)
    for (int d = 0; d < 3; ++d) v[d] = upper ? std::max(v[d], points[k + d]) : std::min(v[d], points[k + d]);
  return nlohmann::json::array({v[0], v[1], v[2]});
}

float unitOption(const Args& args, const std::string& name) {
  if (!args.has(name)) return -1.0f;
  const double v = args.number(name, 0.0);
  if (!(v >= 0.0 && v <= 1.0)) throw Error(name + " expects a number from 0 to 1");
  return float(v);
}

// Pairs of guide segments closer than a wisp's radius, over the frames.
struct CrossingCount {
  float distance = 0.0f;
  size_t max = 0, sum = 0, frames = 0;
  void add(const std::vector<float>& guides, size_t strandCount, int points) {
    const size_t pairs = closeSegmentPairs(guides, strandCount, points, distance);
    max = std::max(max, pairs);
    sum += pairs;
    ++frames;
  }
};

}  // namespace

HairRunOptions hairRunOptions(const Args& args) {
  HairRunOptions options;
  options.volume = unitOption(args, "--hair-volume");
  options.friction = unitOption(args, "--hair-friction");
  options.countCrossings = args.has("--hair-crossings");
  if (args.has("--hair-wisps")) {
    const std::string wisps = args.option("--hair-wisps", "");
    if (wisps != "adaptive" && wisps != "all") throw Error("--hair-wisps expects adaptive or all");
    options.adaptiveWisps = wisps == "adaptive" ? 1 : 0;
  }
  return options;
}

void simulateSceneHair(const LoadedScene& scene, int frames, float fps, const std::string& exportDir,
                       const HairRunOptions& options, nlohmann::json& stats) {
  HairSection section = sceneHairSection(scene);
  if (options.volume >= 0.0f) section.style.dynamics.volume = options.volume;
  if (options.friction >= 0.0f) section.style.dynamics.friction = options.friction;
  if (options.adaptiveWisps >= 0) section.style.dynamics.adaptiveWisps = options.adaptiveWisps == 1;
  SceneHair hair(scene, section);
  const HairSimulator& sim = hair.simulator();
  CrossingCount crossings;
  if (options.countCrossings)
    crossings.distance = 0.5f * meanRootSpacing(sim.rest().points, sim.strandCount(), sim.pointsPerStrand());
  const float start = scene.document.time;
  const auto settleStart = std::chrono::steady_clock::now();
  hair.settle(start, kSettleSeconds, fps);
  const double settleSeconds = secondsSince(settleStart);

  Strands exported = hair.groom().strands();  // topology for the PLY frames
  double guideSeconds = 0.0, childSeconds = 0.0;
  float maxLengthError = 0.0f;
  size_t maxInside = 0, maxRootsInside = 0;
  double rssAfterFirstFrame = 0.0;  // MB: memory must stay flat over long runs
  size_t simulatedGuides = 0, fewestSimulatedGuides = sim.strandCount();
  for (int f = 0; f < frames; ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    hair.step(start + float(f + 1) / fps, 1.0f / fps);
    const auto t1 = std::chrono::steady_clock::now();
    hair.updateAllStrands();
    guideSeconds += std::chrono::duration<double>(t1 - t0).count();
    childSeconds += secondsSince(t1);
    maxLengthError = std::max(maxLengthError, hair.maxGuideLengthError());
    simulatedGuides += sim.simulatedStrands();
    fewestSimulatedGuides = std::min(fewestSimulatedGuides, sim.simulatedStrands());
    if (f == 0) rssAfterFirstFrame = residentMegabytes();
    const SceneHair::InsideCount inside = hair.pointsInsideBody();
    maxInside = std::max(maxInside, inside.points);
    maxRootsInside = std::max(maxRootsInside, inside.roots);
    if (options.countCrossings) crossings.add(sim.positions(), sim.strandCount(), sim.pointsPerStrand());
    if (!exportDir.empty()) {
      exported.points = hair.allStrands();
      writeStrandsPly(exported, (std::filesystem::path(exportDir) / plyFrameName(f + 1)).string());
    }
  }
  const double seconds = guideSeconds + childSeconds;
  stats["hair_style"] = hair.style().name;
  stats["hair_guides"] = hair.groom().guideCount();
  stats["hair_strands"] = hair.groom().strands().strandCount();
  stats["hair_points_per_strand"] = hair.groom().strands().pointsPerStrand;
  stats["hair_groom_seconds"] = hair.groomSeconds();
  stats["hair_settle_seconds"] = settleSeconds;
  stats["hair_seconds"] = seconds;
  stats["hair_ms_per_frame"] = 1000.0 * seconds / frames;
  stats["hair_guides_ms_per_frame"] = 1000.0 * guideSeconds / frames;
  stats["hair_children_ms_per_frame"] = 1000.0 * childSeconds / frames;
  stats["hair_max_length_error"] = maxLengthError;
  stats["hair_points_inside_body"] = maxInside;
  stats["hair_final_points_inside_body"] = hair.pointsInsideBody().points;
  stats["hair_roots_inside_proxies"] = maxRootsInside;
  stats["hair_bbox_min"] = boundsJson(hair.allStrands(), false);
  stats["hair_bbox_max"] = boundsJson(hair.allStrands(), true);
  stats["hair_rss_mb_after_first_frame"] = rssAfterFirstFrame;
  stats["hair_rss_mb_end"] = residentMegabytes();
  stats["hair_volume"] = hair.style().dynamics.volume;
  stats["hair_friction"] = hair.style().dynamics.friction;
  stats["hair_adaptive_wisps"] = hair.style().dynamics.adaptiveWisps;
  stats["hair_simulated_guides_mean"] = double(simulatedGuides) / double(std::max(1, frames));
  stats["hair_simulated_guides_min"] = fewestSimulatedGuides;
  if (options.countCrossings) {
    stats["hair_close_guide_distance"] = crossings.distance;
    stats["hair_close_guide_pairs_groomed"] =
        closeSegmentPairs(sim.rest().points, sim.strandCount(), sim.pointsPerStrand(), crossings.distance);
    stats["hair_close_guide_pairs_max"] = crossings.max;
    stats["hair_close_guide_pairs_mean"] = double(crossings.sum) / double(std::max<size_t>(1, crossings.frames));
  }
  std::cout << "simulated hair: " << hair.groom().strands().strandCount() << " strands (" << hair.groom().guideCount()
            << " guides) over " << frames << " frames in " << seconds << " s (" << 1000.0 * seconds / frames
            << " ms/frame), max length error " << maxLengthError << ", points inside the body " << maxInside
            << (exportDir.empty() ? "" : ", wrote " + exportDir + "/hair_*.ply") << ", on "
            << clipLabel(scene, scene.clipIndex) << "\n";
}

int simulateHairOnly(const LoadedScene& scene, const std::string& path, int frames, const Args& args) {
  const float fps = float(args.number("--fps", 60.0));
  if (!(fps > 0.0f) || !std::isfinite(fps)) throw Error("--fps expects a positive number");
  const std::string exportDir = args.option("--export-dir");
  if (!exportDir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(exportDir, ec);
    if (ec) throw FileError(exportDir, "cannot create the directory: " + ec.message());
  }
  nlohmann::json stats = {
      {"scene", path}, {"frames", frames}, {"fps", fps}, {"threads", ThreadPool::shared().threadCount()}};
  simulateSceneHair(scene, frames, fps, exportDir, hairRunOptions(args), stats);
  const std::string statsPath = args.option("--stats-json");
  if (!statsPath.empty()) writeFileAtomically(statsPath, [&](std::ostream& o) { o << stats.dump(2) << "\n"; });
  return 0;
}

}  // namespace mq::cli
