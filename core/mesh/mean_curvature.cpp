#include "core/mesh/mean_curvature.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>

#include <glm/glm.hpp>

#include "core/mesh/position_weld.h"

namespace mq {
namespace {

glm::dvec3 at(const std::vector<float>& xyz, size_t v) { return {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]}; }

double cotangent(const glm::dvec3& a, const glm::dvec3& b) {
  const double sine = glm::length(glm::cross(a, b));
  return sine > 1e-300 ? glm::dot(a, b) / sine : 0.0;
}

}  // namespace

std::vector<float> vertexMeanCurvature(const std::vector<float>& positions, const std::vector<float>& normals,
                                       const std::vector<uint32_t>& triangles, int smoothingPasses) {
  const size_t n = positions.size() / 3;
  std::vector<float> curvature(n, 0.0f);
  if (n == 0 || normals.size() != positions.size()) return curvature;
  const PositionWeld weld = weldByPosition(positions, triangles);
  const std::vector<float> welded = weld.gather(positions);
  const size_t w = weld.vertexCount();
  std::vector<glm::dvec3> laplacian(w, glm::dvec3(0.0));
  std::vector<double> area(w, 0.0);
  std::map<std::pair<uint32_t, uint32_t>, int> edgeUses;  // an edge used once lies on a boundary
  for (size_t t = 0; t + 2 < weld.triangles.size(); t += 3) {
    const uint32_t idx[3] = {weld.triangles[t], weld.triangles[t + 1], weld.triangles[t + 2]};
    const glm::dvec3 p[3] = {at(welded, idx[0]), at(welded, idx[1]), at(welded, idx[2])};
    const double triangleArea = 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
    double cot[3];
    int obtuse = -1;
    for (int k = 0; k < 3; ++k) {
      // The angle at corner k weighs the opposite edge (i, j).
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      cot[k] = cotangent(p[i] - p[k], p[j] - p[k]);
      if (glm::dot(p[i] - p[k], p[j] - p[k]) < 0.0) obtuse = k;
      laplacian[idx[i]] += cot[k] * (p[j] - p[i]);
      laplacian[idx[j]] += cot[k] * (p[i] - p[j]);
      ++edgeUses[std::minmax(idx[i], idx[j])];
    }
    // Meyer et al.'s mixed area: the Voronoi region, or a share of an obtuse triangle.
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      if (obtuse < 0) {
        area[idx[k]] +=
            (glm::dot(p[i] - p[k], p[i] - p[k]) * cot[j] + glm::dot(p[j] - p[k], p[j] - p[k]) * cot[i]) / 8.0;
      } else {
        area[idx[k]] += triangleArea * (obtuse == k ? 0.5 : 0.25);
      }
    }
  }
  std::vector<bool> boundary(w, false);
  for (const auto& [edge, uses] : edgeUses)
    if (uses == 1) boundary[edge.first] = boundary[edge.second] = true;
  std::vector<float> welded_h(w, 0.0f);
  std::vector<bool> known(w, false);
  for (uint32_t u = 0; u < w; ++u) {
    if (boundary[u] || area[u] <= 0.0) continue;
    const glm::dvec3 delta = laplacian[u] / (2.0 * area[u]);
    welded_h[u] = static_cast<float>(-0.5 * glm::dot(delta, glm::normalize(at(normals, weld.representative[u]))));
    known[u] = true;
  }
  if (smoothingPasses > 0) {
    std::vector<std::vector<uint32_t>> ring(w);
    for (const auto& [edge, uses] : edgeUses) {
      ring[edge.first].push_back(edge.second);
      ring[edge.second].push_back(edge.first);
    }
    std::vector<float> next(w, 0.0f), values;
    // The ring's median first: a sliver's lone spike goes, a ridge stays.
    for (int pass = 0; pass <= smoothingPasses; ++pass) {
      for (uint32_t u = 0; u < w; ++u) {
        next[u] = welded_h[u];
        if (!known[u]) continue;
        values.assign(1, welded_h[u]);
        for (uint32_t r : ring[u])
          if (known[r]) values.push_back(welded_h[r]);
        if (pass == 0) {
          std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
          next[u] = values[values.size() / 2];
        } else {
          float sum = 0.0f;
          for (float value : values) sum += value;
          next[u] = sum / float(values.size());
        }
      }
      welded_h.swap(next);
    }
  }
  // Each original vertex reads its welded vertex (matched by position).
  std::map<std::array<float, 3>, uint32_t> byPosition;
  for (uint32_t v = 0; v < w; ++v) byPosition[{welded[3 * v], welded[3 * v + 1], welded[3 * v + 2]}] = v;
  for (size_t v = 0; v < n; ++v) {
    const auto found = byPosition.find({positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]});
    if (found != byPosition.end()) curvature[v] = welded_h[found->second];
  }
  return curvature;
}

}  // namespace mq
