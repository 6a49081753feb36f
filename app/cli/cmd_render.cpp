// mannequin-cli render: an image of a character or scene, without a window.
#include <cstdio>
#include <iostream>

#include "app/cli/command.h"
#include "app/cli/render_garments.h"
#include "app/cli/render_hair.h"
#include "core/character/posed_character.h"
#include "core/hair/hairstyle_json.h"
#include "core/scene/open_scene.h"
#include "core/util/error.h"
#include "core/util/thread_pool.h"
#include "render/hair_actor.h"
#include "render/offscreen.h"
#include "render/scene_view.h"

namespace mq::cli {
namespace {

struct ImageSize {
  int width = 960;
  int height = 720;
};

ImageSize parseSize(const std::string& text) {
  ImageSize size;
  char x = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &size.width, &x, &size.height, &rest) != 3 || (x != 'x' && x != 'X') ||
      size.width < 16 || size.height < 16 || size.width > 8192 || size.height > 8192)
    throw Error("--size expects WIDTHxHEIGHT between 16 and 8192, got '" + text + "'");
  return size;
}

render::LookMode parseLook(const std::string& name) {
  render::LookMode mode = render::LookMode::Auto;
  if (!render::parseLookMode(name, mode))
    throw Error("--look expects auto, skin, mannequin or plain, got '" + name + "'");
  return mode;
}

void placeCamera(render::SceneView& view, const ViewSettings& settings, const ImageSize& size) {
  view.frameAll(static_cast<double>(size.width) / size.height);
  if (settings.hasCamera) view.setCamera(settings.cameraPosition, settings.cameraFocus);
}

int runRender(const std::vector<std::string>& argv) {
  const Args args(argv);
  args.allowOnly({"--out",
                  "--time",
                  "--clip",
                  "--size",
                  "--skeleton",
                  "--look",
                  "--scale",
                  "--auto-rig",
                  "--hair",
                  "--hair-shadow",
                  "--skinning",
                  "--helper-bones",
                  "--regenerate-weights",
                  "--smooth-weights",
                  "--hair-shader",
                  "--hair-pigment",
                  "--melanin",
                  "--pheomelanin",
                  "--hair-roughness",
                  "--skin-preset",
                  "--weights",
                  "--cones"});
  if (args.positional().size() != 1) throw Error("expects one FILE (or 'default'); see mannequin-cli --help");
  const std::string file = args.positional()[0];
  const std::string out = args.option("--out");
  if (out.empty()) throw Error("--out OUT.png is required");
  const ImageSize size = parseSize(args.option("--size", "960x720"));

  LoadedScene scene = openScene(file);
  printMotionMatch(scene);
  applyCharacterOptions(args, scene);
  applySkinningOption(args, scene);
  if (scene.character.skeleton.boneCount() == 0 && scene.character.meshes.empty())
    throw FileError(file, "has no character to render");
  const int clip = clipOption(args, scene, file);
  const float time = static_cast<float>(args.number("--time", scene.document.time));

  PosedCharacter posed;
  posed.evaluate(scene.character, clip, time, &scene.edits, &ThreadPool::shared());
  render::SceneView view;
  view.setCharacter(scene.character);
  view.updatePose(posed);
  // The skin's scattering profile and colour, where skin is shown (--look
  // skin, materials marked as skin); an unknown name lists the presets.
  if (args.has("--skin-preset")) view.setSkinLook(render::SurfaceLook::skinPresetLook(args.option("--skin-preset")));
  view.setLookMode(parseLook(args.option("--look", scene.document.view.look)));
  if (args.has("--weights")) {
    const std::string name = args.option("--weights");
    const int bone = scene.character.skeleton.findBone(name);
    if (bone < 0) throw Error("--weights: '" + scene.character.name + "' has no bone named '" + name + "'");
    view.setVertexHeat(boneWeights(scene.character, bone));
  }
  if (args.has("--cones") || scene.document.view.showCones) view.showSectionCones(scene.character);
  for (const std::string& warning : loadNotices(scene)) std::cerr << "warning: " << warning << "\n";
  for (const std::string& warning : view.warnings()) std::cerr << "warning: " << warning << "\n";
  // A motion file alone (no meshes) shows its skeleton.
  view.setSkeletonVisible(args.has("--skeleton") || scene.document.view.showSkeleton || scene.character.meshes.empty());
  const RenderedGarments garments = addSceneGarments(view, scene, clip, time, file);
  view.setAmbientOcclusion(true);
  placeCamera(view, scene.document.view, size);
  std::string hairSummary;
  HairRenderOptions hairOptions =
      parseHairRenderOptions(args.option("--hair", "auto"), args.option("--hair-shadow", "count"));
  if (args.has("--hair-shader")) hairOptions.model = hairShadingModelFromName(args.option("--hair-shader"));
  if (args.has("--hair-pigment")) hairOptions.pigment = args.option("--hair-pigment");
  if (args.has("--melanin")) hairOptions.melanin = float(args.number("--melanin", 0.0));
  if (args.has("--pheomelanin")) hairOptions.pheomelanin = float(args.number("--pheomelanin", 0.0));
  if (args.has("--hair-roughness")) hairOptions.roughness = float(args.number("--hair-roughness", 0.3));
  const auto hair = addSceneHair(view, scene, clip, time, hairOptions, hairSummary);
  render::renderToPng(view, out, size.width, size.height);
  std::cout << "wrote " << out << " (" << size.width << "x" << size.height << ", "
            << (clip >= 0 ? "clip '" + scene.character.clips[clip].name + "' at t=" + std::to_string(time)
                          : std::string("rest pose"))
            << (hairSummary.empty() ? "" : "; " + hairSummary) << ")"
            << (garments.summary.empty() ? "" : ", garments: " + garments.summary) << "\n";
  return 0;
}

Registration reg({"render",
                  "FILE --out OUT.png [--time T] [--clip NAME|INDEX|rest] [--size WxH] [--skeleton]\n"
                  "         [--look auto|skin|mannequin|plain] [--hair auto|simulate|rigid|off]\n"
                  "         [--hair-shadow count|maps] [--skinning lbs|dqs|cones] [--helper-bones] "
                  "[--regenerate-weights] [--smooth-weights] [--scale S] [--auto-rig]\n"
                  "         [--skin-preset skin1|skin2|light|medium|tan|dark]\n"
                  "         [--hair-shader kajiya-kay|physical] [--hair-pigment black|brown|blond|red|grey]\n"
                  "         [--melanin M] [--pheomelanin P] [--hair-roughness R] [--weights BONE] [--cones]",
                  "renders an image offscreen (starts a private Xvfb when there is no X display)", runRender});

}  // namespace
}  // namespace mq::cli
