#include "sim/cloth/collision/self_collision.h"

#include <algorithm>
#include <map>

#include "sim/cloth/collision/self_collision/stages.h"

namespace mq::cloth {

using self_collision::kNoTriangle;

SelfCollision::SelfCollision(const std::vector<uint32_t>& triangles, size_t vertexCount)
    : triangles_(triangles), vertexCount_(vertexCount) {
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> index;
  triangleEdges_.resize(triangles.size());
  for (size_t t = 0; t < triangles.size(); t += 3)
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = triangles[t + c], b = triangles[t + (c + 1) % 3];
      const auto key = std::minmax(a, b);
      auto [it, added] = index.emplace(std::make_pair(key.first, key.second), uint32_t(edges_.size()));
      if (added) edges_.push_back({key.first, key.second}), edgeTriangles_.push_back({kNoTriangle, kNoTriangle});
      triangleEdges_[t + c] = it->second;
      auto& sides = edgeTriangles_[it->second];
      // A third triangle on an edge (non-manifold) makes no patch flat: its edge's second side is left unknown.
      if (sides[0] == kNoTriangle)
        sides[0] = uint32_t(t / 3);
      else if (sides[1] == kNoTriangle)
        sides[1] = uint32_t(t / 3);
      else
        sides[0] = sides[1] = kNoTriangle - 1;
    }
}

// The search's stages, each in its file under self_collision/.
void SelfCollision::findCandidates(const ClothState& s, const std::vector<glm::vec3>& x0, float thickness) {
  Step step{s, x0, thickness};
  measureMoves(step);                  // element_boxes.cpp
  findElementBoxes(step);              // element_boxes.cpp
  updateTrees(step);                   // tree_update.cpp
  findMotionBounds(step);              // motion_bounds.cpp
  findFlatPatches(s, x0);              // flat_patches.cpp
  findVertexTriangleCandidates(step);  // vertex_triangle_candidates.cpp
  findEdgeEdgeCandidates(step);        // edge_edge_candidates.cpp
}

// Pushes the weighted point sum_k w_k x_k of a pair apart along n until its
// gap is `thickness`, sharing the move by inverse mass (a position
// constraint), and removes the approaching part of the relative velocity.
template <size_t N>
static int separate(ClothState& s, const uint32_t (&v)[N], const float (&w)[N], const glm::vec3& n, float thickness) {
  glm::vec3 gapPoint(0.0f), relVelocity(0.0f);
  float denom = 0.0f;
  for (size_t k = 0; k < N; ++k) {
    gapPoint += w[k] * s.x[v[k]];
    relVelocity += w[k] * s.v[v[k]];
    denom += w[k] * w[k] * s.invMass[v[k]];
  }
  const float gap = glm::dot(gapPoint, n);
  if (gap >= thickness || denom <= 0.0f) return 0;
  const float push = (thickness - gap) / denom;
  const float vn = glm::dot(relVelocity, n);
  const float stop = vn < 0.0f ? -vn / denom : 0.0f;
  for (size_t k = 0; k < N; ++k) {
    s.x[v[k]] += (push * w[k] * s.invMass[v[k]]) * n;
    s.v[v[k]] += (stop * w[k] * s.invMass[v[k]]) * n;
  }
  return 1;
}

int SelfCollision::applyVertexTriangle(ClothState& s, const VertexTriangle& c, float thickness) const {
  const uint32_t a = triangles_[3 * c.triangle], b = triangles_[3 * c.triangle + 1], d = triangles_[3 * c.triangle + 2];
  const glm::vec3 normal = glm::cross(s.x[b] - s.x[a], s.x[d] - s.x[a]);
  const float l = glm::length(normal);
  if (l <= 0.0f) return 0;
  const glm::vec3 n = (c.side / l) * normal;
  // Only a vertex over the triangle (not beside it in its plane) is in contact.
  const glm::vec3 offset = s.x[c.vertex] - (c.weights.x * s.x[a] + c.weights.y * s.x[b] + c.weights.z * s.x[d]);
  if (glm::length(offset - glm::dot(offset, n) * n) > thickness) return 0;
  const uint32_t v[4] = {c.vertex, a, b, d};
  const float w[4] = {1.0f, -c.weights.x, -c.weights.y, -c.weights.z};
  return separate(s, v, w, n, thickness);
}

int SelfCollision::applyEdgeEdge(ClothState& s, const EdgeEdge& c, float thickness) const {
  const auto [p0, p1] = edges_[c.e0];
  const auto [q0, q1] = edges_[c.e1];
  const glm::vec3 offset = glm::mix(s.x[p0], s.x[p1], c.params.x) - glm::mix(s.x[q0], s.x[q1], c.params.y);
  if (glm::length(offset - glm::dot(offset, c.normal0) * c.normal0) > thickness) return 0;
  const uint32_t v[4] = {p0, p1, q0, q1};
  const float w[4] = {1.0f - c.params.x, c.params.x, -(1.0f - c.params.y), -c.params.y};
  return separate(s, v, w, c.normal0, thickness);
}

std::vector<std::array<uint32_t, 2>> SelfCollision::vertexTrianglePairs() const {
  std::vector<std::array<uint32_t, 2>> pairs;
  for (const VertexTriangle& c : vertexTriangle_) pairs.push_back({c.vertex, c.triangle});
  return pairs;
}

std::vector<std::array<uint32_t, 4>> SelfCollision::edgeEdgePairs() const {
  std::vector<std::array<uint32_t, 4>> pairs;
  for (const EdgeEdge& c : edgeEdge_)
    pairs.push_back({edges_[c.e0].first, edges_[c.e0].second, edges_[c.e1].first, edges_[c.e1].second});
  return pairs;
}

int SelfCollision::resolve(ClothState& s, const std::vector<glm::vec3>& x0, float thickness, int passes) {
  findCandidates(s, x0, thickness);
  int contacts = 0;
  // A pair whose four vertices have not moved since it was last found apart
  // is apart still: later passes skip it (moved_: the clock of each vertex's
  // last push, checked_: of each pair's last test).
  moved_.assign(s.size(), 0);
  checkedVT_.assign(vertexTriangle_.size(), 0);
  checkedEE_.assign(edgeEdge_.size(), 0);
  uint32_t clock = 1;
  auto stale = [&](uint32_t checked, const uint32_t(&v)[4]) {
    return moved_[v[0]] >= checked || moved_[v[1]] >= checked || moved_[v[2]] >= checked || moved_[v[3]] >= checked;
  };
  auto touch = [&](const uint32_t(&v)[4]) {
    for (uint32_t k : v) moved_[k] = clock;
  };
  for (int pass = 0; pass < passes; ++pass) {
    int active = 0;
    for (size_t k = 0; k < vertexTriangle_.size(); ++k) {
      const VertexTriangle& c = vertexTriangle_[k];
      const uint32_t* t = &triangles_[3 * c.triangle];
      const uint32_t v[4] = {c.vertex, t[0], t[1], t[2]};
      if (pass > 0 && !stale(checkedVT_[k], v)) continue;
      checkedVT_[k] = ++clock;
      if (applyVertexTriangle(s, c, thickness)) ++active, touch(v);
    }
    for (size_t k = 0; k < edgeEdge_.size(); ++k) {
      const EdgeEdge& c = edgeEdge_[k];
      const uint32_t v[4] = {edges_[c.e0].first, edges_[c.e0].second, edges_[c.e1].first, edges_[c.e1].second};
      if (pass > 0 && !stale(checkedEE_[k], v)) continue;
      checkedEE_[k] = ++clock;
      if (applyEdgeEdge(s, c, thickness)) ++active, touch(v);
    }
    if (pass == 0) contacts = active;
    if (active == 0) break;
  }
  return contacts;
}

}  // namespace mq::cloth
