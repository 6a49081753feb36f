#include "core/geometry/rigid_carry.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

#include <Eigen/Dense>
#include <Eigen/SVD>

namespace mq {

namespace {

Eigen::Vector3f at(const std::vector<float>& flat, size_t i) { return {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]}; }

// A uniform grid over a point set, for k-nearest queries by growing rings.
class PointGrid {
 public:
  PointGrid(const std::vector<float>& set, float cell) : set_(set), cell_(cell) {
    for (size_t i = 0; i < set.size() / 3; ++i) cells_[key(cellOf(at(set, i)))].push_back(uint32_t(i));
  }

  void nearest(const Eigen::Vector3f& p, int k, std::vector<std::pair<float, uint32_t>>& out) const {
    out.clear();
    const Eigen::Vector3i c = cellOf(p);
    for (int ring = 0; ring < 24; ++ring) {
      for (int x = c.x() - ring; x <= c.x() + ring; ++x)
        for (int y = c.y() - ring; y <= c.y() + ring; ++y)
          for (int z = c.z() - ring; z <= c.z() + ring; ++z) {
            if (std::max({std::abs(x - c.x()), std::abs(y - c.y()), std::abs(z - c.z())}) != ring) continue;
            const auto found = cells_.find(key({x, y, z}));
            if (found == cells_.end()) continue;
            for (uint32_t i : found->second) out.push_back({(at(set_, i) - p).squaredNorm(), i});
          }
      // Points beyond this ring are at least ring * cell away.
      if (int(out.size()) >= k) {
        std::partial_sort(out.begin(), out.begin() + k, out.end());
        const float reach = ring * cell_;
        if (out[k - 1].first <= reach * reach) break;
      }
    }
    if (int(out.size()) < k) {  // far from everything: every point
      out.clear();
      for (uint32_t i = 0; i < set_.size() / 3; ++i) out.push_back({(at(set_, i) - p).squaredNorm(), i});
    }
    std::sort(out.begin(), out.end());
    if (int(out.size()) > k) out.resize(k);
  }

 private:
  Eigen::Vector3i cellOf(const Eigen::Vector3f& p) const {
    return {int(std::floor(p.x() / cell_)), int(std::floor(p.y() / cell_)), int(std::floor(p.z() / cell_))};
  }
  static int64_t key(const Eigen::Vector3i& c) {
    return (int64_t(c.x()) & 0x1fffff) | ((int64_t(c.y()) & 0x1fffff) << 21) | ((int64_t(c.z()) & 0x1fffff) << 42);
  }

  const std::vector<float>& set_;
  float cell_;
  std::unordered_map<int64_t, std::vector<uint32_t>> cells_;
};

// A cell holding a few points on average over the set's bounding box.
float cellFor(const std::vector<float>& set) {
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(1e30f), hi = -lo;
  for (size_t i = 0; i < set.size() / 3; ++i) lo = lo.cwiseMin(at(set, i)), hi = hi.cwiseMax(at(set, i));
  const float volume = std::max(1e-9f, (hi - lo).cwiseMax(1e-3f).prod());
  return std::max(1e-3f, std::cbrt(8.0f * volume / std::max<size_t>(1, set.size() / 3)));
}

}  // namespace

std::vector<uint32_t> nearestPoints(const std::vector<float>& queries, const std::vector<float>& set, int k) {
  std::vector<uint32_t> out;
  const size_t count = set.size() / 3;
  k = int(std::min<size_t>(size_t(std::max(k, 1)), count));
  if (k == 0) return out;
  const PointGrid grid(set, cellFor(set));
  std::vector<std::pair<float, uint32_t>> found;
  out.reserve(queries.size() / 3 * k);
  for (size_t q = 0; q < queries.size() / 3; ++q) {
    grid.nearest(at(queries, q), k, found);
    for (const auto& [d, i] : found) out.push_back(i);
  }
  return out;
}

RigidCarry::RigidCarry(std::vector<float> points, std::vector<float> from, int k)
    : points_(std::move(points)), from_(std::move(from)) {
  k_ = int(std::min<size_t>(size_t(std::max(k, 1)), from_.size() / 3));
  neighbours_ = nearestPoints(points_, from_, k_);
}

std::vector<float> RigidCarry::carry(const std::vector<float>& to) const {
  std::vector<float> out = points_;
  if (to.size() != from_.size() || to == from_ || k_ == 0) return out;
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
