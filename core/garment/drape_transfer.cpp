#include "core/garment/drape_transfer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

#include "core/garment/panel_coordinates.h"
#include "core/geometry/nearest_points.h"
#include "core/util/error.h"

namespace mq {

namespace {

using namespace panel_coordinates;

glm::vec3 at(const std::vector<float>& flat, size_t v) { return {flat[3 * v], flat[3 * v + 1], flat[3 * v + 2]}; }

// Barycentric coordinates of p in the 2D triangle (a, b, c); degenerate: far outside.
glm::vec3 barycentric(glm::vec2 p, glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  const glm::vec2 e0 = b - a, e1 = c - a, d = p - a;
  const float det = e0.x * e1.y - e0.y * e1.x;
  if (std::abs(det) < 1e-12f) return {-1e9f, 0.0f, 0.0f};
  const float u = (d.x * e1.y - d.y * e1.x) / det;
  const float w = (e0.x * d.y - e0.y * d.x) / det;
  return {1.0f - u - w, u, w};
}

// One panel of the old mesh: its triangles bucketed on a grid over its pattern.
class PanelLocator {
 public:
  PanelLocator(const GarmentMesh& mesh, const std::vector<uint32_t>& triangles, const PanelBounds& bounds)
      : mesh_(mesh), triangles_(triangles), bounds_(bounds) {
    const size_t count = std::max<size_t>(1, triangles.size() / 3);
    cells_ = std::clamp(int(std::sqrt(float(count)) / 2.0f), 1, 64);
    buckets_.resize(size_t(cells_) * cells_);
    for (size_t t = 0; t < triangles.size() / 3; ++t) {
      glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
      for (int k = 0; k < 3; ++k) lo = glm::min(lo, corner(t, k)), hi = glm::max(hi, corner(t, k));
      const glm::ivec2 a = cellOf(lo), b = cellOf(hi);
      for (int y = a.y; y <= b.y; ++y)
        for (int x = a.x; x <= b.x; ++x) buckets_[size_t(y) * cells_ + x].push_back(uint32_t(t));
    }
  }

  // The drape at pattern point p: inside a triangle when one holds it, else
  // at the nearest edge of the triangles around (p is then just outside).
  glm::vec3 drapeAt(glm::vec2 p, const std::vector<float>& drape) const {
    float bestOutside = std::numeric_limits<float>::max();
    size_t bestTriangle = 0;
    glm::vec3 bestWeights(1.0f, 0.0f, 0.0f);
    const glm::ivec2 c = cellOf(p);
    for (int ring = 0; ring < cells_; ++ring) {
      for (int y = c.y - ring; y <= c.y + ring; ++y)
        for (int x = c.x - ring; x <= c.x + ring; ++x) {
          if (std::max(std::abs(x - c.x), std::abs(y - c.y)) != ring) continue;
          if (x < 0 || y < 0 || x >= cells_ || y >= cells_) continue;
          for (uint32_t t : buckets_[size_t(y) * cells_ + x]) {
            const glm::vec3 w = barycentric(p, corner(t, 0), corner(t, 1), corner(t, 2));
            const float outside = -std::min({w.x, w.y, w.z, 0.0f});
            if (outside < bestOutside) bestOutside = outside, bestTriangle = t, bestWeights = w;
          }
        }
      if (bestOutside == 0.0f || (bestOutside < 1.0f && ring > 0)) break;
    }
    glm::vec3 w = glm::max(bestWeights, glm::vec3(0.0f));
    w /= std::max(w.x + w.y + w.z, 1e-12f);
    const uint32_t* v = &triangles_[3 * bestTriangle];
    return w.x * at(drape, v[0]) + w.y * at(drape, v[1]) + w.z * at(drape, v[2]);
  }

  bool empty() const { return triangles_.empty(); }

 private:
  glm::vec2 corner(size_t t, int k) const { return uvOf(mesh_, triangles_[3 * t + k]); }
  glm::ivec2 cellOf(glm::vec2 p) const {
    const glm::vec2 f = (p - bounds_.min) / bounds_.extent() * float(cells_);
    return glm::clamp(glm::ivec2(glm::floor(f)), glm::ivec2(0), glm::ivec2(cells_ - 1));
  }

  const GarmentMesh& mesh_;
  std::vector<uint32_t> triangles_;
  PanelBounds bounds_;
  int cells_ = 1;
  std::vector<std::vector<uint32_t>> buckets_;
};

}  // namespace

std::vector<float> transferDrape(const GarmentMesh& before, const std::vector<float>& drape, const GarmentMesh& after) {
  if (drape.size() != 3 * before.vertexCount())
    throw Error("the drape does not fit the garment mesh it is carried from");
  std::vector<float> out(3 * after.vertexCount());
  if (before.vertexCount() == 0) return out;
  const bool patterns = hasPatterns(before) && hasPatterns(after);
  std::vector<PanelLocator> locators;
  std::vector<PanelBounds> boundsBefore, boundsAfter;
  if (patterns) {
    boundsBefore = panelBounds(before);
    boundsAfter = panelBounds(after);
    std::vector<std::vector<uint32_t>> panelTriangles(boundsBefore.size());
    for (size_t t = 0; t < before.triangleCount(); ++t) {
      const uint32_t* v = &before.triangles[3 * t];
      const uint16_t panel = before.panelIds[v[0]];
      if (before.panelIds[v[1]] == panel && before.panelIds[v[2]] == panel)
        panelTriangles[panel].insert(panelTriangles[panel].end(), v, v + 3);
    }
    for (size_t p = 0; p < boundsBefore.size(); ++p) locators.emplace_back(before, panelTriangles[p], boundsBefore[p]);
  }
  // Without pattern coordinates for it: the drape of the nearest old vertex
  // in the rest placement (searched for all vertices at once, when first needed).
  std::vector<uint32_t> nearest;
  const auto nearestOld = [&](size_t v) {
    if (nearest.empty()) nearest = nearestPoints(after.positions, before.positions, 1);
    return nearest[v];
  };
  for (size_t v = 0; v < after.vertexCount(); ++v) {
    const size_t panel = patterns ? after.panelIds[v] : 0;
    const glm::vec3 p =
        patterns && panel < locators.size() && !locators[panel].empty()
            ? locators[panel].drapeAt(samePlace(uvOf(after, v), boundsAfter[panel], boundsBefore[panel]), drape)
            : at(drape, nearestOld(v));
    out[3 * v] = p.x, out[3 * v + 1] = p.y, out[3 * v + 2] = p.z;
  }
  return out;
}

}  // namespace mq
