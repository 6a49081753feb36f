// The CGAL part of surface_segment_query.h, in its own translation unit.
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include "core/geometry/surface_segment_query.h"

namespace mq {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 point(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

}  // namespace

struct SurfaceSegmentQuery::Tree {
  std::vector<Triangle> triangles;  // the tree refers into this
  AabbTree tree;
};

SurfaceSegmentQuery::SurfaceSegmentQuery(const std::vector<float>& positions, const std::vector<uint32_t>& triangles)
    : tree_(std::make_unique<Tree>()) {
  auto at = [&](uint32_t v) {
    return Kernel::Point_3(positions[3 * size_t(v)], positions[3 * size_t(v) + 1], positions[3 * size_t(v) + 2]);
  };
  tree_->triangles.reserve(triangles.size() / 3);
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const Triangle triangle(at(triangles[t]), at(triangles[t + 1]), at(triangles[t + 2]));
    if (!triangle.is_degenerate()) tree_->triangles.push_back(triangle);
  }
  tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
  tree_->tree.build();  // now, so that concurrent queries only read
}

SurfaceSegmentQuery::~SurfaceSegmentQuery() = default;

bool SurfaceSegmentQuery::hits(const glm::dvec3& a, const glm::dvec3& b) const {
  if (tree_->triangles.empty() || a == b) return false;
  return tree_->tree.do_intersect(Kernel::Segment_3(point(a), point(b)));
}

}  // namespace mq
