#include "core/garment/pin_remap.h"

#include <algorithm>
#include <limits>

#include <glm/glm.hpp>

#include "core/garment/panel_coordinates.h"

namespace mq {

namespace {

using namespace panel_coordinates;

uint32_t nearestInRestPose(const GarmentMesh& mesh, glm::vec3 p) {
  uint32_t best = 0;
  float bestDistance = std::numeric_limits<float>::max();
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    const glm::vec3 d = mesh.position(v) - p;
    if (glm::dot(d, d) < bestDistance) bestDistance = glm::dot(d, d), best = uint32_t(v);
  }
  return best;
}

}  // namespace

std::vector<uint32_t> remapPins(const GarmentMesh& before, const std::vector<uint32_t>& pins,
                                const GarmentMesh& after) {
  std::vector<uint32_t> out;
  if (after.vertexCount() == 0) return out;
  const bool patterns = hasPatterns(before) && hasPatterns(after);
  const std::vector<PanelBounds> boundsBefore = patterns ? panelBounds(before) : std::vector<PanelBounds>{};
  const std::vector<PanelBounds> boundsAfter = patterns ? panelBounds(after) : std::vector<PanelBounds>{};
  for (uint32_t pin : pins) {
    if (pin >= before.vertexCount()) continue;
    const size_t panel = patterns ? before.panelIds[pin] : 0;
    if (!patterns || panel >= boundsAfter.size() || boundsAfter[panel].empty()) {
      out.push_back(nearestInRestPose(after, before.position(pin)));
      continue;
    }
    // Where the pin sits in its panel (0..1 across the pattern's bounds), in the rebuilt panel's metres.
    const glm::vec2 wanted = samePlace(uvOf(before, pin), boundsBefore[panel], boundsAfter[panel]);
    uint32_t best = 0;
    float bestDistance = std::numeric_limits<float>::max();
    for (size_t v = 0; v < after.vertexCount(); ++v) {
      if (after.panelIds[v] != panel) continue;
      const glm::vec2 d = uvOf(after, v) - wanted;
      if (glm::dot(d, d) < bestDistance) bestDistance = glm::dot(d, d), best = uint32_t(v);
    }
    out.push_back(best);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace mq
