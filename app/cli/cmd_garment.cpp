// mannequin-cli garment: a scene's garments as sewing patterns: their panels
// and seams (with the sewn edges' lengths, and a warning where they differ),
// the pattern written as SVG or DXF at true scale, and a DXF pattern read in
// as a new garment of the scene.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/garment/garment_json.h"
#include "core/garment/pattern_dxf.h"
#include "core/garment/pattern_svg.h"
#include "core/scene/scene_document.h"
#include "core/util/error.h"

namespace mq::cli {
namespace {

// Sewn edges further apart in length than this are reported: the seam
// eases one into the other (a sleeve cap into its armhole) or puckers.
constexpr float kSeamLengthTolerance = 0.005f;  // metres

// --garment N (from 0) or NAME; -1 when absent.
int chosenGarment(const Args& args, const std::vector<Garment>& garments, const std::string& path) {
  if (!args.has("--garment")) return -1;
  const std::string wanted = args.option("--garment");
  for (size_t i = 0; i < garments.size(); ++i)
    if (garments[i].name == wanted) return int(i);
  char* end = nullptr;
  const long index = std::strtol(wanted.c_str(), &end, 10);
  if (!wanted.empty() && *end == '\0' && index >= 0 && index < long(garments.size())) return int(index);
  std::string names;
  for (size_t i = 0; i < garments.size(); ++i) names += (i ? ", " : "") + std::to_string(i) + " " + garments[i].name;
  throw FileError(path, "no garment \"" + wanted + "\"; the scene has " + (names.empty() ? "none" : names));
}

nlohmann::json garmentJson(const Garment& garment) {
  nlohmann::json panels = nlohmann::json::array(), seams = nlohmann::json::array();
  for (const Panel& panel : garment.panels)
    panels.push_back({{"name", panel.name}, {"edges", panel.edgeCount()}, {"area_cm2", panel.area() * 1e4f}});
  const std::vector<SeamLengths> lengths = seamLengths(garment);
  for (size_t s = 0; s < garment.seams.size(); ++s) {
    const Seam& seam = garment.seams[s];
    seams.push_back({{"a", seam.panelA + "." + seam.edgeA},
                     {"b", seam.panelB + "." + seam.edgeB},
                     {"length_a_cm", lengths[s].a * 100.0f},
                     {"length_b_cm", lengths[s].b * 100.0f},
                     {"lengths_differ", std::abs(lengths[s].a - lengths[s].b) > kSeamLengthTolerance}});
  }
  return {{"name", garment.name}, {"panels", panels}, {"seams", seams}};
}

void printGarment(size_t index, const Garment& garment) {
  std::cout << "garment " << index << ": " << garment.name << ", " << garment.panels.size() << " panels, "
            << garment.seams.size() << " seams\n"
            << std::fixed << std::setprecision(1);
  for (const Panel& panel : garment.panels)
    std::cout << "  panel " << panel.name << ": " << panel.edgeCount() << " edges, " << panel.area() * 1e4f << " cm2\n";
  const std::vector<SeamLengths> lengths = seamLengths(garment);
  for (size_t s = 0; s < garment.seams.size(); ++s) {
    const Seam& seam = garment.seams[s];
    const float difference = std::abs(lengths[s].a - lengths[s].b);
    std::cout << "  seam " << s + 1 << ": " << seam.panelA << "." << seam.edgeA << " (" << lengths[s].a * 100.0f
              << " cm) to " << seam.panelB << "." << seam.edgeB << " (" << lengths[s].b * 100.0f << " cm)"
              << (difference > kSeamLengthTolerance
                      ? ", lengths differ by " + std::to_string(int(std::lround(difference * 1000.0f))) + " mm"
                      : "")
              << "\n";
  }
}

void exportPattern(const Args& args, const std::vector<Garment>& garments, int chosen, const std::string& path) {
  const std::string out = args.option("--export-pattern");
  if (garments.empty()) throw FileError(path, "the scene has no garments");
  if (chosen < 0 && garments.size() > 1)
    throw Error("the scene has " + std::to_string(garments.size()) + " garments: choose one with --garment");
  const std::string ext = std::filesystem::path(out).extension().string();
  if (ext != ".svg" && ext != ".dxf") throw Error(out + ": --export-pattern writes .svg or .dxf");
  const float allowance = float(args.number("--seam-allowance", 0.0) / 1000.0);
  const Garment& garment = garments[size_t(std::max(chosen, 0))];
  if (ext == ".svg")
    writePatternSvg(out, garment, {allowance});
  else
    writePatternDxf(out, garment, {allowance});
  std::cout << "wrote the pattern of " << garment.name << " (" << garment.panels.size() << " panels, "
            << garment.seams.size() << " seams) to " << out << "\n";
}

// The DXF pattern becomes a new garment of the scene, saved as another document.
void importPattern(const Args& args, SceneDocument document, std::vector<Garment> garments, const std::string& path) {
  const std::string in = args.option("--import-pattern"), out = args.option("--save-as");
  if (out.empty()) throw Error("--import-pattern needs --save-as OUT.mqscene (the scene with the new garment)");
  if (!isSceneDocumentPath(out)) throw FileError(out, "--save-as writes a scene document (.mqscene or .json)");
  Garment garment = readPatternDxf(in);
  std::string name = garment.name;
  for (int n = 2; std::any_of(garments.begin(), garments.end(), [&](const Garment& g) { return g.name == name; }); ++n)
    name = garment.name + " " + std::to_string(n);
  garment.name = name;
  garments.push_back(garment);
  document.garments = garmentsToJson(garments);
  rebaseDocumentPaths(document, path, out);
  saveSceneDocument(document, out);
  std::cout << "imported " << garment.name << " (" << garment.panels.size() << " panels, " << garment.seams.size()
            << " seams) from " << in << "; saved the scene as " << out << "\n";
}

int runGarment(const std::vector<std::string>& argv) {
  const Args args(argv);
  args.allowOnly({"--garment", "--export-pattern", "--seam-allowance", "--json", "--import-pattern", "--save-as"});
  if (args.positional().size() != 1) throw Error("garment needs exactly one SCENE argument");
  const std::string path = args.positional()[0];
  if (!isSceneDocumentPath(path)) throw FileError(path, "garment needs a scene document (.mqscene or .json)");
  const SceneDocument document = loadSceneDocument(path);
  std::vector<Garment> garments;
  try {
    garments = garmentsFromJson(document.garments);
  } catch (const FileError&) {
    throw;
  } catch (const Error& e) {
    throw FileError(path, e.what());
  }
  const int chosen = chosenGarment(args, garments, path);

  if (args.has("--import-pattern")) {
    importPattern(args, document, garments, path);
    return 0;
  }
  if (args.has("--export-pattern")) {
    exportPattern(args, garments, chosen, path);
    return 0;
  }
  if (args.has("--json")) {
    nlohmann::json list = nlohmann::json::array();
    for (size_t i = 0; i < garments.size(); ++i)
      if (chosen < 0 || int(i) == chosen) list.push_back(garmentJson(garments[i]));
    std::cout << std::setw(2) << nlohmann::json{{"scene", path}, {"garments", list}} << "\n";
    return 0;
  }
  if (garments.empty()) std::cout << path << ": no garments\n";
  for (size_t i = 0; i < garments.size(); ++i)
    if (chosen < 0 || int(i) == chosen) printGarment(i, garments[i]);
  return 0;
}

Registration reg({"garment",
                  "SCENE [--garment N|NAME] [--json] [--export-pattern OUT.svg|OUT.dxf [--seam-allowance MM]] "
                  "[--import-pattern IN.dxf --save-as OUT.mqscene]",
                  "a scene's garments as patterns: panels, seams and the sewn edges' lengths (a warning where "
                  "they differ by more than 5 mm); --export-pattern writes one garment's pattern as SVG or DXF "
                  "(AAMA layers) at 1:1 in mm, with the cutting line MM outside the sewing line if asked; "
                  "--import-pattern adds the panels and seams of a DXF pattern to the scene as a new garment",
                  runGarment});

}  // namespace
}  // namespace mq::cli
