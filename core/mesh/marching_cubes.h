#pragma once
// Iso-surface extraction from a regular grid of scalar samples (marching
// cubes). The surface is built face by face: on every cube face the sign
// pattern alone (plus the asymptotic decider on ambiguous faces) fixes the
// contour segments, so the two cubes that share a face always agree. Each
// cube's segments close into loops, triangulated without diagonals on cube
// faces (so no two cubes build the same triangle); vertices live on grid
// edges and are shared by all cubes around the edge. Result: a closed,
// 2-manifold, consistently oriented mesh whenever the iso-surface stays
// inside the grid (inside = value < iso, normals point to larger values).

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace mq {

// Samples at origin + cellSize * (i, j, k), stored with i fastest.
struct ScalarGrid {
  glm::vec3 origin{0.0f};
  float cellSize = 1.0f;
  glm::ivec3 dims{0};  // samples per axis
  std::vector<float> values;

  size_t index(int i, int j, int k) const { return (size_t(k) * dims.y + j) * dims.x + i; }
  float at(int i, int j, int k) const { return values[index(i, j, k)]; }
  glm::vec3 point(int i, int j, int k) const { return origin + cellSize * glm::vec3(i, j, k); }
};

struct IsoSurface {
  std::vector<float> positions;     // 3 per vertex
  std::vector<uint32_t> triangles;  // 3 per triangle, counter-clockwise seen from outside
};

// Extracts the surface value == iso. Grid values must be finite.
IsoSurface extractIsoSurface(const ScalarGrid& grid, float iso);

}  // namespace mq
