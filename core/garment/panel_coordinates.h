#pragma once
// Where a garment-mesh vertex sits in its panel's pattern, relative to the
// panel's bounds: what a rebuilt mesh (another measurement, another particle
// distance) and the old one have in common, for carrying pins and drapes
// from one to the other.

#include <algorithm>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "core/garment/garment.h"

namespace mq::panel_coordinates {

struct PanelBounds {
  glm::vec2 min{std::numeric_limits<float>::max()};
  glm::vec2 max{std::numeric_limits<float>::lowest()};
  glm::vec2 extent() const { return glm::max(max - min, glm::vec2(1e-6f)); }
  bool empty() const { return min.x > max.x; }
};

inline glm::vec2 uvOf(const GarmentMesh& mesh, size_t v) { return {mesh.restUvs[2 * v], mesh.restUvs[2 * v + 1]}; }

// The mesh has pattern coordinates and panel ids for every vertex.
inline bool hasPatterns(const GarmentMesh& mesh) {
  return mesh.panelIds.size() == mesh.vertexCount() && mesh.restUvs.size() == 2 * mesh.vertexCount();
}

inline std::vector<PanelBounds> panelBounds(const GarmentMesh& mesh) {
  std::vector<PanelBounds> bounds;
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    const size_t panel = mesh.panelIds[v];
    if (panel >= bounds.size()) bounds.resize(panel + 1);
    bounds[panel].min = glm::min(bounds[panel].min, uvOf(mesh, v));
    bounds[panel].max = glm::max(bounds[panel].max, uvOf(mesh, v));
  }
  return bounds;
}

// A pattern point of panel bounds `from` at the same relative place in `to`.
inline glm::vec2 samePlace(glm::vec2 uv, const PanelBounds& from, const PanelBounds& to) {
  return to.min + (uv - from.min) / from.extent() * to.extent();
}

}  // namespace mq::panel_coordinates
