#include "sim/cloth/collision/self_collision.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "sim/cloth/collision/proximity.h"
#include "core/util/thread_pool.h"

namespace mq::cloth {

namespace {

constexpr size_t kBlocks = 64;

bool sharesVertex(uint32_t a0, uint32_t a1, uint32_t b0, uint32_t b1) {
  return a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1;
}

// Runs body(item, outBlock) over [0, count) in fixed blocks, in parallel, and
// concatenates the blocks' outputs in order: deterministic.
template <class T, class Body>
std::vector<T> collectInBlocks(size_t count, Body&& body) {
  std::vector<std::vector<T>> blocks(kBlocks);
  const size_t size = (count + kBlocks - 1) / kBlocks;
  ThreadPool::shared().parallelFor(0, kBlocks, 1, [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b)
      for (size_t i = b * size; i < std::min(count, (b + 1) * size); ++i) body(i, blocks[b]);
  });
  size_t total = 0;
  for (const auto& b : blocks) total += b.size();
  std::vector<T> all;
  all.reserve(total);
  for (auto& b : blocks) all.insert(all.end(), b.begin(), b.end());
  return all;
}

}  // namespace

SelfCollision::SelfCollision(const std::vector<uint32_t>& triangles, size_t vertexCount) : triangles_(triangles) {
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> index;
  triangleEdges_.resize(triangles.size());
  for (size_t t = 0; t < triangles.size(); t += 3)
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = triangles[t + c], b = triangles[t + (c + 1) % 3];
      const auto key = std::minmax(a, b);
      auto [it, added] = index.emplace(std::make_pair(key.first, key.second), uint32_t(edges_.size()));
      if (added) edges_.push_back({key.first, key.second});
      triangleEdges_[t + c] = it->second;
    }
}

void SelfCollision::findCandidates(const ClothState& s, const std::vector<glm::vec3>& x0, float thickness) {
  const size_t n = s.size(), triangleCount = triangles_.size() / 3;
  // How every vertex moved in the step. Two elements can close their gap by
  // at most the largest difference of their vertices' moves (a sheet falling
  // as a whole closes none).
  std::vector<glm::vec3> move(n);
  glm::vec3 meanMove(0.0f);
  float meanMotion = 0.0f;
  for (size_t v = 0; v < n; ++v) {
    move[v] = s.x[v] - x0[v];
    meanMove += move[v];
    meanMotion += glm::length(move[v]);
  }
  meanMove /= float(std::max<size_t>(n, 1));
  meanMotion /= float(std::max<size_t>(n, 1));
  float deviation = 0.0f;  // largest distance of a move from the mean move
  for (size_t v = 0; v < n; ++v) deviation = std::max(deviation, glm::length(move[v] - meanMove));
  auto closing = [&](std::initializer_list<uint32_t> first, std::initializer_list<uint32_t> second) {
    float worst = 0.0f;
    for (uint32_t a : first)
      for (uint32_t b : second) {
        const glm::vec3 d = move[a] - move[b];
        worst = std::max(worst, glm::dot(d, d));
      }
    return std::sqrt(worst);
  };
  // Element boxes for the broad phase, whichever is smaller: swept over the
  // step (start and end, grown by the thickness), or at the start grown by
  // half the thickness plus the deviation (any two elements closing by up to
  // twice the deviation then still overlap). The second wins when the cloth
  // moves mostly as a whole.
  const bool relative = 2.0f * deviation < meanMotion + thickness;
  const float grow = relative ? 0.5f * thickness + deviation : thickness;
  auto sweptBox = [&](std::initializer_list<uint32_t> vertices) {
    Box b;
    for (uint32_t v : vertices) {
      b.extend(x0[v]);
      if (!relative) b.extend(s.x[v]);
    }
    b.min -= glm::vec3(grow);
    b.max += glm::vec3(grow);
    return b;
  };
  std::vector<Box> boxes(triangleCount);
  for (size_t t = 0; t < triangleCount; ++t)
    boxes[t] = sweptBox({triangles_[3 * t], triangles_[3 * t + 1], triangles_[3 * t + 2]});
  tree_.build(boxes);
  std::vector<Box> edgeBoxes(edges_.size());
  for (size_t e = 0; e < edges_.size(); ++e) edgeBoxes[e] = sweptBox({edges_[e].first, edges_[e].second});
  edgeTree_.build(edgeBoxes);
  vertexTriangle_ = collectInBlocks<VertexTriangle>(n, [&](size_t v, std::vector<VertexTriangle>& out) {
    tree_.query(sweptBox({uint32_t(v)}), [&](uint32_t t) {
      const uint32_t a = triangles_[3 * t], b = triangles_[3 * t + 1], c = triangles_[3 * t + 2];
      if (v == a || v == b || v == c) return;
      const glm::vec3 w = closestTriangleWeights(x0[v], x0[a], x0[b], x0[c]);
      const glm::vec3 normal = glm::cross(x0[b] - x0[a], x0[c] - x0[a]);
      const glm::vec3 offset = x0[v] - (w.x * x0[a] + w.y * x0[b] + w.z * x0[c]);
      const float reach = thickness + closing({uint32_t(v)}, {a, b, c});
      if (glm::dot(offset, offset) > reach * reach) return;
      const float side = glm::dot(offset, normal) >= 0.0f ? 1.0f : -1.0f;
      out.push_back({uint32_t(v), t, w, side});
    });
  });
  edgeEdge_ = collectInBlocks<EdgeEdge>(edges_.size(), [&](size_t e, std::vector<EdgeEdge>& out) {
    const auto [p0, p1] = edges_[e];
    const Box& box = edgeBoxes[e];
    const size_t first = out.size();
    edgeTree_.query(box, [&](uint32_t f) {
      // (The tree only visits edges whose swept boxes meet this one's: the
      // others never come within the thickness during the step.)
      if (f <= e) return;
      const auto [q0, q1] = edges_[f];
      if (sharesVertex(p0, p1, q0, q1)) return;
      const float reach = thickness + closing({p0, p1}, {q0, q1});
      // Bounding balls first: the segments' points lie within half their
      // lengths of their midpoints.
      const float apart = glm::length(0.5f * (x0[p0] + x0[p1] - x0[q0] - x0[q1])) -
                          0.5f * (glm::length(x0[p0] - x0[p1]) + glm::length(x0[q0] - x0[q1]));
      if (apart > reach) return;
      const glm::vec2 st = closestSegmentParameters(x0[p0], x0[p1], x0[q0], x0[q1]);
      const glm::vec3 d = glm::mix(x0[p0], x0[p1], st.x) - glm::mix(x0[q0], x0[q1], st.y);
      const float l = glm::length(d);
      if (l < 1e-9f || l > reach) return;
      out.push_back({uint32_t(e), f, st, d / l});
    });
    // In order of the other edge (the tree's order depends on the boxes).
    std::sort(out.begin() + first, out.end(), [](const EdgeEdge& a, const EdgeEdge& b) { return a.e1 < b.e1; });
  });
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

int SelfCollision::resolve(ClothState& s, const std::vector<glm::vec3>& x0, float thickness, int passes) {
  findCandidates(s, x0, thickness);
  int contacts = 0;
  for (int pass = 0; pass < passes; ++pass) {
    int active = 0;
    for (const auto& c : vertexTriangle_) active += applyVertexTriangle(s, c, thickness);
    for (const auto& c : edgeEdge_) active += applyEdgeEdge(s, c, thickness);
    if (pass == 0) contacts = active;
    if (active == 0) break;
  }
  return contacts;
}

}  // namespace mq::cloth
