// mannequin-cli groom SCENE|default: grows the scene's hairstyle headless
// (rest pose) and reports timings; optionally writes the strands as PLY.
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/hair/character_groom.h"
#include "core/hair/hairstyle_json.h"
#include "core/hair/head_fit.h"
#include "core/hair/strands_io.h"
#include "core/scene/open_scene.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace mq::cli {
namespace {

HairSection hairSectionOf(const LoadedScene& scene) {
  const nlohmann::json& hair = scene.document.hair;
  if (hair.is_null()) {
    HairSection section;
    section.style = builtinHairStyle("long_straight");
    section.fitToHead = true;
    return section;
  }
  try {
    return hairSectionFromJson(hair);
  } catch (const FileError&) {
    throw;
  } catch (const Error& e) {
    throw FileError(scene.documentPath, e.what());
  }
}

nlohmann::json bounds(const std::vector<float>& points, bool upper) {
  glm::vec3 v(upper ? -1e30f : 1e30f);
  for (size_t k = 0; k + 2 < points.size(); k += 3) {
    const glm::vec3 p(points[k], points[k + 1], points[k + 2]);
    v = upper ? glm::max(v, p) : glm::min(v, p);
  }
  return nlohmann::json::array({v.x, v.y, v.z});
}

int countOption(const Args& args, const std::string& name, double fallback, double lo, double hi) {
  const double v = args.number(name, fallback);
  if (v < lo || v > hi || v != double(int64_t(v)))
    throw Error("option " + name + " expects a whole number in " + std::to_string(int64_t(lo)) + ".." +
                std::to_string(int64_t(hi)));
  return int(v);
}

int runGroom(const std::vector<std::string>& argv) {
  const Args args(argv);
  args.allowOnly({"--strands", "--points", "--style", "--out", "--stats-json", "--seed", "--scale", "--auto-rig"});
  if (args.positional().size() != 1) throw Error("groom needs exactly one SCENE (or 'default')");
  const auto start = std::chrono::steady_clock::now();
  LoadedScene scene = openScene(args.positional()[0]);
  printMotionMatch(scene);
  applyCharacterOptions(args, scene);
  HairSection section = hairSectionOf(scene);
  if (args.has("--style")) {
    section.style = builtinHairStyle(args.option("--style"));
    section.fitToHead = true;
  }
  if (args.has("--points")) section.style.pointsPerStrand = countOption(args, "--points", 32, 2, 1024);
  if (args.has("--seed")) section.style.seed = uint32_t(countOption(args, "--seed", 1, 0, 2147483647));
  if (args.has("--strands"))
    section.strands = size_t(countOption(args, "--strands", 0, 1, double(HairGroom::kMaxStrands)));

  const auto groomStart = std::chrono::steady_clock::now();
  const float unfittedLength = section.style.length;
  std::unique_ptr<HairGroom> groom;
  try {
    groom = makeSectionGroom(scene.character, section);
  } catch (const FileError&) {
    throw;
  } catch (const Error& e) {
    throw FileError(args.positional()[0], e.what());
  }
  const double setupSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - groomStart).count();
  groom->grow(section.style, section.strands);
  const double growSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - groomStart).count() - setupSeconds;

  const Strands& strands = groom->strands();
  const size_t inside = groom->countPointsInside();
  const std::string out = args.option("--out");
  if (!out.empty()) writeStrandsPly(strands, out);

  nlohmann::json stats{
      {"style", section.style.name},
      {"strands", strands.strandCount()},
      {"guides", groom->guideCount()},
      {"points_per_strand", strands.pointsPerStrand},
      {"seconds", growSeconds},
      {"roots_seconds", groom->timings().roots},
      {"guides_seconds", groom->timings().guides},
      {"children_seconds", groom->timings().children},
      {"setup_seconds", setupSeconds},
      {"total_seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()},
      {"panels", groom->flow().panels().size()},
      {"scalp_area_cm2", groom->scalp().area() * 1e4},
      {"min_root_distance_mm", groom->childRoots().size() ? groom->childRoots().minDistance * 1e3 : 0.0f},
      {"head_size_m", headSize(groom->proxy())},
      {"style_scale", section.style.length / unfittedLength},
      {"bbox_min", bounds(strands.points, false)},
      {"bbox_max", bounds(strands.points, true)},
      {"points_inside_body", inside}};
  const std::string statsPath = args.option("--stats-json");
  if (!statsPath.empty()) writeFileAtomically(statsPath, [&](std::ostream& o) { o << std::setw(2) << stats << "\n"; });
  std::cout << "groomed " << strands.strandCount() << " strands (" << groom->guideCount() << " guides) x "
            << strands.pointsPerStrand << " points, style " << section.style.name << ", in " << growSeconds
            << " s (guides " << groom->timings().guides << " s, children " << groom->timings().children
            << " s); points inside the body: " << inside << (out.empty() ? "" : "; wrote " + out) << "\n";
  return inside == 0 ? 0 : 4;
}

static Registration reg(
    {"groom",
     "SCENE|default [--strands N] [--points P] [--style NAME] [--seed S] [--out strands.ply] [--stats-json OUT]",
     "grows the hairstyle (flow-field styling, guides and children); stats and PLY polylines", runGroom});

}  // namespace
}  // namespace mq::cli
