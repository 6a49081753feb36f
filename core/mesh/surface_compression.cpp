#include "core/mesh/surface_compression.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "core/mesh/mesh.h"
#include "core/util/thread_pool.h"

namespace mq {
namespace {

constexpr int kPhaseSweeps = 2;
constexpr size_t kMinChunk = 4096;  // vertices; smaller meshes stay on the calling thread
const glm::vec3 kSignReference = glm::normalize(glm::vec3(0.81f, 0.47f, 0.35f));  // any axis unlikely to lie in a fold

glm::vec3 at(const std::vector<float>& xyz, size_t v) { return {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]}; }

// Row of the least-squares system for direction u: C's entries (a, b, c) in
// u^T C u = a x^2 + 2 b x y + c y^2.
glm::dvec3 rowOf(double x, double y) { return {x * x, 2.0 * x * y, y * y}; }

}  // namespace

SurfaceCompression::SurfaceCompression(const std::vector<float>& restPositions,
                                       const std::vector<uint32_t>& triangles) {
  const size_t n = restPositions.size() / 3;
  restPositions_ = restPositions;
  std::vector<std::vector<uint32_t>> adjacent(n);
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = triangles[t + k], b = triangles[t + (k + 1) % 3];
      adjacent[a].push_back(b);
      adjacent[b].push_back(a);
    }
  std::vector<float> normals;
  computeVertexNormals(restPositions, triangles, normals);
  firstEdge_.assign(n + 1, 0);
  tangentFrame_.assign(6 * n, 0.0f);
  inverseNormal_.assign(6 * n, 0.0f);
  for (size_t v = 0; v < n; ++v) {
    std::vector<uint32_t>& around = adjacent[v];
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    firstEdge_[v + 1] = firstEdge_[v] + static_cast<uint32_t>(around.size());
    // A tangent frame of the rest normal.
    glm::vec3 normal = at(normals, v);
    if (glm::dot(normal, normal) < 1e-20f) normal = {0, 0, 1};
    normal = glm::normalize(normal);
    const glm::vec3 helper = std::abs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 t1 = glm::normalize(glm::cross(helper, normal)), t2 = glm::cross(normal, t1);
    for (int c = 0; c < 3; ++c) {
      tangentFrame_[6 * v + c] = t1[c];
      tangentFrame_[6 * v + 3 + c] = t2[c];
    }
    glm::dmat3 normalMatrix(0.0);
    for (uint32_t u : around) {
      const glm::vec3 edge = at(restPositions, u) - at(restPositions, v);
      const glm::vec2 inPlane(glm::dot(edge, t1), glm::dot(edge, t2));
      const float planar = glm::length(inPlane);
      const glm::vec2 direction = planar > 0.0f ? inPlane / planar : glm::vec2(0.0f);
      neighbour_.push_back(u);
      const glm::dvec3 row = rowOf(direction.x, direction.y);
      inverseRestLengthSquared_.push_back(1.0f / std::max(glm::dot(edge, edge), 1e-30f));
      for (int k = 0; k < 3; ++k) rows_.push_back(float(row[k]));
      normalMatrix += glm::outerProduct(row, row);
    }
    if (std::abs(glm::determinant(normalMatrix)) < 1e-9) continue;  // fewer than 3 distinct directions
    const glm::dmat3 inverse = glm::inverse(normalMatrix);
    const float packed[6] = {float(inverse[0][0]), float(inverse[0][1]), float(inverse[0][2]),
                             float(inverse[1][1]), float(inverse[1][2]), float(inverse[2][2])};
    std::copy(packed, packed + 6, inverseNormal_.begin() + 6 * v);
  }
}

void SurfaceCompression::evaluate(const std::vector<float>& posedPositions, std::vector<float>& out,
                                  std::vector<float>* phase) const {
  const size_t n = vertexCount();
  std::vector<float> raw(4 * n, 0.0f);
  out.assign(4 * n, 0.0f);
  if (phase) phase->assign(n, 0.0f);
  if (posedPositions.size() != 3 * n) return;
  fitStretch(posedPositions, raw);
  smoothDirections(raw, out);
  if (phase) integratePhase(out, *phase);
}

void SurfaceCompression::fitStretch(const std::vector<float>& posedPositions, std::vector<float>& out) const {
  // Each vertex writes only its own 4 floats: split by index, deterministic.
  ThreadPool::shared().parallelFor(0, vertexCount(), kMinChunk, [&](size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v) {
      float* result = &out[4 * v];
      result[3] = 1.0f;
      const float* m = &inverseNormal_[6 * v];
      if (m[0] == 0.0f && m[3] == 0.0f && m[5] == 0.0f) continue;
      // Right-hand side of the normal equations: sum of row_e (l_e / L_e)^2.
      glm::vec3 rhs(0.0f);
      const glm::vec3 p = at(posedPositions, v);
      for (uint32_t e = firstEdge_[v]; e < firstEdge_[v + 1]; ++e) {
        const glm::vec3 d = at(posedPositions, neighbour_[e]) - p;
        rhs += glm::vec3(rows_[3 * e], rows_[3 * e + 1], rows_[3 * e + 2]) *
               (glm::dot(d, d) * inverseRestLengthSquared_[e]);
      }
      const double a = double(m[0]) * rhs.x + m[1] * rhs.y + m[2] * rhs.z;
      const double b = m[1] * rhs.x + m[3] * rhs.y + m[4] * rhs.z;
      const double c = m[2] * rhs.x + m[4] * rhs.y + m[5] * rhs.z;
      // Smallest eigenvalue of [[a, b], [b, c]] and its eigenvector.
      const double mean = 0.5 * (a + c), radius = std::sqrt(0.25 * (a - c) * (a - c) + b * b);
      const double smallest = mean - radius;
      result[3] = static_cast<float>(std::sqrt(std::max(smallest, 0.0)));
      // Not compressed (beyond skinning noise), or equally in every direction.
      if (smallest >= (1.0 - kMinCompression) * (1.0 - kMinCompression) || radius < 1e-12) continue;
      glm::dvec2 direction =
          std::abs(a - smallest) > std::abs(c - smallest) ? glm::dvec2(b, smallest - a) : glm::dvec2(smallest - c, b);
      direction = glm::normalize(direction);
      glm::vec3 across(0.0f);
      for (int k = 0; k < 3; ++k)
        across[k] =
            static_cast<float>(direction.x * tangentFrame_[6 * v + k] + direction.y * tangentFrame_[6 * v + 3 + k]);
      // u and -u are the same direction; one sign everywhere keeps neighbours
      // from cancelling when the shader interpolates them.
      if (glm::dot(across, kSignReference) < 0.0f) across = -across;
      for (int k = 0; k < 3; ++k) result[k] = across[k];
    }
  });
}

void SurfaceCompression::smoothDirections(const std::vector<float>& raw, std::vector<float>& out) const {
  ThreadPool::shared().parallelFor(0, vertexCount(), kMinChunk, [&](size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v) {
      const glm::vec3 own(raw[4 * v], raw[4 * v + 1], raw[4 * v + 2]);
      out[4 * v + 3] = raw[4 * v + 3];
      if (own == glm::vec3(0.0f)) continue;  // smoothing never spreads folds onto uncompressed skin
      glm::vec3 sum = (1.0f - raw[4 * v + 3]) * own;
      for (uint32_t e = firstEdge_[v]; e < firstEdge_[v + 1]; ++e) {
        const uint32_t u = neighbour_[e];
        glm::vec3 other(raw[4 * u], raw[4 * u + 1], raw[4 * u + 2]);
        if (glm::dot(other, own) < 0.0f) other = -other;
        sum += std::max(1.0f - raw[4 * u + 3], 0.0f) * other;
      }
      const glm::vec3 direction = glm::length(sum) > 1e-12f ? glm::normalize(sum) : own;
      for (int k = 0; k < 3; ++k) out[4 * v + k] = direction[k];
    }
  });
}

void SurfaceCompression::integratePhase(std::vector<float>& out, std::vector<float>& phase) const {
  const size_t n = vertexCount();
  std::vector<uint32_t> seeds;
  for (uint32_t v = 0; v < n; ++v)
    if (out[4 * v] != 0.0f || out[4 * v + 1] != 0.0f || out[4 * v + 2] != 0.0f) seeds.push_back(v);
  // Seeds in index order: a patch's phase origin is arbitrary (it only
  // shifts its folds), and the order never depends on timing.
  std::vector<bool> reached(n, false);
  std::vector<uint32_t> queue;
  for (uint32_t seed : seeds) {
    if (reached[seed]) continue;
    reached[seed] = true;
    phase[seed] = 0.0f;
    queue.assign(1, seed);
    for (size_t head = 0; head < queue.size(); ++head) {
      const uint32_t v = queue[head];
      const glm::vec3 a(out[4 * v], out[4 * v + 1], out[4 * v + 2]);
      for (uint32_t e = firstEdge_[v]; e < firstEdge_[v + 1]; ++e) {
        const uint32_t u = neighbour_[e];
        if (reached[u]) continue;
        glm::vec3 b(out[4 * u], out[4 * u + 1], out[4 * u + 2]);
        if (b == glm::vec3(0.0f)) continue;
        // Orient the neighbour like its parent, so the phase grows along it.
        if (glm::dot(a, b) < 0.0f) {
          b = -b;
          for (int k = 0; k < 3; ++k) out[4 * u + k] = b[k];
        }
        reached[u] = true;
        phase[u] = phase[v] + glm::dot(at(restPositions_, u) - at(restPositions_, v), 0.5f * (a + b));
        queue.push_back(u);
      }
    }
  }
  // Breadth-first sums depend on the path where the directions turn; a few
  // Jacobi sweeps of the same relation, averaged over each ring, even out
  // the seams where fronts met.
  std::vector<float> next(phase);
  for (int sweep = 0; sweep < kPhaseSweeps; ++sweep) {
    for (uint32_t v : seeds) {
      const glm::vec3 a(out[4 * v], out[4 * v + 1], out[4 * v + 2]);
      float sum = phase[v];
      int count = 1;
      for (uint32_t e = firstEdge_[v]; e < firstEdge_[v + 1]; ++e) {
        const uint32_t u = neighbour_[e];
        const glm::vec3 b(out[4 * u], out[4 * u + 1], out[4 * u + 2]);
        if (b == glm::vec3(0.0f) || glm::dot(a, b) <= 0.0f) continue;
        sum += phase[u] + glm::dot(at(restPositions_, v) - at(restPositions_, u), 0.5f * (a + b));
        ++count;
      }
      next[v] = sum / float(count);
    }
    phase.swap(next);
  }
}

}  // namespace mq
