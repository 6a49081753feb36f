#include "core/mesh/bent_edges.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "core/mesh/position_weld.h"

namespace mq {

BentEdges bentEdges(const std::vector<float>& positions, const std::vector<uint32_t>& triangles, float degrees) {
  const PositionWeld weld = weldByPosition(positions, triangles);
  const std::vector<float> welded = weld.gather(positions);
  auto point = [&](uint32_t v) { return glm::vec3(welded[3 * v], welded[3 * v + 1], welded[3 * v + 2]); };
  const size_t count = weld.triangles.size() / 3;
  std::vector<glm::vec3> normals(count);
  std::vector<bool> usable(count);
  for (size_t t = 0; t < count; ++t) {
    const uint32_t* tri = &weld.triangles[3 * t];
    const glm::vec3 n = glm::cross(point(tri[1]) - point(tri[0]), point(tri[2]) - point(tri[0]));
    const float length = glm::length(n);
    usable[t] = length > 0.0f && std::isfinite(length);
    normals[t] = usable[t] ? n / length : glm::vec3(0.0f);
  }
  // Every edge as (low vertex, high vertex, triangle), sorted: an interior edge is a run of two.
  struct EdgeSide {
    uint32_t a, b, triangle;
    bool operator<(const EdgeSide& o) const { return a != o.a ? a < o.a : b != o.b ? b < o.b : triangle < o.triangle; }
  };
  std::vector<EdgeSide> sides;
  sides.reserve(3 * count);
  for (size_t t = 0; t < count; ++t)
    for (int k = 0; k < 3; ++k) {
      const uint32_t u = weld.triangles[3 * t + k], v = weld.triangles[3 * t + (k + 1) % 3];
      sides.push_back({std::min(u, v), std::max(u, v), uint32_t(t)});
    }
  std::sort(sides.begin(), sides.end());
  const float cosLimit = std::cos(glm::radians(degrees));
  BentEdges result;
  for (size_t i = 0; i < sides.size();) {
    size_t j = i + 1;
    while (j < sides.size() && sides[j].a == sides[i].a && sides[j].b == sides[i].b) ++j;
    const uint32_t t0 = sides[i].triangle, t1 = sides[i + 1 < j ? i + 1 : i].triangle;
    if (j - i == 2 && usable[t0] && usable[t1]) {
      ++result.interiorEdges;
      if (glm::dot(normals[t0], normals[t1]) < cosLimit) ++result.bent;
    }
    i = j;
  }
  return result;
}

}  // namespace mq
