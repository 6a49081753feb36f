#include "core/mesh/tangents.h"

#include <cmath>

#include <glm/glm.hpp>

namespace mq {
namespace {

glm::vec3 load3(const std::vector<float>& a, size_t i) { return {a[3 * i], a[3 * i + 1], a[3 * i + 2]}; }

// A unit vector perpendicular to unit n.
glm::vec3 anyPerpendicular(const glm::vec3& n) {
  const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(n, axis));
}

glm::vec3 orthogonalTo(const glm::vec3& t, const glm::vec3& n) {
  const glm::vec3 projected = t - n * glm::dot(n, t);
  const float length = glm::length(projected);
  return length > 1e-12f ? projected / length : anyPerpendicular(n);
}

void store4(std::vector<float>& a, size_t i, const glm::vec3& t, float w) {
  a[4 * i] = t.x;
  a[4 * i + 1] = t.y;
  a[4 * i + 2] = t.z;
  a[4 * i + 3] = w;
}

}  // namespace

void computeVertexTangents(const std::vector<float>& positions, const std::vector<float>& normals,
                           const std::vector<float>& uvs, const std::vector<uint32_t>& triangles,
                           std::vector<float>& tangents) {
  const size_t n = positions.size() / 3;
  std::vector<glm::vec3> sumU(n, glm::vec3(0.0f)), sumV(n, glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const uint32_t i0 = triangles[t], i1 = triangles[t + 1], i2 = triangles[t + 2];
    const glm::vec3 e1 = load3(positions, i1) - load3(positions, i0);
    const glm::vec3 e2 = load3(positions, i2) - load3(positions, i0);
    const glm::vec2 d1(uvs[2 * i1] - uvs[2 * i0], uvs[2 * i1 + 1] - uvs[2 * i0 + 1]);
    const glm::vec2 d2(uvs[2 * i2] - uvs[2 * i0], uvs[2 * i2 + 1] - uvs[2 * i0 + 1]);
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(det) < 1e-20f) continue;
    // Unnormalised on purpose: larger triangles weigh more.
    const glm::vec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
    const glm::vec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
    for (uint32_t i : {i0, i1, i2}) {
      sumU[i] += dPdu;
      sumV[i] += dPdv;
    }
  }
  tangents.assign(4 * n, 0.0f);
  for (size_t v = 0; v < n; ++v) {
    const glm::vec3 normal = glm::normalize(load3(normals, v));
    const glm::vec3 tangent = orthogonalTo(sumU[v], normal);
    // glTF's uvs start at the image's top left, so the normal map's "up" (its
    // bitangent, cross(n, t) * w) runs towards decreasing v.
    const float handedness = glm::dot(glm::cross(normal, tangent), sumV[v]) > 0.0f ? -1.0f : 1.0f;
    store4(tangents, v, tangent, handedness);
  }
}

void carryTangents(const std::vector<float>& restNormals, const std::vector<float>& restTangents,
                   const std::vector<float>& posedNormals, std::vector<float>& posedTangents) {
  const size_t n = restTangents.size() / 4;
  posedTangents.resize(4 * n);
  for (size_t v = 0; v < n; ++v) {
    const glm::vec3 from = glm::normalize(load3(restNormals, v));
    const glm::vec3 to = glm::normalize(load3(posedNormals, v));
    const glm::vec3 t(restTangents[4 * v], restTangents[4 * v + 1], restTangents[4 * v + 2]);
    // Rodrigues' rotation by the angle between the normals about their cross
    // product, written without trigonometry: with c = cos, k = from x to,
    // R t = c t + k x t + k (k.t) / (1 + c).
    const float c = glm::dot(from, to);
    const glm::vec3 k = glm::cross(from, to);
    const glm::vec3 turned = c > -0.9999f ? c * t + glm::cross(k, t) + k * (glm::dot(k, t) / (1.0f + c)) : -t;
    store4(posedTangents, v, orthogonalTo(turned, to), restTangents[4 * v + 3]);
  }
}

}  // namespace mq
