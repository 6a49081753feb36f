#pragma once
// Analytic solids: sphere, capsule (segment + radius) and plane (the half
// space below it is solid). signedDistance() is negative inside.
// Plain geometry, so that sim (cloth colliders) and render (their actors)
// share it without render depending on sim.

#include <glm/glm.hpp>

namespace mq {

struct SolidPrimitive {
  enum class Shape { Sphere, Capsule, Plane };
  Shape shape = Shape::Sphere;
  glm::vec3 a{0.0f};  // sphere centre, capsule end, or a point on the plane
  glm::vec3 b{0.0f};  // capsule other end, or the plane's normal
  float radius = 0.0f;
  float friction = -1.0f;  // < 0: use the cloth's friction

  static SolidPrimitive sphere(glm::vec3 centre, float radius);
  static SolidPrimitive capsule(glm::vec3 end0, glm::vec3 end1, float radius);
  static SolidPrimitive plane(glm::vec3 point, glm::vec3 normal);

  // Signed distance of p to the surface and the outward normal there.
  float signedDistance(const glm::vec3& p, glm::vec3& normal) const;
};

const char* shapeName(SolidPrimitive::Shape shape);

}  // namespace mq
