#include "core/math/transform.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/matrix_decompose.hpp>

namespace mq {

glm::mat4 Trs::matrix() const {
  glm::mat4 m = glm::mat4_cast(rotation);
  m[0] *= scale.x;
  m[1] *= scale.y;
  m[2] *= scale.z;
  m[3] = glm::vec4(translation, 1.0f);
  return m;
}

Trs Trs::fromMatrix(const glm::mat4& m) {
  Trs trs;
  trs.translation = glm::vec3(m[3]);
  glm::vec3 c0(m[0]), c1(m[1]), c2(m[2]);
  trs.scale = {glm::length(c0), glm::length(c1), glm::length(c2)};
  if (glm::determinant(glm::mat3(m)) < 0.0f) trs.scale.x = -trs.scale.x;
  glm::mat3 r(c0 / trs.scale.x, c1 / trs.scale.y, c2 / trs.scale.z);
  trs.rotation = glm::normalize(glm::quat_cast(r));
  return trs;
}

glm::quat slerpShortest(glm::quat a, glm::quat b, float t) {
  float d = glm::dot(a, b);
  if (d < 0.0f) {
    b = -b;
    d = -d;
  }
  if (d > 0.9995f) return glm::normalize(a * (1.0f - t) + b * t);
  const float theta = std::acos(d);
  const float s = std::sin(theta);
  const float wa = std::sin((1.0f - t) * theta) / s;
  const float wb = std::sin(t * theta) / s;
  return glm::normalize(a * wa + b * wb);
}

glm::quat quatFromEulerDegrees(const glm::vec3& degrees) {
  const glm::vec3 r = glm::radians(degrees);
  const glm::quat qx = glm::angleAxis(r.x, glm::vec3(1, 0, 0));
  const glm::quat qy = glm::angleAxis(r.y, glm::vec3(0, 1, 0));
  const glm::quat qz = glm::angleAxis(r.z, glm::vec3(0, 0, 1));
  return glm::normalize(qz * qy * qx);
}

glm::vec3 eulerDegreesFromQuat(const glm::quat& q) {
  // Inverse of quatFromEulerDegrees: R = Rz * Ry * Rx.
  const glm::mat3 m = glm::mat3_cast(glm::normalize(q));
  // m[col][row]
  const float sy = -m[0][2];
  float x, y, z;
  if (std::abs(sy) < 0.99999f) {
    y = std::asin(sy);
    x = std::atan2(m[1][2], m[2][2]);
    z = std::atan2(m[0][1], m[0][0]);
  } else {
    y = sy > 0 ? 1.5707963f : -1.5707963f;
    x = std::atan2(-m[2][1], m[1][1]);
    z = 0.0f;
  }
  return glm::degrees(glm::vec3(x, y, z));
}

glm::quat editAfterWorldRotation(const glm::quat& editBefore, const glm::quat& worldRotationBefore,
                                 const glm::vec3& worldAxis, float radians) {
  // world = beforeEdit * edit, so turning the world rotation by (axis, angle)
  // turns the edit about the same axis seen in the beforeEdit frame.
  const glm::quat beforeEdit = worldRotationBefore * glm::inverse(editBefore);
  const glm::vec3 localAxis = glm::normalize(glm::inverse(beforeEdit) * worldAxis);
  return glm::normalize(glm::angleAxis(radians, localAxis) * editBefore);
}

}  // namespace mq
