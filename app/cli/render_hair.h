#pragma once
// The hair part of `mannequin-cli render`: the scene's hairstyle groomed on
// its character and drawn with render::HairActor, posed at the render time.

#include <memory>
#include <optional>
#include <string>

#include "core/hair/hairstyle.h"
#include "core/scene/open_scene.h"

namespace mq::render {
class HairActor;
class SceneView;
}  // namespace mq::render

namespace mq::cli {

// How the strands reach the pose at the render time:
//   simulate: the guides are simulated from the clip's start (0.5 s of
//             settling there, then 60 steps per second) to the time, the
//             children follow them;
//   rigid:    the groom is carried by the head bone (no dynamics);
//   auto:     simulate when a clip plays, rigid otherwise; off: no hair.
enum class HairRenderMode { Auto, Simulate, Rigid, Off };
HairRenderMode parseHairRenderMode(const std::string& name);  // throws mq::Error

// --hair-shadow count|maps: the self-shadowing term (render/hair_actor.h),
// the exact per-column count or opacity shadow maps.
// --hair-shader kajiya-kay|physical, --hair-pigment black|brown|blond|red|grey,
// --melanin M, --pheomelanin P, --hair-roughness R: override the style's
// "shading" (a pigment or a concentration implies physical).
struct HairRenderOptions {
  HairRenderMode mode = HairRenderMode::Auto;
  bool opacityShadowMaps = false;
  std::optional<HairShadingModel> model;
  std::optional<std::string> pigment;
  std::optional<float> melanin, pheomelanin, roughness;
  // The style's shading with these overrides.
  HairShadingParams shadingFor(HairShadingParams style) const;
};
HairRenderOptions parseHairRenderOptions(const std::string& mode, const std::string& shadow);  // throws mq::Error

// Adds the hair of `scene` (none without a "hair" section) to `view` for
// clip `clip` at `time`. Returns the actor, which must outlive the
// rendering, or null; `summary` gets a short description for the user.
std::unique_ptr<render::HairActor> addSceneHair(render::SceneView& view, const LoadedScene& scene, int clip, float time,
                                                const HairRenderOptions& options, std::string& summary);

}  // namespace mq::cli
