#include "core/geometry/rigid_carry.h"

#include <algorithm>
#include <utility>

#include <Eigen/Dense>
#include <Eigen/SVD>

#include "core/geometry/nearest_points.h"

namespace mq {

namespace {

Eigen::Vector3f at(const std::vector<float>& flat, size_t i) { return {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]}; }

}  // namespace

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
