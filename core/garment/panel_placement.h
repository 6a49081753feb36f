#pragma once
// Where a flat panel sits around the body before sewing: wrapped onto a
// cylinder around a bone (an isometry, so rest lengths are those of the
// pattern) or laid on a plane. Pattern u runs around the cylinder (or along
// `side` on a plane), pattern v runs along `axis`.

#include <string>

#include <glm/glm.hpp>

namespace mq {

struct PanelPlacement {
  enum class Shape { Plane, Cylinder };
  Shape shape = Shape::Plane;
  std::string bone;                    // the bone it was placed around (informative)
  glm::vec3 center{0.0f};              // cylinder: a point on its axis; plane: where `anchor` lands
  glm::vec3 axis{0.0f, 1.0f, 0.0f};    // world direction of pattern +v (unit)
  glm::vec3 facing{0.0f, 0.0f, 1.0f};  // outward direction at u = anchor.x (unit, normal to axis)
  float radius = 0.2f;                 // cylinder radius
  glm::vec2 anchor{0.0f};              // pattern point that lands at `center` (+ radius * facing)

  // World direction of pattern +u at the anchor: axis x facing, so that
  // counter-clockwise pattern triangles face outward.
  glm::vec3 side() const { return glm::cross(axis, facing); }
  glm::vec3 place(glm::vec2 patternPoint) const;
};

}  // namespace mq
