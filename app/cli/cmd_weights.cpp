// mannequin-cli weights FILE [--regenerate] [--smooth] [--helper-bones]
//     [--transition L] [--axial-weight A] [--passes N] --out OUT.glb|.gltf|.mqscene
// Rebuilds the skin weights (core/skinning/weight_regeneration.h) and writes
// them: into a rigged glTF (plain LBS with the new weights and the helper
// bones baked, for any engine), or into a scene document that keeps the
// settings, so the editor and every command rebuild the same weights.
#include <iostream>

#include "app/cli/command.h"
#include "core/io/rigged_export.h"
#include "core/scene/open_scene.h"
#include "core/scene/scene_document.h"
#include "core/skinning/weight_regeneration.h"
#include "core/util/error.h"
#include "core/util/thread_pool.h"

namespace mq::cli {
namespace {

WeightSettings settingsFrom(const Args& args, WeightSettings settings) {
  settings.regenerate |= args.has("--regenerate");
  settings.smooth |= args.has("--smooth");
  settings.axialWeight = args.number("--axial-weight", settings.axialWeight);
  settings.transition = args.number("--transition", settings.transition);
  const double passes = args.number("--passes", settings.passes);
  if (!(settings.axialWeight >= 0.0 && settings.axialWeight <= WeightSettings::kMaxAxialWeight))
    throw Error("--axial-weight must be between 0 and 100");
  if (!(settings.transition >= WeightSettings::kMinTransition && settings.transition <= WeightSettings::kMaxTransition))
    throw Error("--transition must be between 0.05 and 20");
  if (!(passes >= 1.0 && passes <= WeightSettings::kMaxPasses) || passes != static_cast<int>(passes))
    throw Error("--passes must be a whole number between 1 and 10000");
  settings.passes = static_cast<int>(passes);
  return settings;
}

int runWeights(const std::vector<std::string>& argv) {
  const Args args(argv);
  args.allowOnly({"--out", "--regenerate", "--smooth", "--helper-bones", "--transition", "--axial-weight", "--passes",
                  "--fps", "--scale", "--auto-rig"});
  if (args.positional().size() != 1) throw Error("weights needs exactly one FILE");
  const std::string out = args.option("--out");
  const bool toScene = isSceneDocumentPath(out);
  if (out.empty() || !(toScene || isRiggedExportPath(out)))
    throw Error("weights needs --out OUT.glb, OUT.gltf (a rigged character) or OUT.mqscene (a scene document)");
  LoadedScene scene = openScene(args.positional()[0]);
  applyCharacterOptions(args, scene);
  if (scene.character.meshes.empty() || scene.character.maxInfluences() == 0)
    throw Error("'" + scene.character.name + "' has no skinned mesh whose weights could be rebuilt");
  const WeightSettings settings = settingsFrom(args, scene.document.weights);
  if (!settings.active() && !args.has("--helper-bones"))
    throw Error("weights needs --regenerate, --smooth or --helper-bones (what to do to the weights)");
  if (settings != scene.document.weights) {
    std::cout << regenerateWeights(scene.character, settings, &ThreadPool::shared()).summary() << "\n";
    scene.document.weights = settings;
  }
  applySkinningOption(args, scene);  // --helper-bones, after the weights

  if (toScene) {
    SceneDocument document = scene.document;
    if (scene.documentPath.empty() && args.positional()[0] != "default") document.character = args.positional()[0];
    rebaseDocumentPaths(document, scene.documentPath, out);
    saveSceneDocument(document, out);
    std::cout << "wrote " << out << " (scene document: the weights are rebuilt when it opens)\n";
    return 0;
  }
  const double fps = args.number("--fps", 30.0);
  if (!(fps > 0.0 && fps <= 1000.0)) throw Error("--fps must be in (0, 1000]");
  exportRiggedCharacter(scene.character, out, static_cast<float>(fps));
  std::cout << "wrote " << out << " (rigged: " << scene.character.skeleton.boneCount() << " bones"
            << withHelperBones(scene.character) << ", " << scene.character.clips.size() << " clips)\n";
  return 0;
}

static Registration reg(
    {"weights",
     "FILE [--regenerate] [--smooth] [--helper-bones] [--transition L] [--axial-weight A] [--passes N]\n"
     "         [--scale S] [--auto-rig] --out OUT.glb|OUT.gltf|OUT.mqscene [--fps F]",
     "rebuild the skin weights (the survey's regeneration and smoothing) and write them as a rigged glTF\n"
     "or into a scene document",
     runWeights,
     "--regenerate  one bone per vertex by its distance to each bone's cylinder (bones it sees from\n"
     "              inside the skin), then blended over L section radii at each joint (--transition,\n"
     "              default 2; --axial-weight A weighs the distance past a bone's ends, default 0.5)\n"
     "--smooth      bounds how fast a weight may change along the skin by the same lengths\n"
     "              (at most N passes, default 64); on its own it smooths the file's weights\n"
     "--helper-bones  half-angle and twist bones at the joints, after the weights\n"
     "A glTF gets the weights and helper bones baked (plain LBS in any engine, clips sampled at F fps,\n"
     "30 by default); a scene document records the settings, and the weights are rebuilt when it opens."});

}  // namespace
}  // namespace mq::cli
