#include "core/garment/pin_remap.h"

#include <algorithm>
#include <limits>

#include <glm/glm.hpp>

namespace mq {

namespace {

struct PanelBounds {
  glm::vec2 min{std::numeric_limits<float>::max()};
  glm::vec2 max{std::numeric_limits<float>::lowest()};
  glm::vec2 extent() const { return glm::max(max - min, glm::vec2(1e-6f)); }
};

glm::vec2 uvOf(const GarmentMesh& mesh, size_t v) { return {mesh.restUvs[2 * v], mesh.restUvs[2 * v + 1]}; }

bool hasPatterns(const GarmentMesh& mesh) {
  return mesh.panelIds.size() == mesh.vertexCount() && mesh.restUvs.size() == 2 * mesh.vertexCount();
}

std::vector<PanelBounds> panelBounds(const GarmentMesh& mesh) {
  std::vector<PanelBounds> bounds;
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    const size_t panel = mesh.panelIds[v];
    if (panel >= bounds.size()) bounds.resize(panel + 1);
    bounds[panel].min = glm::min(bounds[panel].min, uvOf(mesh, v));
    bounds[panel].max = glm::max(bounds[panel].max, uvOf(mesh, v));
  }
  return bounds;
}

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
    if (!patterns || panel >= boundsAfter.size() || boundsAfter[panel].min.x > boundsAfter[panel].max.x) {
      out.push_back(nearestInRestPose(after, before.position(pin)));
      continue;
    }
    // Where the pin sits in its panel (0..1 across the pattern's bounds), in the rebuilt panel's metres.
    const PanelBounds& from = boundsBefore[panel];
    const PanelBounds& to = boundsAfter[panel];
    const glm::vec2 wanted = to.min + (uvOf(before, pin) - from.min) / from.extent() * to.extent();
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
