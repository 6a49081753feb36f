#pragma once
// Response of a cloth vertex to a contact with a surface moving at velocity
// `surfaceVelocity` (the survey's repulsion): the vertex is put back at the
// surface offset by `depth` along the outward normal; a velocity approaching
// the surface loses its normal part (inelastic) and its tangential part
// shrinks by friction * |normal part| (Coulomb); a separating velocity is
// kept (elastic), so cloth lifts off freely.

#include <glm/glm.hpp>

namespace mq::cloth {

inline void respondToContact(glm::vec3& x, glm::vec3& v, const glm::vec3& normal, float depth,
                             const glm::vec3& surfaceVelocity, float friction) {
  x += depth * normal;
  glm::vec3 rel = v - surfaceVelocity;
  const float vn = glm::dot(rel, normal);
  if (vn >= 0.0f) return;
  rel -= vn * normal;
  const float tangential = glm::length(rel);
  const float kept = tangential > 0.0f ? glm::max(0.0f, 1.0f - friction * (-vn) / tangential) : 0.0f;
  v = surfaceVelocity + kept * rel;
}

}  // namespace mq::cloth
