// mannequin-cli skin-report FILE|SCENE [--skinning M] [--json] [--no-poses] [--no-clips]
//                           [--no-intersections] [--clip-fps F] [--clip NAME|INDEX|rest]
// How well a skinning method keeps the body's shape: the skin metrics on the
// standard test poses of a humanoid and over each clip.
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/scene/open_scene.h"
#include "core/skinning/skin_report.h"
#include "core/util/error.h"
#include "core/util/thread_pool.h"

namespace mq::cli {
namespace {

using nlohmann::json;

// Unmeasured values (negative) are null in JSON and "-" in the table.
json measured(double v) { return v < 0.0 ? json() : json(std::round(v * 1e4) / 1e4); }
json measured(long v) { return v < 0 ? json() : json(v); }

json toJson(const SkinReport& r) {
  json j;
  j["method"] = r.method;
  j["vertices"] = r.vertices;
  j["triangles"] = r.triangles;
  j["rest_error"] = r.restError;
  j["poses"] = json::array();
  for (const PoseMeasure& p : r.poses)
    j["poses"].push_back(
        {{"pose", p.name},
         {"thickness", measured(p.thickness)},
         {"half_area", measured(p.halfArea)},
         {"twist_section", measured(p.twistSection)},
         {"local_volume", measured(p.localVolume)},
         {"intersections", measured(p.intersections)},
         {"body_deviation_rms_mm", p.deviationRms < 0.0 ? json() : measured(1e3 * p.deviationRms)},
         {"body_deviation_mean_mm", p.deviationRms < 0.0 ? json() : json(std::round(1e7 * p.deviationMean) / 1e4)}});
  j["clips"] = json::array();
  for (const ClipMeasure& c : r.clips)
    j["clips"].push_back({{"clip", c.name},
                          {"frames", c.frames},
                          {"worst_intersections", measured(c.worstIntersections)},
                          {"worst_time", c.worstTime},
                          {"mean_intersections", c.worstIntersections < 0 ? json() : json(c.meanIntersections)},
                          {"min_volume", c.minVolume},
                          {"max_volume", c.maxVolume}});
  j["notes"] = r.notes;
  return j;
}

std::string cell(double v, int precision = 3) {
  if (v < 0.0) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", precision, v);
  return text;
}

void printTable(const std::string& file, const SkinReport& r, std::ostream& out) {
  out << file << ": " << r.method << " skinning, " << r.vertices << " vertices, " << r.triangles
      << " triangles (welded); rest pose error " << std::scientific << std::setprecision(1) << r.restError
      << std::defaultfloat << " of the bounding box\n";
  if (!r.poses.empty()) {
    out << "  pose               M1 thick  M1 half  M2 twist  M3 volume  M4 pairs  M6 rms mm\n";
    for (const PoseMeasure& p : r.poses)
      out << "  " << std::left << std::setw(18) << p.name << std::right << std::setw(9) << cell(p.thickness)
          << std::setw(9) << cell(p.halfArea) << std::setw(10) << cell(p.twistSection) << std::setw(11)
          << cell(p.localVolume) << std::setw(10) << (p.intersections < 0 ? "-" : std::to_string(p.intersections))
          << std::setw(11) << cell(p.deviationRms < 0.0 ? -1.0 : 1e3 * p.deviationRms, 1) << "\n";
  }
  for (const ClipMeasure& c : r.clips)
    out << "  clip '" << c.name << "', " << c.frames << " frames: M4 worst "
        << (c.worstIntersections < 0 ? "-"
                                     : std::to_string(c.worstIntersections) + " at t = " + cell(c.worstTime, 3) +
                                           " s, mean " + cell(c.meanIntersections, 1))
        << "; M3' volume " << cell(c.minVolume, 4) << " to " << cell(c.maxVolume, 4) << "\n";
  for (const std::string& note : r.notes) out << "  note: " << note << "\n";
}

int runSkinReport(const std::vector<std::string>& argv) {
  const Args args(argv);
  args.allowOnly({"--skinning", "--helper-bones", "--regenerate-weights", "--smooth-weights", "--scale", "--auto-rig",
                  "--json", "--no-poses", "--no-clips", "--no-intersections", "--clip-fps", "--clip"});
  if (args.positional().size() != 1) throw Error("skin-report needs exactly one FILE");
  const std::string file = args.positional()[0];
  LoadedScene scene = openScene(file);
  printMotionMatch(scene);
  applyCharacterOptions(args, scene);
  applySkinningOption(args, scene);
  if (scene.character.meshes.empty()) throw Error("'" + file + "' has no skin to measure");
  SkinReportOptions options;
  options.poses = !args.has("--no-poses");
  options.clips = !args.has("--no-clips");
  options.intersections = !args.has("--no-intersections");
  options.clipFps = float(args.number("--clip-fps", 30.0));
  if (args.has("--clip")) {
    if (args.has("--no-clips")) throw Error("--clip and --no-clips exclude each other");
    options.clip = clipOption(args, scene, file);
    options.edits = &scene.edits;
  }
  if (!(options.clipFps > 0.0f && options.clipFps <= 1000.0f)) throw Error("--clip-fps must be between 0 and 1000");
  const SkinReport report = measureSkinning(scene.character, options, &ThreadPool::shared());
  if (args.has("--json"))
    std::cout << std::setw(2) << toJson(report) << "\n";
  else
    printTable(file, report, std::cout);
  return 0;
}

static Registration reg({"skin-report",
                         "FILE [--skinning lbs|dqs|cones] [--helper-bones] [--regenerate-weights] [--smooth-weights] "
                         "[--scale S] [--auto-rig] [--json] [--no-poses] [--no-clips] [--no-intersections]\n"
                         "         [--clip-fps F] [--clip NAME|INDEX|rest]",
                         "skin metrics (outer section M1, twist section M2, local volume M3, self-intersections M4) "
                         "on a humanoid's test poses and over each clip",
                         runSkinReport});

}  // namespace
}  // namespace mq::cli
