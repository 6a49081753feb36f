#include "core/geometry/solid_primitive.h"

#include <algorithm>

namespace mq {

namespace {

float distanceToPoint(const glm::vec3& p, const glm::vec3& centre, float radius, glm::vec3& normal) {
  const glm::vec3 d = p - centre;
  const float l = glm::length(d);
  normal = l > 1e-12f ? d / l : glm::vec3(0.0f, 1.0f, 0.0f);
  return l - radius;
}

}  // namespace

SolidPrimitive SolidPrimitive::sphere(glm::vec3 centre, float radius) {
  return {Shape::Sphere, centre, centre, radius};
}

SolidPrimitive SolidPrimitive::capsule(glm::vec3 end0, glm::vec3 end1, float radius) {
  return {Shape::Capsule, end0, end1, radius};
}

SolidPrimitive SolidPrimitive::plane(glm::vec3 point, glm::vec3 normal) {
  return {Shape::Plane, point, glm::normalize(normal), 0.0f};
}

float SolidPrimitive::signedDistance(const glm::vec3& p, glm::vec3& normal) const {
  switch (shape) {
    case Shape::Sphere:
      return distanceToPoint(p, a, radius, normal);
    case Shape::Capsule: {
      const glm::vec3 axis = b - a;
      const float len2 = glm::dot(axis, axis);
      const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, axis) / len2, 0.0f, 1.0f) : 0.0f;
      return distanceToPoint(p, a + t * axis, radius, normal);
    }
    case Shape::Plane:
      normal = b;
      return glm::dot(p - a, b);
  }
  return 1e30f;
}

const char* shapeName(SolidPrimitive::Shape shape) {
  switch (shape) {
    case SolidPrimitive::Shape::Sphere:
      return "sphere";
    case SolidPrimitive::Shape::Capsule:
      return "capsule";
    case SolidPrimitive::Shape::Plane:
      return "plane";
  }
  return "?";
}

}  // namespace mq
