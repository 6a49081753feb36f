#include "core/geometry/nearest_points.h"

#include <algorithm>

#include <nanoflann.hpp>

namespace mq {

namespace {

// A flat xyz array as nanoflann's dataset.
struct FlatPoints {
  const std::vector<float>& xyz;
  size_t kdtree_get_point_count() const { return xyz.size() / 3; }
  float kdtree_get_pt(size_t i, size_t dim) const { return xyz[3 * i + dim]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using KdTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, FlatPoints>, FlatPoints, 3, uint32_t>;

}  // namespace

std::vector<uint32_t> nearestPoints(const std::vector<float>& queries, const std::vector<float>& set, int k) {
  std::vector<uint32_t> out;
  const size_t count = set.size() / 3;
  k = int(std::min<size_t>(size_t(std::max(k, 1)), count));
  if (k == 0) return out;
  const FlatPoints points{set};
  const KdTree tree(3, points, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  out.resize(queries.size() / 3 * k);
  std::vector<float> distances(k);
  for (size_t q = 0; q < queries.size() / 3; ++q) tree.knnSearch(&queries[3 * q], k, &out[q * k], distances.data());
  return out;
}

}  // namespace mq
