#pragma once
// First hit of a ray on a triangle mesh, through a bounding volume hierarchy
// (median split on the widest axis, Möller-Trumbore triangle tests, with a
// small tolerance so a ray through an edge or a vertex still hits). Built
// once over flat arrays (copied); queries are const and may run on several
// threads.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace mq {

class TriangleRayCaster {
 public:
  TriangleRayCaster(const std::vector<float>& positions, const std::vector<uint32_t>& triangles);

  // Distance along unit `direction` from `origin` to the nearest triangle hit
  // beyond `minDistance`, skipping triangles that use vertex `skipVertex`
  // (the ray's own corner; -1: none). Negative when nothing is hit.
  float firstHit(const glm::vec3& origin, const glm::vec3& direction, float minDistance, int64_t skipVertex = -1) const;

 private:
  struct Node {
    glm::vec3 min, max;
    uint32_t first, count;  // leaf: triangles [first, first + count); inner: count 0, children first, first + 1
  };
  void build(uint32_t node, uint32_t first, uint32_t count);

  std::vector<float> positions_;
  std::vector<uint32_t> triangles_;
  std::vector<uint32_t> order_;  // triangle indices, grouped by leaf
  std::vector<glm::vec3> centroids_;
  std::vector<Node> nodes_;
};

}  // namespace mq
