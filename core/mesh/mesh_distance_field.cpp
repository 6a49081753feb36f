#include "core/mesh/mesh_distance_field.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <unordered_map>

#include "core/mesh/closest_point.h"
#include "core/mesh/position_weld.h"
#include "core/util/thread_pool.h"

namespace mq {

namespace {

glm::vec3 vertexAt(const std::vector<float>& positions, uint32_t v) {
  return {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]};
}

// 1 for each vertex on an edge used by a single triangle (an open border).
std::vector<uint8_t> borderVertices(const std::vector<uint32_t>& triangles, size_t vertexCount) {
  std::unordered_map<uint64_t, int> uses;
  auto key = [](uint32_t a, uint32_t b) { return uint64_t(std::min(a, b)) << 32 | std::max(a, b); };
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
    for (int k = 0; k < 3; ++k) ++uses[key(triangles[t + k], triangles[t + (k + 1) % 3])];
  std::vector<uint8_t> border(vertexCount, 0);
  for (const auto& [edge, count] : uses)
    if (count == 1) border[edge >> 32] = border[edge & 0xffffffffu] = 1;
  return border;
}

}  // namespace

MeshDistanceField::MeshDistanceField(const std::vector<float>& positions, const std::vector<uint32_t>& triangles,
                                     const Aabb& region, float cell, float band)
    : cell_(std::max(cell, 1e-5f)), band_(std::max(band, 2.0f * std::max(cell, 1e-5f))) {
  if (!region.valid()) return;
  origin_ = region.min;
  dims_ = glm::max(glm::ivec3(glm::ceil((region.max - region.min) / cell_)) + 1, glm::ivec3(2));
  values_.assign(size_t(dims_.x) * dims_.y * dims_.z, band_);
  std::vector<uint8_t> known(values_.size(), 0);
  sampleBand(positions, triangles, known);
  signBeyondBand(known);
}

// Every grid point within the band of a triangle takes its distance to the
// nearest one. Exporters split vertices at UV seams: the mesh is welded
// first, so that only real borders count as open.
void MeshDistanceField::sampleBand(const std::vector<float>& positions, const std::vector<uint32_t>& triangles,
                                   std::vector<uint8_t>& known) {
  const PositionWeld weld = weldByPosition(positions, triangles);
  const std::vector<float> welded = weld.gather(positions);
  std::vector<float> normals;
  computeVertexNormals(welded, weld.triangles, normals);
  const std::vector<uint8_t> border = borderVertices(weld.triangles, weld.vertexCount());
  std::vector<float> unsignedDistance(values_.size(), band_);
  // Slabs of grid planes in parallel: each writes its own planes only.
  ThreadPool::shared().parallelFor(0, size_t(dims_.z), 4, [&](size_t zBegin, size_t zEnd) {
    for (size_t t = 0; t + 2 < weld.triangles.size(); t += 3) {
      const uint32_t v[3] = {weld.triangles[t], weld.triangles[t + 1], weld.triangles[t + 2]};
      const glm::vec3 a = vertexAt(welded, v[0]), b = vertexAt(welded, v[1]), c = vertexAt(welded, v[2]);
      glm::ivec3 lo =
          glm::max(glm::ivec3(glm::ceil((glm::min(glm::min(a, b), c) - band_ - origin_) / cell_)), glm::ivec3(0));
      glm::ivec3 hi =
          glm::min(glm::ivec3(glm::floor((glm::max(glm::max(a, b), c) + band_ - origin_) / cell_)), dims_ - 1);
      lo.z = std::max(lo.z, int(zBegin));
      hi.z = std::min(hi.z, int(zEnd) - 1);
      for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
          for (int x = lo.x; x <= hi.x; ++x) {
            const size_t i = index(x, y, z);
            const glm::vec3 p = origin_ + cell_ * glm::vec3(x, y, z);
            const glm::vec3 w = closestTriangleWeights(p, a, b, c);
            const glm::vec3 q = w.x * a + w.y * b + w.z * c;
            const float d = glm::length(p - q);
            if (d >= unsignedDistance[i] || d > band_) continue;
            unsignedDistance[i] = d;
            known[i] = 1;
            // On an open border (every vertex with weight is a border
            // vertex), the point is beside the surface, not inside it.
            bool onBorder = true;
            for (int k = 0; k < 3; ++k) onBorder = onBorder && (w[k] == 0.0f || border[v[k]]);
            const glm::vec3 n =
                w.x * vertexAt(normals, v[0]) + w.y * vertexAt(normals, v[1]) + w.z * vertexAt(normals, v[2]);
            values_[i] = onBorder || glm::dot(p - q, n) >= 0.0f ? d : -d;
          }
    }
  });
}

// Beyond the band, each grid point takes the sign of the band point a
// breadth-first walk reaches it from: inside stays inside, deep down.
void MeshDistanceField::signBeyondBand(std::vector<uint8_t>& known) {
  std::deque<size_t> queue;
  for (size_t i = 0; i < known.size(); ++i)
    if (known[i]) queue.push_back(i);
  const size_t strideY = size_t(dims_.x), strideZ = size_t(dims_.x) * dims_.y;
  while (!queue.empty()) {
    const size_t i = queue.front();
    queue.pop_front();
    const int x = int(i % strideY), y = int(i / strideY % dims_.y), z = int(i / strideZ);
    const float value = std::copysign(band_, values_[i]);
    auto visit = [&](bool inside, size_t j) {
      if (!inside || known[j]) return;
      known[j] = 1;
      values_[j] = value;
      queue.push_back(j);
    };
    visit(x > 0, i - 1);
    visit(x + 1 < dims_.x, i + 1);
    visit(y > 0, i - strideY);
    visit(y + 1 < dims_.y, i + strideY);
    visit(z > 0, i - strideZ);
    visit(z + 1 < dims_.z, i + strideZ);
  }
}

float MeshDistanceField::distance(const glm::vec3& p) const {
  if (values_.empty()) return band_;
  const glm::vec3 q = (p - origin_) / cell_;
  const glm::vec3 last = glm::vec3(dims_ - 1);
  if (!(q.x >= 0.0f && q.y >= 0.0f && q.z >= 0.0f && q.x <= last.x && q.y <= last.y && q.z <= last.z)) return band_;
  const glm::ivec3 c = glm::min(glm::ivec3(q), dims_ - 2);
  const glm::vec3 f = q - glm::vec3(c);
  auto at = [&](int dx, int dy, int dz) { return values_[index(c.x + dx, c.y + dy, c.z + dz)]; };
  const float x00 = glm::mix(at(0, 0, 0), at(1, 0, 0), f.x), x10 = glm::mix(at(0, 1, 0), at(1, 1, 0), f.x);
  const float x01 = glm::mix(at(0, 0, 1), at(1, 0, 1), f.x), x11 = glm::mix(at(0, 1, 1), at(1, 1, 1), f.x);
  return glm::mix(glm::mix(x00, x10, f.y), glm::mix(x01, x11, f.y), f.z);
}

glm::vec3 MeshDistanceField::outward(const glm::vec3& p) const {
  const float h = 0.5f * cell_;
  const glm::vec3 g(distance(p + glm::vec3(h, 0, 0)) - distance(p - glm::vec3(h, 0, 0)),
                    distance(p + glm::vec3(0, h, 0)) - distance(p - glm::vec3(0, h, 0)),
                    distance(p + glm::vec3(0, 0, h)) - distance(p - glm::vec3(0, 0, h)));
  const float len = glm::length(g);
  return len > 1e-6f * h ? g / len : glm::vec3(0.0f);
}

bool MeshDistanceField::pushOut(glm::vec3& p, float margin, glm::vec3* normal) const {
  // The field is a distance only within the band, and trilinear: a few
  // steps along the gradient settle the point at the margin. Where they do
  // not (a fold, the rim of a hole), the farthest out of them is kept.
  glm::vec3 best = p, bestNormal(0.0f), q = p;
  float bestDistance = distance(p), d = bestDistance;
  if (bestDistance >= margin) return false;
  for (int step = 0; step < 6 && bestDistance < margin; ++step) {
    const glm::vec3 out = outward(q);
    if (out == glm::vec3(0.0f)) break;
    q += out * (margin - d + 1e-5f);
    d = distance(q);
    if (d > bestDistance) {
      best = q;
      bestNormal = out;
      bestDistance = d;
    }
  }
  if (best == p) return false;
  p = best;
  if (normal) *normal = bestNormal;
  return true;
}

}  // namespace mq
