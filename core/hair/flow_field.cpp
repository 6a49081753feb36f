#include "core/hair/flow_field.h"

#include <cmath>

#include <Eigen/Dense>

#include "core/hair/source_sum.h"

namespace mq {

struct FlowField::Factorisation {
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
};

namespace {

constexpr float kInvFourPi = 0.0795774715f;
constexpr float kCoreFraction = 0.02f;  // source core radius / sqrt(panel area)

inline glm::vec3 sourceVelocity(const PointSource& s, const glm::vec3& x) {
  const glm::vec3 d = x - s.position;
  const float r2 = s.radius * s.radius;
  const float q = glm::dot(d, d) + r2;
  return d * (s.strength * r2 / (q * std::sqrt(q)));
}

inline glm::vec3 vortexVelocity(const Vortex& v, const glm::vec3& x) {
  const glm::vec3 d = x - v.position;
  const float r2 = v.radius * v.radius;
  const float falloff = std::exp(0.5f - glm::dot(d, d) / (2.0f * r2));
  return glm::cross(v.axis, d) * (v.strength / v.radius * falloff);
}

}  // namespace

void FlowField::setObstacle(const SurfacePanels& panels, const std::vector<uint8_t>& scalpPanel) {
  panels_ = panels;
  scalpPanel_ = scalpPanel;
  scalpPanel_.resize(panels.size(), 0);
  const int n = int(panels.size());
  sourcePositions_.resize(n);
  for (int j = 0; j < n; ++j) {
    const float depth = j < int(panels.depths.size()) ? panels.depths[j] : std::sqrt(panels.areas[j]);
    sourcePositions_[j] = panels.centers[j] - depth * panels.normals[j];
  }
  const size_t padded = (panels.size() + 15) & ~size_t(15);  // whole AVX-512 lanes
  px_.assign(padded, 0.0f);
  py_.assign(padded, 0.0f);
  pz_.assign(padded, 0.0f);
  weight_.assign(padded, 0.0f);
  core2_.assign(padded, 1.0f);
  for (int j = 0; j < n; ++j) {
    px_[j] = sourcePositions_[j].x;
    py_[j] = sourcePositions_[j].y;
    pz_[j] = sourcePositions_[j].z;
    core2_[j] = kCoreFraction * kCoreFraction * panels.areas[j];
  }
  // a(i, j): normal velocity at collocation point i from a unit flux at source j.
  Eigen::MatrixXd a(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const glm::vec3 d = panels.centers[i] - sourcePositions_[j];
      const float q = glm::dot(d, d) + core2_[j];
      a(i, j) = kInvFourPi * glm::dot(d, panels.normals[i]) / (q * std::sqrt(q));
    }
  lu_ = std::make_shared<const Factorisation>(Factorisation{Eigen::PartialPivLU<Eigen::MatrixXd>(a)});
  solveStrengths();
}

void FlowField::setPrimitives(const FlowPrimitives& primitives, const glm::vec3& headOrigin, float scalpOutflow) {
  streams_.clear();
  uniform_ = glm::vec3(0.0f);
  for (UniformStream s : primitives.streams) {
    const float len = glm::length(s.direction);
    if (len <= 0.0f) continue;
    s.direction /= len;
    uniform_ += s.direction * s.strength;
    streams_.push_back(s);
  }
  sources_ = primitives.sources;
  for (PointSource& s : sources_) {
    s.position += headOrigin;
    s.radius = std::max(s.radius, 1e-4f);
  }
  vortices_.clear();
  for (Vortex v : primitives.vortices) {
    const float len = glm::length(v.axis);
    if (len <= 0.0f) continue;
    v.axis /= len;
    v.position += headOrigin;
    v.radius = std::max(v.radius, 1e-4f);
    vortices_.push_back(v);
  }
  scalpOutflow_ = scalpOutflow;
  solveStrengths();
}

void FlowField::setNoise(uint32_t seed, float amplitude, float wavelength) {
  perlin_ = PerlinNoise(seed);
  noiseAmplitude_ = amplitude;
  noiseFrequency_ = wavelength > 0.0f ? 1.0f / wavelength : 1.0f;
}

void FlowField::solveStrengths() {
  const int n = int(panels_.size());
  flux_.assign(n, 0.0f);
  target_.assign(n, 0.0f);
  if (n == 0) return;
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) {
    target_[i] = scalpPanel_[i] ? scalpOutflow_ : 0.0f;
    rhs[i] = target_[i] - glm::dot(primitiveVelocity(panels_.centers[i]), panels_.normals[i]);
  }
  const Eigen::VectorXd q = lu_->lu.solve(rhs);
  for (int j = 0; j < n; ++j) {
    flux_[j] = float(q[j]);
    weight_[j] = float(q[j]) * kInvFourPi;
  }
}

glm::vec3 FlowField::primitiveVelocity(const glm::vec3& x) const {
  glm::vec3 v = uniform_;
  for (const PointSource& s : sources_) v += sourceVelocity(s, x);
  for (const Vortex& w : vortices_) v += vortexVelocity(w, x);
  return v;
}

glm::vec3 FlowField::panelVelocity(const glm::vec3& x, int skip) const {
  const SourceSumKernel kernel = fastestSourceSumKernel();
  glm::vec3 v = sumSources(kernel, px_.data(), py_.data(), pz_.data(), weight_.data(), core2_.data(), px_.size(), x);
  if (skip >= 0 && size_t(skip) < panels_.size()) {
    const glm::vec3 d = x - sourcePositions_[skip];
    const float r2 = glm::dot(d, d) + core2_[skip];
    v -= d * (weight_[skip] / (r2 * std::sqrt(r2)));
  }
  return v;
}

glm::vec3 FlowField::noise(const glm::vec3& x) const {
  if (noiseAmplitude_ <= 0.0f) return glm::vec3(0.0f);
  return noiseAmplitude_ * perlin_.noise3(x * noiseFrequency_);
}

}  // namespace mq
