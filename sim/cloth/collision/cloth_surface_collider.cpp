#include "sim/cloth/collision/cloth_surface_collider.h"

#include <cmath>
#include <unordered_map>

#include "core/util/error.h"
#include "sim/cloth/collision/aabb_tree.h"
#include "sim/cloth/collision/proximity.h"

namespace mq::cloth {

namespace {

// A vertex whose nearest point is on a boundary feature counts as over the
// surface (a contact) only while it lies within about 25 degrees of the
// surface's normal there; farther round the edge it is beyond the hem.
constexpr float kOverBoundaryCos = 0.9f;

uint64_t edgeKey(uint32_t a, uint32_t b) { return a < b ? (uint64_t(a) << 32) | b : (uint64_t(b) << 32) | a; }

glm::vec3 unitOr(const glm::vec3& v, const glm::vec3& fallback) {
  const float length = glm::length(v);
  return length > 1e-20f ? v / length : fallback;
}

}  // namespace

void ClothSurfaceCollider::setMesh(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& triangles) {
  if (triangles.size() % 3 != 0) throw Error("cloth surface collider needs 3 indices per triangle");
  for (uint32_t v : triangles)
    if (v >= positions.size()) throw Error("cloth surface collider triangle vertex out of range");
  triangles_ = triangles;
  from_ = to_ = current_ = positions;
  velocity_.assign(positions.size(), glm::vec3(0.0f));
  // Edge neighbours; an edge of one triangle is on the boundary (edges of
  // three or more are left without a neighbour but not called boundary).
  const size_t count = triangles_.size() / 3;
  edgeNeighbour_.assign(3 * count, -1);
  std::unordered_map<uint64_t, int64_t> firstUse;  // edge -> 3 t + k of its first triangle, -2: used three times
  std::vector<uint8_t> shared(3 * count, 0);
  firstUse.reserve(3 * count);
  for (size_t t = 0; t < count; ++t)
    for (int k = 0; k < 3; ++k) {
      const uint64_t key = edgeKey(triangles_[3 * t + k], triangles_[3 * t + (k + 1) % 3]);
      auto [it, inserted] = firstUse.try_emplace(key, int64_t(3 * t + k));
      if (inserted) continue;
      shared[3 * t + k] = 1;
      if (it->second < 0) continue;
      const int64_t other = it->second;
      shared[size_t(other)] = 1;
      if (edgeNeighbour_[size_t(other)] < 0) {  // the second triangle on this edge
        edgeNeighbour_[size_t(other)] = int32_t(t);
        edgeNeighbour_[3 * t + k] = int32_t(other / 3);
      } else {  // a third: non-manifold, no neighbours across it
        edgeNeighbour_[size_t(other)] = -1;
        it->second = -2;
      }
    }
  boundaryVertex_.assign(positions.size(), 0);
  for (size_t e = 0; e < shared.size(); ++e)
    if (!shared[e]) {
      const size_t t = e / 3, k = e % 3;
      boundaryVertex_[triangles_[3 * t + k]] = boundaryVertex_[triangles_[3 * t + (k + 1) % 3]] = 1;
    }
  updateNormals();
  tree_.build(triangleBoxes(current_, triangles_, 0.0f));
}

void ClothSurfaceCollider::setTarget(const std::vector<glm::vec3>& positions, float stepTime) {
  if (positions.size() != to_.size()) throw Error("cloth surface target has a different vertex count");
  if (!(stepTime > 0.0f)) throw Error("cloth surface target needs a positive step time");
  from_ = to_;
  to_ = positions;
  for (size_t i = 0; i < to_.size(); ++i) velocity_[i] = (to_[i] - from_[i]) / stepTime;
}

void ClothSurfaceCollider::moveTo(float fraction) {
  for (size_t i = 0; i < current_.size(); ++i) current_[i] = glm::mix(from_[i], to_[i], fraction);
  updateNormals();
  tree_.refit(triangleBoxes(current_, triangles_, 0.0f));
}

void ClothSurfaceCollider::updateNormals() {
  const size_t count = triangles_.size() / 3;
  faceNormal_.resize(count);
  vertexNormal_.assign(current_.size(), glm::vec3(0.0f));
  for (size_t t = 0; t < count; ++t) {
    const uint32_t v[3] = {triangles_[3 * t], triangles_[3 * t + 1], triangles_[3 * t + 2]};
    const glm::vec3 n =
        unitOr(glm::cross(current_[v[1]] - current_[v[0]], current_[v[2]] - current_[v[0]]), glm::vec3(0.0f));
    faceNormal_[t] = n;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 e1 = current_[v[(k + 1) % 3]] - current_[v[k]], e2 = current_[v[(k + 2) % 3]] - current_[v[k]];
      const float l1 = glm::length(e1), l2 = glm::length(e2);
      if (l1 > 0.0f && l2 > 0.0f)
        vertexNormal_[v[k]] += std::acos(glm::clamp(glm::dot(e1, e2) / (l1 * l2), -1.0f, 1.0f)) * n;
    }
  }
  for (glm::vec3& n : vertexNormal_) n = unitOr(n, glm::vec3(0.0f));
}

glm::vec3 ClothSurfaceCollider::featureNormal(uint32_t t, const glm::vec3& w, bool& onBoundary) const {
  onBoundary = false;
  const int zeros = (w.x == 0.0f) + (w.y == 0.0f) + (w.z == 0.0f);
  if (zeros == 0) return faceNormal_[t];
  if (zeros == 2) {  // a corner
    const int k = w.x != 0.0f ? 0 : w.y != 0.0f ? 1 : 2;
    const uint32_t v = triangles_[3 * t + k];
    onBoundary = boundaryVertex_[v] != 0;
    return vertexNormal_[v];
  }
  // On the edge opposite the corner of weight zero: edge (j+1, j+2) = edge index (j+1) % 3.
  const int j = w.x == 0.0f ? 0 : w.y == 0.0f ? 1 : 2;
  const int edge = (j + 1) % 3;
  const int32_t across = edgeNeighbour_[3 * t + edge];
  if (across < 0) {
    const uint32_t a = triangles_[3 * t + edge], b = triangles_[3 * t + (edge + 1) % 3];
    onBoundary = boundaryVertex_[a] && boundaryVertex_[b];
    return faceNormal_[t];
  }
  return unitOr(faceNormal_[t] + faceNormal_[size_t(across)], faceNormal_[t]);
}

bool ClothSurfaceCollider::nearestContact(const glm::vec3& p, float radius, SurfaceContact& contact) const {
  float best2 = radius * radius;
  int64_t nearest = -1;
  glm::vec3 weights(0.0f);
  // Of triangles equally near the lowest index wins (independent of the visiting order).
  tree_.nearest(p, best2, [&](uint32_t t) {
    if (faceNormal_[t] == glm::vec3(0.0f)) return;  // degenerate
    const uint32_t a = triangles_[3 * t], b = triangles_[3 * t + 1], c = triangles_[3 * t + 2];
    const glm::vec3 w = closestTriangleWeights(p, current_[a], current_[b], current_[c]);
    const glm::vec3 offset = p - (w.x * current_[a] + w.y * current_[b] + w.z * current_[c]);
    const float d2 = glm::dot(offset, offset);
    if (d2 > best2 || (d2 == best2 && nearest >= 0 && t > nearest)) return;
    best2 = d2;
    nearest = t;
    weights = w;
  });
  if (nearest < 0) return false;
  const uint32_t t = uint32_t(nearest);
  const uint32_t a = triangles_[3 * t], b = triangles_[3 * t + 1], c = triangles_[3 * t + 2];
  const glm::vec3 q = weights.x * current_[a] + weights.y * current_[b] + weights.z * current_[c];
  bool onBoundary = false;
  const glm::vec3 side = featureNormal(t, weights, onBoundary);
  const glm::vec3 offset = p - q;
  const float d = glm::length(offset);
  const bool behind = glm::dot(offset, side) < 0.0f;
  // Beyond a hem: nothing is known of inside, so a vertex on the side the
  // surface does not face is left alone; one on the side it faces only keeps
  // its distance from the edge (so the outer cloth does not sag through the
  // waistband's rim between its vertices).
  if (onBoundary && d > 1e-6f && std::abs(glm::dot(offset, side)) < kOverBoundaryCos * d) {
    if (behind) return false;
    contact = {q, offset / d, weights.x * velocity_[a] + weights.y * velocity_[b] + weights.z * velocity_[c], d};
    return true;
  }
  contact.point = q;
  contact.signedDistance = behind ? -d : d;
  // Out is along the shortest way to the surface, through it from behind.
  if (d > 1e-6f)
    contact.normal = behind ? -offset / d : offset / d;
  else
    contact.normal = side != glm::vec3(0.0f) ? side : faceNormal_[t];
  contact.velocity = weights.x * velocity_[a] + weights.y * velocity_[b] + weights.z * velocity_[c];
  return true;
}

}  // namespace mq::cloth
