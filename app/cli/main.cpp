// mannequin-cli: the editor's work without a window.
#include <algorithm>
#include <cstdlib>
#include <iostream>

#include "app/cli/command.h"

#include "core/character/auto_rig.h"
#include "core/character/posed_character.h"
#include "core/io/json_fields.h"
#include "core/scene/open_scene.h"
#include "core/skinning/section_cones.h"
#include "core/skinning/weight_regeneration.h"
#include "core/util/error.h"
#include "core/util/thread_pool.h"

namespace mq::cli {

std::vector<Command>& commands() {
  static std::vector<Command> all;
  return all;
}

Args::Args(const std::vector<std::string>& args) {
  // Flags that take no value; everything else starting with -- takes one.
  static const std::vector<std::string> flags = {"--json",
                                                 "--help",
                                                 "--skeleton",
                                                 "--no-hair",
                                                 "--no-cloth",
                                                 "--self-collisions",
                                                 "--no-poses",
                                                 "--no-clips",
                                                 "--no-intersections",
                                                 "--in-place",
                                                 "--helper-bones",
                                                 "--rigged",
                                                 "--regenerate-weights",
                                                 "--smooth-weights",
                                                 "--regenerate",
                                                 "--smooth",
                                                 "--cones",
                                                 "--auto-rig",
                                                 "--mirror",
                                                 "--hair-crossings"};
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--", 0) == 0 && a.size() > 2) {
      const auto eq = a.find('=');
      if (eq != std::string::npos)
        options_.emplace_back(a.substr(0, eq), a.substr(eq + 1));
      else if (std::find(flags.begin(), flags.end(), a) != flags.end() || i + 1 >= args.size())
        options_.emplace_back(a, "");
      else
        options_.emplace_back(a, args[++i]);
    } else {
      positional_.push_back(a);
    }
  }
}

std::string Args::option(const std::string& name, const std::string& fallback) const {
  for (const auto& [k, v] : options_)
    if (k == name) {
      if (v.empty()) throw Error("option " + name + " needs a value");
      return v;
    }
  return fallback;
}

bool Args::has(const std::string& name) const {
  return std::any_of(options_.begin(), options_.end(), [&](const auto& o) { return o.first == name; });
}

double Args::number(const std::string& name, double fallback) const {
  const std::string v = option(name);
  if (v.empty()) return fallback;
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (!end || *end != '\0') throw Error("option " + name + " expects a number, got '" + v + "'");
  return d;
}

void Args::allowOnly(const std::vector<std::string>& known) const {
  for (const auto& [k, v] : options_)
    if (std::find(known.begin(), known.end(), k) == known.end()) throw Error("unknown option " + k);
}

void applySkinningOption(const Args& args, LoadedScene& scene) {
  WeightSettings weights = scene.document.weights;
  weights.regenerate |= args.has("--regenerate-weights");
  weights.smooth |= args.has("--smooth-weights");
  if (weights != scene.document.weights) {
    std::cerr << regenerateWeights(scene.character, weights, &ThreadPool::shared()).summary() << "\n";
    scene.document.weights = weights;
    prepareSkinning(scene.character);
  }
  if (args.has("--helper-bones") && scene.character.helperBones.empty()) {
    std::string why;
    if (addHelperBones(scene.character, &why) == 0) throw Error("--helper-bones: " + why);
    scene.document.helperBones = true;
    prepareSkinning(scene.character);
  }
  if (!args.has("--skinning")) return;
  const std::string name = args.option("--skinning");
  const auto method = parseSkinningMethod(name);
  if (!method) throw Error("--skinning: unknown method '" + name + "' (expected " + skinningMethodChoices() + ")");
  scene.character.skinning = *method;
  scene.document.skinning = *method;
  prepareSkinning(scene.character);
}

std::string withHelperBones(const Character& character) {
  if (character.helperBones.empty()) return {};
  return " with " + std::to_string(character.helperBones.size()) + " helper bones";
}

void applyCharacterOptions(const Args& args, LoadedScene& scene) {
  if (args.has("--scale")) {
    const double factor = args.number("--scale", 1.0);
    if (!(factor > 0.0) || !std::isfinite(factor) || factor > 1e4) throw Error("--scale expects a positive number");
    scene.character.scaleUniformly(static_cast<float>(factor));
    scene.document.scale *= static_cast<float>(factor);
  }
  if (args.has("--auto-rig") && !scene.document.autoRig) {
    try {
      autoRigHumanoid(scene.character, true, &ThreadPool::shared());
    } catch (const Error& e) {
      throw Error(std::string("--auto-rig: ") + e.what());
    }
    scene.document.autoRig = true;
    scene.fileSkins.clear();
    for (const Mesh& mesh : scene.character.meshes) scene.fileSkins.push_back(mesh.skin);
  }
  prepareSkinning(scene.character);
}

int clipOption(const Args& args, const LoadedScene& scene, const std::string& file) {
  if (!args.has("--clip")) return scene.clipIndex;
  const std::string wanted = args.option("--clip");
  if (wanted == "rest") return -1;
  const int clip = scene.character.findClip(wanted);
  if (clip >= 0) return clip;
  std::string names;
  for (const Clip& c : scene.character.clips) names += (names.empty() ? "" : ", ") + c.name;
  throw FileError(file, "no clip '" + wanted + "' (clips: " + (names.empty() ? "none" : names) + ")");
}

std::string clipLabel(const LoadedScene& scene, int clip) {
  if (clip < 0 || clip >= int(scene.character.clips.size())) return "the rest pose";
  return "clip '" + scene.character.clips[clip].name + "'";
}

void printMotionMatch(const std::string& bvhPath, const BoneMatchReport& match) {
  std::cerr << "motion " << bvhPath << ": " << match.summary() << "\n";
}

void printMotionMatch(const LoadedScene& scene) {
  if (scene.motionMatch) printMotionMatch(scene.document.motionFile, *scene.motionMatch);
}

}  // namespace mq::cli

namespace {

void printUsage(std::ostream& out) {
  out << "usage: mannequin-cli <command> [arguments]   (mannequin-cli <command> --help: its options;\n"
         "       mannequin-cli --version)\n\n"
         "FILE is a character file (glTF, GLB, FBX, DAE, BVH), a scene document, or the word\n"
         "'default' for the built-in mannequin.\n\ncommands:\n";
  auto all = mq::cli::commands();
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  for (const auto& c : all) out << "  " << c.name << " " << c.usage << "\n      " << c.summary << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    printUsage(std::cout);
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version" || args[0] == "version") {
    std::cout << "mannequin-cli " << MANNEQUIN_VERSION
              << "\nLicence: GPL-3.0-or-later (it links CGAL's GPL packages); see LICENSE.\n";
    return 0;
  }
  for (const auto& c : mq::cli::commands()) {
    if (c.name != args[0]) continue;
    if (std::find(args.begin() + 1, args.end(), "--help") != args.end() ||
        std::find(args.begin() + 1, args.end(), "-h") != args.end()) {
      std::cout << "usage: mannequin-cli " << c.name << " " << c.usage << "\n\n" << c.summary << "\n";
      if (!c.details.empty()) std::cout << "\n" << c.details << "\n";
      return 0;
    }
    try {
      return c.run(std::vector<std::string>(args.begin() + 1, args.end()));
    } catch (const mq::Error& e) {
      std::cerr << "mannequin-cli " << c.name << ": error: " << e.what() << "\n";
      return 1;
    } catch (const std::bad_alloc&) {
      std::cerr << "mannequin-cli " << c.name
                << ": error: out of memory (the input asks for more than this machine has)\n";
      return 1;
    } catch (const std::exception& e) {
      std::cerr << "mannequin-cli " << c.name << ": internal error: " << mq::jsonProblem(e) << "\n";
      return 3;
    }
  }
  std::cerr << "mannequin-cli: unknown command '" << args[0] << "'\n";
  printUsage(std::cerr);
  return 2;
}
