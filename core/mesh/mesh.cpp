#include "core/mesh/mesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mq {

int SkinBinding::maxInfluences() const {
  if (empty()) return 0;
  const size_t k = influencesPerVertex;
  int best = 0;
  for (size_t v = 0; v * k < weights.size(); ++v) {
    int count = 0;
    for (size_t i = 0; i < k; ++i) count += weights[v * k + i] > 0.0f;
    best = std::max(best, count);
  }
  return best;
}

void SkinBinding::normalise() {
  if (empty()) return;
  const size_t k = influencesPerVertex;
  for (size_t v = 0; v * k < weights.size(); ++v) {
    float* w = &weights[v * k];
    const float sum = std::accumulate(w, w + k, 0.0f);
    if (sum > 0.0f)
      for (size_t i = 0; i < k; ++i) w[i] /= sum;
  }
}

void SkinBinding::limitInfluences(int limit) {
  if (empty() || influencesPerVertex <= limit) return;
  const size_t k = influencesPerVertex;
  const size_t vertices = weights.size() / k;
  std::vector<uint16_t> newJoints(vertices * limit, 0);
  std::vector<float> newWeights(vertices * limit, 0.0f);
  std::vector<int> order(k);
  for (size_t v = 0; v < vertices; ++v) {
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return weights[v * k + a] > weights[v * k + b]; });
    for (int i = 0; i < limit; ++i) {
      newJoints[v * limit + i] = joints[v * k + order[i]];
      newWeights[v * limit + i] = weights[v * k + order[i]];
    }
  }
  joints = std::move(newJoints);
  weights = std::move(newWeights);
  influencesPerVertex = limit;
  normalise();
}

void SkinBinding::makeRigid() {
  limitInfluences(1);
  for (float& w : weights) w = w > 0.0f ? 1.0f : 0.0f;
}

std::vector<float> SkinBinding::weightsOfBone(int bone, size_t vertices) const {
  std::vector<float> out(vertices, 0.0f);
  const int k = influencesPerVertex;
  if (k == 0 || joints.size() < vertices * k) return out;
  for (size_t v = 0; v < vertices; ++v)
    for (int i = 0; i < k; ++i) {
      const uint16_t joint = joints[v * k + i];
      if (joint < jointBones.size() && jointBones[joint] == bone) out[v] += weights[v * k + i];
    }
  return out;
}

std::vector<Submesh> Mesh::drawRanges() const {
  if (!submeshes.empty()) return submeshes;
  return {Submesh{0, static_cast<uint32_t>(triangleCount()), material}};
}

void computeVertexNormals(const std::vector<float>& positions, const std::vector<uint32_t>& triangles,
                          std::vector<float>& normals) {
  normals.assign(positions.size(), 0.0f);
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const uint32_t i0 = triangles[t], i1 = triangles[t + 1], i2 = triangles[t + 2];
    const glm::vec3 a(positions[3 * i0], positions[3 * i0 + 1], positions[3 * i0 + 2]);
    const glm::vec3 b(positions[3 * i1], positions[3 * i1 + 1], positions[3 * i1 + 2]);
    const glm::vec3 c(positions[3 * i2], positions[3 * i2 + 1], positions[3 * i2 + 2]);
    const glm::vec3 n = glm::cross(b - a, c - a);  // length = 2 * area
    for (uint32_t i : {i0, i1, i2})
      for (int d = 0; d < 3; ++d) normals[3 * i + d] += n[d];
  }
  for (size_t v = 0; v + 2 < normals.size(); v += 3) {
    const float len =
        std::sqrt(normals[v] * normals[v] + normals[v + 1] * normals[v + 1] + normals[v + 2] * normals[v + 2]);
    if (len > 0.0f)
      for (int d = 0; d < 3; ++d) normals[v + d] /= len;
    else
      normals[v + 1] = 1.0f;
  }
}

Aabb boundsOf(const std::vector<float>& positions) {
  Aabb box;
  for (size_t i = 0; i + 2 < positions.size(); i += 3) box.extend({positions[i], positions[i + 1], positions[i + 2]});
  return box;
}

}  // namespace mq
