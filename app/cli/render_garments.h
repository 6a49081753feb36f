#pragma once
// The garments of a scene in `mannequin-cli render`: each garment is sewn on
// the character and simulated up to the render time (DrapeSchedule: sewing
// at the rest pose, a blend to the clip's first pose, then the clip), then
// drawn with the cloth shading of its fabric. Once draped, the garments step
// together, each worn over those of lower layers (sim/garment/garment_layers.h).

#include <memory>
#include <string>
#include <vector>

#include "core/scene/open_scene.h"

namespace mq::render {
class ClothActor;
class SceneView;
}  // namespace mq::render

namespace mq::cli {

struct RenderedGarments {
  std::vector<std::unique_ptr<render::ClothActor>> actors;  // keep alive until the image is rendered
  std::string summary;                                      // "T-shirt (5061 vertices, 62 steps)"
  RenderedGarments();
  ~RenderedGarments();
  RenderedGarments(RenderedGarments&&) noexcept;
};

// Adds the scene's garments to `view` as they are at `time` of `clip` (-1:
// the rest pose). Throws FileError(file, ...) for bad garment sections and
// when the cloth diverges.
RenderedGarments addSceneGarments(render::SceneView& view, const LoadedScene& scene, int clip, float time,
                                  const std::string& file);

}  // namespace mq::cli
