// mannequin-cli groom SCENE|default: grows the scene's hairstyle headless
// (rest pose) and reports timings; optionally writes the strands as PLY.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/hair/character_groom.h"
#include "core/hair/groom_stroke.h"
#include "core/hair/hairstyle_json.h"
#include "core/hair/head_fit.h"
#include "core/hair/strands_io.h"
#include "core/scene/open_scene.h"
#include "core/scene/scene_document.h"
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

glm::vec3 pointOption(const Args& args, const std::string& name) {
  const std::string text = args.option(name);
  glm::vec3 v(0.0f);
  char* end = nullptr;
  const char* p = text.c_str();
  for (int d = 0; d < 3; ++d) {
    const double x = std::strtod(p, &end);
    if (end == p || !std::isfinite(x) || std::abs(x) > 100.0 || (d < 2 && *end != ',') || (d == 2 && *end != '\0'))
      throw Error("option " + name + " expects X,Y,Z in metres (three numbers, each under 100), not '" + text + "'");
    v[d] = float(x);
    p = end + 1;
  }
  return v;
}

// --brush B --at X,Y,Z [--to X,Y,Z]: one stroke from `at` to `to` (world
// metres, rest pose), added after the document's strokes.
GroomStroke strokeOption(const Args& args, const glm::vec3& headCenter) {
  GroomStroke stroke;
  stroke.brush = groomBrushFromName(args.option("--brush"));
  stroke.radius = float(args.number("--radius", 0.03));
  if (!(stroke.radius > 0.0f && stroke.radius <= 1.0f)) throw Error("option --radius expects metres in (0, 1]");
  stroke.strength = float(args.number("--strength", stroke.brush == GroomBrush::Comb ? 1.0 : 0.5));
  const float lowest = stroke.brush == GroomBrush::Length ? -1.0f : 0.0f;
  if (!(stroke.strength >= lowest && stroke.strength <= 1.0f))
    throw Error("option --strength expects " + std::string(lowest < 0.0f ? "-1" : "0") + " to 1 for the " +
                groomBrushName(stroke.brush) + " brush");
  stroke.mirror = args.has("--mirror");
  if (isPaintBrush(stroke.brush)) {
    if (!args.has("--value")) throw Error("the " + groomBrushName(stroke.brush) + " brush needs --value V");
    const PaintRange range = paintRange(stroke.brush);
    stroke.value = float(args.number("--value", 1.0));
    if (!(stroke.value >= range.min && stroke.value <= range.max))
      throw Error("option --value expects " + std::to_string(range.min).substr(0, 4) + " to " +
                  std::to_string(range.max).substr(0, 4) + " for the " + groomBrushName(stroke.brush) + " brush");
  } else if (args.has("--value")) {
    throw Error(
        "--value is for the paint brushes (paint_density, paint_length, paint_clumping, paint_melanin, "
        "paint_pheomelanin)");
  }
  if (!args.has("--at")) throw Error("--brush needs --at X,Y,Z (where the stroke starts, world metres, rest pose)");
  const glm::vec3 at = pointOption(args, "--at") - headCenter;
  const glm::vec3 to = args.has("--to") ? pointOption(args, "--to") - headCenter : at;
  if (stroke.brush == GroomBrush::Comb && at == to) throw Error("the comb needs --to X,Y,Z: where it drags the hair");
  stroke.dabs = dabsAlong(at, to, stroke.radius);
  return stroke;
}

// The strands' painted pigments: the range of each, and how many strands
// the paint changed (by more than 0.01).
nlohmann::json pigmentStats(const Strands& strands, const HairShadingParams& style) {
  const float base[2] = {style.melanin, style.pheomelanin};
  float lo[2] = {base[0], base[1]}, hi[2] = {base[0], base[1]};
  size_t painted = 0;
  const size_t count = strands.pigmentPaint.empty() ? 0 : strands.strandCount();
  for (size_t s = 0; s < count; ++s) {
    const auto [eumelanin, pheomelanin] = strands.pigments(s, base[0], base[1]);
    const float v[2] = {eumelanin, pheomelanin};
    bool changed = false;
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], v[k]);
      hi[k] = std::max(hi[k], v[k]);
      changed = changed || std::abs(v[k] - base[k]) > 0.01f;
    }
    painted += changed;
  }
  return {{"melanin", {lo[0], hi[0]}}, {"pheomelanin", {lo[1], hi[1]}}, {"painted_strands", painted}};
}

int runGroom(const std::vector<std::string>& argv) {
  const Args args(argv);
  args.allowOnly({"--strands", "--points", "--style", "--out", "--stats-json", "--seed", "--scale", "--auto-rig",
                  "--brush", "--at", "--to", "--radius", "--strength", "--mirror", "--value", "--save-as"});
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
  if (args.has("--brush")) {
    if (section.style.strokes.size() >= kMaxGroomStrokes)
      throw Error("the hairstyle already holds " + std::to_string(kMaxGroomStrokes) + " strokes");
    section.style.strokes.push_back(strokeOption(args, groom->proxy().headCenter()));
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
      {"points_inside_body", inside},
      {"strokes", section.style.strokes.size()},
      {"pigments", pigmentStats(strands, section.style.shading)}};
  const std::string saveAs = args.option("--save-as");
  if (!saveAs.empty()) {
    if (!isSceneDocumentPath(saveAs)) throw FileError(saveAs, "--save-as writes a scene document (.mqscene or .json)");
    SceneDocument document = scene.document;
    if (!scene.documentPath.empty()) rebaseDocumentPaths(document, scene.documentPath, saveAs);
    document.hair = toJson(section);  // the style as grown: fitted to this head, with its strokes
    saveSceneDocument(document, saveAs);
  }
  const std::string statsPath = args.option("--stats-json");
  if (!statsPath.empty()) writeFileAtomically(statsPath, [&](std::ostream& o) { o << std::setw(2) << stats << "\n"; });
  std::cout << "groomed " << strands.strandCount() << " strands (" << groom->guideCount() << " guides) x "
            << strands.pointsPerStrand << " points, style " << section.style.name << ", in " << growSeconds
            << " s (guides " << groom->timings().guides << " s, children " << groom->timings().children << " s); "
            << section.style.strokes.size() << " brush strokes; points inside the body: " << inside
            << (out.empty() ? "" : "; wrote " + out) << (saveAs.empty() ? "" : "; saved the scene as " + saveAs)
            << "\n";
  return inside == 0 ? 0 : 4;
}

static Registration reg(
    {"groom",
     "SCENE|default [--strands N] [--points P] [--style NAME] [--seed S] [--out strands.ply] [--stats-json OUT] "
     "[--brush comb|cut|length|puff|smooth|clump|frizz|paint_density|paint_length|paint_clumping|paint_melanin|"
     "paint_pheomelanin --at X,Y,Z "
     "[--to X,Y,Z] [--radius M] [--strength S] [--mirror] [--value V]] [--save-as OUT.mqscene]",
     "grows the hairstyle (flow-field styling, guides and children, the document's brush strokes); stats and PLY "
     "polylines",
     runGroom,
     "  --brush B --at X,Y,Z [--to X,Y,Z]: adds one stroke of brush B from --at to --to (world metres, rest\n"
     "    pose; a dab every quarter radius), after the document's strokes. --radius in metres (default\n"
     "    0.03), --strength 0..1 (default 1 for the comb, which then drags the hair all the way, else\n"
     "    0.5; the length brush takes -1..1, negative shortens),\n"
     "    --mirror also brushes across the head's symmetry plane. The comb drags the hair from --at to --to.\n"
     "    The paint brushes paint a map over the scalp with --value: paint_density the share of the hair that\n"
     "    grows there (0..1), paint_length a length factor (0.05..10), paint_clumping the clumping (0..1),\n"
     "    paint_melanin and paint_pheomelanin the colour as the fibre's pigment concentrations (0..8; blond\n"
     "    about 0.3, brown 1.3, black 8; pheomelanin reddens); --strength is then the paint's opacity.\n"
     "  --save-as OUT: writes the scene with the hairstyle as grown (fitted to this head, with its strokes).\n"});

}  // namespace
}  // namespace mq::cli
