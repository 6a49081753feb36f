#include "core/mesh/inward_thickness.h"

#include <glm/glm.hpp>

#include "core/mesh/mesh.h"
#include "core/mesh/triangle_ray_caster.h"

namespace mq {

std::vector<float> inwardThickness(const std::vector<float>& positions, const std::vector<float>& normals,
                                   const std::vector<uint32_t>& triangles, float missing) {
  const size_t n = positions.size() / 3;
  std::vector<float> thickness(n, missing);
  if (normals.size() != positions.size()) return thickness;
  Aabb box;
  for (size_t v = 0; v < n; ++v) box.extend({positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]});
  // Past the triangles around the ray's own vertex and its seam twins.
  const float minDistance = 1e-5f * box.diagonal();
  const TriangleRayCaster caster(positions, triangles);
  for (size_t v = 0; v < n; ++v) {
    const glm::vec3 p(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
    const glm::vec3 normal(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
    if (glm::dot(normal, normal) < 1e-20f) continue;
    const float hit = caster.firstHit(p, -glm::normalize(normal), minDistance, int64_t(v));
    if (hit > 0.0f) thickness[v] = hit;
  }
  return thickness;
}

}  // namespace mq
