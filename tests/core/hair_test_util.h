#pragma once
// Test helpers for the hair tests: a sphere head with a scalp cap.
#include <cmath>

#include "core/hair/scalp.h"

namespace mq::test {

// The part of a UV sphere above `capY` (relative, -1..1) as a scalp.
inline ScalpSurface sphereScalp(const glm::vec3& center, float radius, float capY, int rings = 48, int segments = 96) {
  ScalpSurface s;
  const float pi = 3.14159265f;
  const float thetaMax = std::acos(capY);
  for (int r = 0; r <= rings; ++r) {
    const float theta = thetaMax * float(r) / float(rings);
    for (int k = 0; k < segments; ++k) {
      const float phi = 2.0f * pi * float(k) / float(segments);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      const glm::vec3 p = center + radius * n;
      for (int d = 0; d < 3; ++d) s.positions.push_back(p[d]);
      for (int d = 0; d < 3; ++d) s.normals.push_back(n[d]);
    }
  }
  for (int r = 0; r < rings; ++r)
    for (int k = 0; k < segments; ++k) {
      const uint32_t a = r * segments + k, b = r * segments + (k + 1) % segments;
      const uint32_t c = a + segments, d = b + segments;
      s.triangles.insert(s.triangles.end(), {a, c, b, b, c, d});
    }
  return s;
}

}  // namespace mq::test
