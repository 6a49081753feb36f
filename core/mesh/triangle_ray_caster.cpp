#include "core/mesh/triangle_ray_caster.h"

#include <algorithm>
#include <cmath>

namespace mq {
namespace {

constexpr uint32_t kLeafSize = 4;
constexpr float kEdgeTolerance = 1e-5f;  // in barycentric units

glm::vec3 vertex(const std::vector<float>& p, uint32_t v) { return {p[3 * v], p[3 * v + 1], p[3 * v + 2]}; }

// Slab test: entry distance of the ray into the box, or +inf when it misses.
float boxEntry(const glm::vec3& lo, const glm::vec3& hi, const glm::vec3& origin, const glm::vec3& inverse, float far) {
  const glm::vec3 t0 = (lo - origin) * inverse, t1 = (hi - origin) * inverse;
  const glm::vec3 tmin = glm::min(t0, t1), tmax = glm::max(t0, t1);
  const float enter = std::max({tmin.x, tmin.y, tmin.z, 0.0f});
  const float exit = std::min({tmax.x, tmax.y, tmax.z, far});
  return enter <= exit ? enter : INFINITY;
}

}  // namespace

TriangleRayCaster::TriangleRayCaster(const std::vector<float>& positions, const std::vector<uint32_t>& triangles)
    : positions_(positions), triangles_(triangles) {
  const uint32_t count = static_cast<uint32_t>(triangles.size() / 3);
  order_.resize(count);
  centroids_.resize(count);
  for (uint32_t t = 0; t < count; ++t) {
    order_[t] = t;
    centroids_[t] = (vertex(positions, triangles[3 * t]) + vertex(positions, triangles[3 * t + 1]) +
                     vertex(positions, triangles[3 * t + 2])) /
                    3.0f;
  }
  nodes_.reserve(2 * count / kLeafSize + 2);
  nodes_.push_back({});
  if (count > 0) build(0, 0, count);
}

void TriangleRayCaster::build(uint32_t node, uint32_t first, uint32_t count) {
  glm::vec3 lo(INFINITY), hi(-INFINITY), clo(INFINITY), chi(-INFINITY);
  for (uint32_t i = first; i < first + count; ++i) {
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 p = vertex(positions_, triangles_[3 * order_[i] + k]);
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    clo = glm::min(clo, centroids_[order_[i]]);
    chi = glm::max(chi, centroids_[order_[i]]);
  }
  nodes_[node].min = lo;
  nodes_[node].max = hi;
  if (count <= kLeafSize) {
    nodes_[node].first = first;
    nodes_[node].count = count;
    return;
  }
  const glm::vec3 extent = chi - clo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const uint32_t half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                   [&](uint32_t a, uint32_t b) { return centroids_[a][axis] < centroids_[b][axis]; });
  const uint32_t children = static_cast<uint32_t>(nodes_.size());
  nodes_.push_back({});
  nodes_.push_back({});
  nodes_[node].first = children;
  nodes_[node].count = 0;
  build(children, first, half);
  build(children + 1, first + half, count - half);
}

float TriangleRayCaster::firstHit(const glm::vec3& origin, const glm::vec3& direction, float minDistance,
                                  int64_t skipVertex) const {
  if (order_.empty()) return -1.0f;
  // A zero component would make 0 * inf = NaN in the slab test for a ray
  // starting on a box face; a tiny one keeps it finite.
  glm::vec3 inverse;
  for (int k = 0; k < 3; ++k)
    inverse[k] = 1.0f / (std::abs(direction[k]) > 1e-12f ? direction[k] : std::copysign(1e-12f, direction[k]));
  float best = INFINITY;
  uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (boxEntry(node.min, node.max, origin, inverse, best) == INFINITY) continue;
    if (node.count == 0) {
      stack[top++] = node.first;
      stack[top++] = node.first + 1;
      continue;
    }
    for (uint32_t i = node.first; i < node.first + node.count; ++i) {
      const uint32_t* tri = &triangles_[3 * order_[i]];
      if (int64_t(tri[0]) == skipVertex || int64_t(tri[1]) == skipVertex || int64_t(tri[2]) == skipVertex) continue;
      // Möller-Trumbore.
      const glm::vec3 a = vertex(positions_, tri[0]);
      const glm::vec3 e1 = vertex(positions_, tri[1]) - a, e2 = vertex(positions_, tri[2]) - a;
      const glm::vec3 pv = glm::cross(direction, e2);
      const float det = glm::dot(e1, pv);
      if (std::abs(det) < 1e-20f) continue;
      const glm::vec3 tv = origin - a;
      const float u = glm::dot(tv, pv) / det;
      if (u < -kEdgeTolerance || u > 1.0f + kEdgeTolerance) continue;
      const glm::vec3 qv = glm::cross(tv, e1);
      const float v = glm::dot(direction, qv) / det;
      if (v < -kEdgeTolerance || u + v > 1.0f + kEdgeTolerance) continue;
      const float t = glm::dot(e2, qv) / det;
      if (t > minDistance && t < best) best = t;
    }
  }
  return best == INFINITY ? -1.0f : best;
}

}  // namespace mq
