#pragma once
// Test helpers for the strand dynamics tests: straight strands and points.
#include <vector>

#include <glm/glm.hpp>

#include "core/hair/strands.h"

namespace mq::test {

inline glm::vec3 pointOf(const std::vector<float>& points, size_t i) {
  return {points[3 * i], points[3 * i + 1], points[3 * i + 2]};
}

// A straight strand of strands.pointsPerStrand points from root along dir.
inline void addStraightStrand(Strands& strands, glm::vec3 root, glm::vec3 dir, float length) {
  const int n = strands.pointsPerStrand;
  for (int i = 0; i < n; ++i) {
    const glm::vec3 p = root + dir * (length * float(i) / float(n - 1));
    strands.points.insert(strands.points.end(), {p.x, p.y, p.z});
  }
  strands.rootNormals.insert(strands.rootNormals.end(), {dir.x, dir.y, dir.z});
}

}  // namespace mq::test
