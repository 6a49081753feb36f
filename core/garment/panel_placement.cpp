#include "core/garment/panel_placement.h"

#include <cmath>

namespace mq {

glm::vec3 PanelPlacement::place(glm::vec2 p) const {
  glm::vec2 d = p - anchor;
  if (shape == Shape::Plane) return center + side() * d.x + axis * d.y;
  float angle = d.x / radius;
  return center + axis * d.y + radius * (std::cos(angle) * facing + std::sin(angle) * side());
}

}  // namespace mq
