// PanelMesh measurements and edits (no CGAL here: see panel_mesher_cgal.cpp).
#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/garment/panel_mesher.h"

namespace mq {

float PanelMesh::area() const {
  double total = 0.0;
  for (size_t t = 0; t < triangles.size(); t += 3) {
    glm::vec2 a = vertices[triangles[t]], b = vertices[triangles[t + 1]], c = vertices[triangles[t + 2]];
    glm::vec2 ab = b - a, ac = c - a;
    total += 0.5 * (double(ab.x) * ac.y - double(ab.y) * ac.x);
  }
  return float(total);
}

float PanelMesh::maxEdgeLength() const {
  float longest = 0.0f;
  for (size_t t = 0; t < triangles.size(); t += 3)
    for (int i = 0; i < 3; ++i)
      longest = std::max(longest, glm::length(vertices[triangles[t + i]] - vertices[triangles[t + (i + 1) % 3]]));
  return longest;
}

float PanelMesh::meanEdgeLength() const {
  double sum = 0.0;
  for (size_t t = 0; t < triangles.size(); t += 3)
    for (int i = 0; i < 3; ++i) sum += glm::length(vertices[triangles[t + i]] - vertices[triangles[t + (i + 1) % 3]]);
  return triangles.empty() ? 0.0f : float(sum / double(triangles.size()));
}

uint32_t PanelMesh::splitBoundary(int edge, size_t k, float s) {
  std::vector<uint32_t>& along = edgeVertices[edge];
  std::vector<float>& arcs = edgeArcLengths[edge];
  assert(k + 1 < along.size());
  uint32_t a = along[k], b = along[k + 1];
  // Clamped inside the segment: a seam's partner may sit a little outside it.
  float t = std::clamp((s - arcs[k]) / std::max(arcs[k + 1] - arcs[k], 1e-12f), 0.1f, 0.9f);
  s = glm::mix(arcs[k], arcs[k + 1], t);
  uint32_t m = uint32_t(vertices.size());
  vertices.push_back(glm::mix(vertices[a], vertices[b], t));
  // The boundary segment a->b belongs to exactly one triangle (a, b, c) in
  // counter-clockwise order; it becomes (a, m, c) and (m, b, c).
  for (size_t tri = 0; tri < triangles.size(); tri += 3) {
    for (int i = 0; i < 3; ++i) {
      if (triangles[tri + i] != a || triangles[tri + (i + 1) % 3] != b) continue;
      uint32_t c = triangles[tri + (i + 2) % 3];
      triangles[tri + (i + 1) % 3] = m;
      triangles.insert(triangles.end(), {m, b, c});
      along.insert(along.begin() + long(k) + 1, m);
      arcs.insert(arcs.begin() + long(k) + 1, s);
      return m;
    }
  }
  assert(false && "boundary segment without a triangle");
  return m;
}

}  // namespace mq
