#include "core/hair/root_sampling.h"

#include <algorithm>
#include <cmath>

namespace mq {

namespace {

// SplitMix64: fast, good enough for sample positions, and reproducible everywhere.
struct Rng {
  uint64_t state;
  explicit Rng(uint64_t seed) : state(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull) {}
  uint64_t next() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  float uniform() { return float(next() >> 40) * (1.0f / 16777216.0f); }
};

struct Candidates {
  std::vector<glm::vec3> positions, normals;
};

Candidates randomPoints(const ScalpSurface& scalp, size_t count, uint32_t seed) {
  const size_t triangles = scalp.triangleCount();
  std::vector<double> cdf(triangles);
  double total = 0.0;
  for (size_t t = 0; t < triangles; ++t) {
    const glm::vec3 a = scalp.position(scalp.triangles[3 * t]), b = scalp.position(scalp.triangles[3 * t + 1]),
                    c = scalp.position(scalp.triangles[3 * t + 2]);
    total += 0.5 * glm::length(glm::cross(b - a, c - a));
    cdf[t] = total;
  }
  Candidates out;
  out.positions.reserve(count);
  out.normals.reserve(count);
  Rng rng(seed);
  for (size_t i = 0; i < count; ++i) {
    const double pick = double(rng.uniform()) * total;
    const size_t t = std::min(size_t(std::upper_bound(cdf.begin(), cdf.end(), pick) - cdf.begin()), triangles - 1);
    float u = rng.uniform(), v = rng.uniform();
    if (u + v > 1.0f) {
      u = 1.0f - u;
      v = 1.0f - v;
    }
    const uint32_t* tri = &scalp.triangles[3 * t];
    const float w = 1.0f - u - v;
    out.positions.push_back(w * scalp.position(tri[0]) + u * scalp.position(tri[1]) + v * scalp.position(tri[2]));
    glm::vec3 n = w * scalp.normal(tri[0]) + u * scalp.normal(tri[1]) + v * scalp.normal(tri[2]);
    const float len = glm::length(n);
    out.normals.push_back(len > 0.0f ? n / len : glm::vec3(0, 1, 0));
  }
  return out;
}

// The 2D grid over the projection: cells of at least the disk radius, each a
// linked list of accepted roots.
class ProjectedGrid {
 public:
  ProjectedGrid(const std::vector<glm::vec3>& points, const glm::vec3& axis, float radius) {
    const glm::vec3 helper = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    u_ = glm::normalize(glm::cross(helper, axis));
    v_ = glm::cross(axis, u_);
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : points) {
      const glm::vec2 q = project(p);
      lo = glm::min(lo, q);
      hi = glm::max(hi, q);
    }
    origin_ = lo;
    const glm::vec2 extent = hi - lo + glm::vec2(1e-6f);
    cell_ = std::max(radius, std::sqrt(extent.x * extent.y / 4.0e6f));
    nu_ = int(extent.x / cell_) + 1;
    nv_ = int(extent.y / cell_) + 1;
    head_.assign(size_t(nu_) * nv_, -1);
  }
  glm::vec2 project(const glm::vec3& p) const { return {glm::dot(p, u_), glm::dot(p, v_)}; }
  glm::ivec2 cellOf(const glm::vec3& p) const {
    const glm::vec2 q = (project(p) - origin_) / cell_;
    return {std::clamp(int(q.x), 0, nu_ - 1), std::clamp(int(q.y), 0, nv_ - 1)};
  }
  // True when no accepted point lies within sqrt(r2) of p.
  bool isFree(const glm::vec3& p, float r2, const std::vector<glm::vec3>& accepted,
              const std::vector<int>& next) const {
    const glm::ivec2 c = cellOf(p);
    for (int j = std::max(0, c.y - 1); j <= std::min(nv_ - 1, c.y + 1); ++j)
      for (int i = std::max(0, c.x - 1); i <= std::min(nu_ - 1, c.x + 1); ++i)
        for (int k = head_[size_t(j) * nu_ + i]; k >= 0; k = next[k]) {
          const glm::vec3 d = accepted[k] - p;
          if (glm::dot(d, d) < r2) return false;
        }
    return true;
  }
  void insert(const glm::vec3& p, int index, std::vector<int>& next) {
    const glm::ivec2 c = cellOf(p);
    int& head = head_[size_t(c.y) * nu_ + c.x];
    next.push_back(head);
    head = index;
  }

 private:
  glm::vec3 u_, v_;
  glm::vec2 origin_;
  float cell_ = 1.0f;
  int nu_ = 1, nv_ = 1;
  std::vector<int> head_;
};

glm::vec3 meanNormal(const ScalpSurface& scalp) {
  glm::vec3 sum(0.0f);
  for (size_t t = 0; t < scalp.triangleCount(); ++t) {
    const glm::vec3 a = scalp.position(scalp.triangles[3 * t]), b = scalp.position(scalp.triangles[3 * t + 1]),
                    c = scalp.position(scalp.triangles[3 * t + 2]);
    sum += glm::cross(b - a, c - a);
  }
  const float len = glm::length(sum);
  return len > 1e-12f ? sum / len : glm::vec3(0, 1, 0);
}

}  // namespace

size_t rootCountForDensity(const ScalpSurface& scalp, float hairsPerCm2, size_t maxCount) {
  const double count = double(scalp.area()) * 1e4 * double(std::max(0.0f, hairsPerCm2));
  return std::min(maxCount, size_t(count));
}

HairRoots sampleRoots(const ScalpSurface& scalp, size_t count, uint32_t seed) {
  HairRoots roots;
  if (count == 0 || scalp.empty()) return roots;
  const float area = scalp.area();
  if (area <= 0.0f) return roots;
  const Candidates candidates = randomPoints(scalp, std::max<size_t>(4 * count, 256), seed);
  // Random sequential addition saturates near 0.7 area / r^2 disks; ask for
  // about 70% of that and shrink the radius in the rare case it falls short.
  float radius = std::sqrt(0.5f * area / float(count));
  for (int attempt = 0; attempt < 20; ++attempt, radius *= 0.9f) {
    ProjectedGrid grid(candidates.positions, meanNormal(scalp), radius);
    std::vector<glm::vec3> accepted;
    std::vector<int> next, acceptedIndex;
    accepted.reserve(count);
    next.reserve(count);
    const float r2 = radius * radius;
    for (size_t i = 0; i < candidates.positions.size() && accepted.size() < count; ++i) {
      const glm::vec3& p = candidates.positions[i];
      if (!grid.isFree(p, r2, accepted, next)) continue;
      grid.insert(p, int(accepted.size()), next);
      accepted.push_back(p);
      acceptedIndex.push_back(int(i));
    }
    if (accepted.size() < count && attempt + 1 < 20) continue;
    roots.minDistance = radius;
    roots.positions.reserve(3 * accepted.size());
    roots.normals.reserve(3 * accepted.size());
    for (size_t k = 0; k < accepted.size(); ++k) {
      const glm::vec3 n = candidates.normals[acceptedIndex[k]];
      for (int d = 0; d < 3; ++d) roots.positions.push_back(accepted[k][d]);
      for (int d = 0; d < 3; ++d) roots.normals.push_back(n[d]);
    }
    break;
  }
  return roots;
}

}  // namespace mq
