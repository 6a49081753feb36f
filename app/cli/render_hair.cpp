#include "app/cli/render_hair.h"

#include <algorithm>
#include <cmath>

#include "app/cli/scene_hair.h"
#include "core/optics/hair_bsdf.h"
#include "core/util/error.h"
#include "render/hair_actor.h"
#include "render/scene_view.h"

namespace mq::cli {
namespace {

constexpr float kRenderFps = 60.0f;
constexpr float kSettleSeconds = 0.5f;

// Steps from the clip's start to `time` and returns the strands there.
const std::vector<float>& simulateTo(SceneHair& hair, float clipStart, float time) {
  const float start = std::min(clipStart, time);
  hair.settle(start, kSettleSeconds, kRenderFps);
  const int steps = int(std::lround((time - start) * kRenderFps));
  for (int i = 1; i <= steps; ++i)
    hair.step(start + (time - start) * float(i) / float(steps), (time - start) / float(steps));
  if (steps == 0) hair.step(time, 1.0f / kRenderFps);
  return hair.updateAllStrands();
}

}  // namespace

HairRenderMode parseHairRenderMode(const std::string& name) {
  if (name == "auto") return HairRenderMode::Auto;
  if (name == "simulate") return HairRenderMode::Simulate;
  if (name == "rigid") return HairRenderMode::Rigid;
  if (name == "off") return HairRenderMode::Off;
  throw Error("--hair expects auto, simulate, rigid or off, got '" + name + "'");
}

HairRenderOptions parseHairRenderOptions(const std::string& mode, const std::string& shadow) {
  HairRenderOptions options;
  options.mode = parseHairRenderMode(mode);
  if (shadow != "count" && shadow != "maps") throw Error("--hair-shadow expects count or maps, got '" + shadow + "'");
  options.opacityShadowMaps = shadow == "maps";
  return options;
}

HairShadingParams HairRenderOptions::shadingFor(HairShadingParams style) const {
  if (pigment) {
    const optics::HairPigment p = optics::hairPigmentPreset(*pigment);
    style.melanin = float(p.eumelanin);
    style.pheomelanin = float(p.pheomelanin);
  }
  if (melanin) style.melanin = *melanin;
  if (pheomelanin) style.pheomelanin = *pheomelanin;
  if (roughness) style.roughness = *roughness;
  if (pigment || melanin || pheomelanin || roughness) style.model = HairShadingModel::Physical;
  if (model) style.model = *model;
  if (style.melanin < 0.0f || style.pheomelanin < 0.0f) throw Error("--melanin and --pheomelanin must be >= 0");
  if (!(style.roughness >= 0.05f && style.roughness <= 1.0f)) throw Error("--hair-roughness must be in 0.05..1");
  return style;
}

std::unique_ptr<render::HairActor> addSceneHair(render::SceneView& view, const LoadedScene& scene, int clip, float time,
                                                const HairRenderOptions& options, std::string& summary) {
  HairRenderMode mode = options.mode;
  if (mode == HairRenderMode::Off || !sceneHasHair(scene)) return nullptr;
  const bool hasClip = clip >= 0 && clip < int(scene.character.clips.size());
  if (mode == HairRenderMode::Auto) mode = hasClip ? HairRenderMode::Simulate : HairRenderMode::Rigid;
  SceneHair hair(scene, sceneHairSection(scene));
  hair.setClip(clip);
  auto actor = std::make_unique<render::HairActor>();
  actor->setColors(hair.style().rootColor, hair.style().tipColor);
  const HairShadingParams fibre = options.shadingFor(hair.style().shading);
  actor->setFibre(fibre);
  if (options.opacityShadowMaps) {
    render::HairShading shading = actor->shading();
    shading.shadowMethod = render::HairShadowMethod::OpacityMaps;
    actor->setShading(shading);
  }
  actor->setStrands(hair.groom().strands());  // after the fibre: its painted pigments' tints
  const bool simulate = mode == HairRenderMode::Simulate;
  actor->updatePositions(simulate ? simulateTo(hair, hasClip ? scene.character.clips[clip].startTime() : time, time)
                                  : hair.rigidStrands(time));
  view.add(*actor);
  summary = "hair " + hair.style().name + ", " + std::to_string(hair.groom().strands().strandCount()) + " strands, " +
            (simulate ? "simulated to the time" : "carried by the head") +
            (fibre.model == HairShadingModel::Physical
                 ? ", physical shading (melanin " + std::to_string(fibre.melanin).substr(0, 4) + ", pheomelanin " +
                       std::to_string(fibre.pheomelanin).substr(0, 4) + ")"
                 : "");
  return actor;
}

}  // namespace mq::cli
