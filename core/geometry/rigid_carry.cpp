#include "core/geometry/rigid_carry.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Dense>
#include <Eigen/SVD>
#include <nanoflann.hpp>

namespace mq {

namespace {

Eigen::Vector3f at(const std::vector<float>& flat, size_t i) { return {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]}; }

// A flat xyz array as nanoflann's dataset.
struct FlatPoints {
  const std::vector<float>& xyz;
  size_t kdtree_get_point_count() const { return xyz.size() / 3; }
  float kdtree_get_pt(size_t i, size_t dim) const { return xyz[3 * i + dim]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, FlatPoints>, FlatPoints, 3, uint32_t>;

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

RigidCarry::RigidCarry(std::vector<float> points, std::vector<float> from, int k)
    : points_(std::move(points)), from_(std::move(from)) {
  k_ = int(std::min<size_t>(size_t(std::max(k, 1)), from_.size() / 3));
}

std::vector<float> RigidCarry::carry(const std::vector<float>& to) const {
  std::vector<float> out = points_;
  if (to.size() != from_.size() || to == from_ || k_ == 0) return out;
  if (neighbours_.empty()) neighbours_ = nearestPoints(points_, from_, k_);
  for (size_t p = 0; p < points_.size() / 3; ++p) {
    const uint32_t* near = &neighbours_[p * k_];
    Eigen::Vector3f a = Eigen::Vector3f::Zero(), b = Eigen::Vector3f::Zero();
    for (int j = 0; j < k_; ++j) a += at(from_, near[j]), b += at(to, near[j]);
    a /= float(k_), b /= float(k_);
    // Kabsch: the rotation that best takes the neighbourhood from `from` to `to`.
    Eigen::Matrix3f covariance = Eigen::Matrix3f::Zero();
    for (int j = 0; j < k_; ++j) covariance += (at(from_, near[j]) - a) * (at(to, near[j]) - b).transpose();
    const Eigen::JacobiSVD<Eigen::Matrix3f> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3f flip = Eigen::Matrix3f::Identity();
    flip(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0f ? -1.0f : 1.0f;
    const Eigen::Matrix3f rotation = svd.matrixV() * flip * svd.matrixU().transpose();
    const Eigen::Vector3f moved = rotation * (at(points_, p) - a) + b;
    for (int c = 0; c < 3; ++c) out[3 * p + c] = moved[c];
  }
  return out;
}

}  // namespace mq
