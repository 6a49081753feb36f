#pragma once
// Whether a straight segment crosses a triangle surface: the visibility test
// of weight regeneration (a vertex may only be bound to a bone it sees from
// inside the skin). The tree is CGAL's AABB tree, kept in its own .cpp.

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

namespace mq {

class SurfaceSegmentQuery {
 public:
  // positions: 3 floats per vertex; triangles: 3 indices each. Degenerate
  // triangles are left out.
  SurfaceSegmentQuery(const std::vector<float>& positions, const std::vector<uint32_t>& triangles);
  ~SurfaceSegmentQuery();
  SurfaceSegmentQuery(const SurfaceSegmentQuery&) = delete;
  SurfaceSegmentQuery& operator=(const SurfaceSegmentQuery&) = delete;

  // True when the segment from a to b touches a triangle. Safe to call from
  // several threads at once.
  bool hits(const glm::dvec3& a, const glm::dvec3& b) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace mq
