#include "sim/cloth/collision/proximity.h"

#include <algorithm>

namespace mq::cloth {

glm::vec2 closestSegmentParameters(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& q0, const glm::vec3& q1) {
  const glm::vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const float a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  constexpr float eps = 1e-12f;
  float s = 0.0f, t = 0.0f;
  if (a <= eps && e <= eps) return {0, 0};
  if (a <= eps) return {0, std::clamp(f / e, 0.0f, 1.0f)};
  const float c = glm::dot(d1, r);
  if (e <= eps) return {std::clamp(-c / a, 0.0f, 1.0f), 0};
  const float b = glm::dot(d1, d2), denom = a * e - b * b;
  s = denom > eps ? std::clamp((b * f - c * e) / denom, 0.0f, 1.0f) : 0.0f;
  t = (b * s + f) / e;
  if (t < 0.0f) {
    t = 0.0f;
    s = std::clamp(-c / a, 0.0f, 1.0f);
  } else if (t > 1.0f) {
    t = 1.0f;
    s = std::clamp((b - c) / a, 0.0f, 1.0f);
  }
  return {s, t};
}

}  // namespace mq::cloth
