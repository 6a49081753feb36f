#pragma once
// Test helpers for the hair tests: a sphere head with a scalp cap.
#include <algorithm>
#include <cmath>
#include <random>

#include "core/hair/scalp.h"
#include "core/hair/strands.h"

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

// The sphere head of the synthetic groom below.
inline const glm::vec3 kHeadCenter(0.0f, 1.6f, 0.0f);
constexpr float kHeadRadius = 0.1f;

// A synthetic groom: roots on the top and back of a sphere; each strand
// combs down over the sphere (gravity projected on the tangent plane, a
// little further out per strand for volume) and falls straight below it.
inline Strands combedStrands(int count, int points, float length) {
  Strands strands;
  strands.pointsPerStrand = points;
  std::mt19937 rng(12111);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  const glm::vec3 down(0.0f, -1.0f, 0.0f);
  while (int(strands.strandCount()) < count) {
    glm::vec3 n(uniform(rng), uniform(rng), uniform(rng));
    const float len = glm::length(n);
    if (len > 1.0f || len < 0.1f) continue;
    n /= len;
    if (n.y < 0.1f && !(n.z < -0.3f && n.y > -0.5f)) continue;  // scalp: top and back
    if (n.z > 0.45f && n.y < 0.8f) continue;                    // keep the face clear
    const float lift = kHeadRadius * (0.02f + 0.12f * (0.5f + 0.5f * uniform(rng)));
    const float segment = length * (0.9f + 0.1f * uniform(rng)) / float(points - 1);
    const glm::vec3 wander = 0.15f * glm::vec3(uniform(rng), 0.0f, uniform(rng));
    glm::vec3 p = kHeadCenter + n * (kHeadRadius * 1.01f);
    for (int i = 0; i < points; ++i) {
      strands.points.insert(strands.points.end(), {p.x, p.y, p.z});
      const glm::vec3 out = glm::normalize(p - kHeadCenter);
      const float radius = kHeadRadius + lift * std::min(1.0f, 3.0f * float(i) / float(points));
      glm::vec3 along = down - glm::dot(down, out) * out;  // comb over the sphere
      if (p.y < kHeadCenter.y - 0.02f || glm::length(along) < 0.2f) along = down + wander;
      p += segment * glm::normalize(along);
      const glm::vec3 d = p - kHeadCenter;
      if (glm::length(d) < radius) p = kHeadCenter + glm::normalize(d) * radius;  // stay outside, with volume
    }
    strands.rootNormals.insert(strands.rootNormals.end(), {n.x, n.y, n.z});
  }
  return strands;
}

}  // namespace mq::test
