#pragma once
// Small cloth scenes shared by the cloth tests.

#include <random>
#include <vector>

#include "core/garment/fabric.h"
#include "core/garment/sheet.h"
#include "sim/cloth/cloth_simulator.h"
#include "sim/cloth/forces/spring_force.h"

namespace mq::cloth::test {

// A horizontal n x n sheet of `size` metres centred at `centre`.
inline ClothMesh horizontalSheetMesh(int n, float size, glm::vec3 centre) {
  const Sheet s = makeSheet(horizontalSheet(n, size, centre));
  ClothMesh m;
  m.positions = s.positions;
  m.triangles = s.triangles;
  return m;
}

// A vertical sheet hanging from its top row (row 0) at height `top`.
inline ClothMesh hangingSheetMesh(int columns, int rows, float width, float height, float top) {
  SheetSpec spec;
  spec.columns = columns;
  spec.rows = rows;
  spec.width = width;
  spec.height = height;
  spec.origin = {-0.5f * width, top, 0.0f};
  spec.widthAxis = {1, 0, 0};
  spec.heightAxis = {0, -0.995f, -0.0998f};  // tilted ~6 degrees so it swings
  const Sheet s = makeSheet(spec);
  ClothMesh m;
  m.positions = s.positions;
  m.triangles = s.triangles;
  return m;
}

inline void pinTopRow(ClothSimulator& sim, int columns) {
  for (int c = 0; c < columns; ++c) sim.pinVertex(uint32_t(c));
}

inline bool allFinite(const ClothSimulator& sim) {
  for (const glm::vec3& x : sim.positions())
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z)) return false;
  return true;
}

// Springs over a columns x columns grid of positions x (row-major): edges
// (k 80), diagonals (40) and skip-one (10), each rest length the current one
// scaled by a draw from rng in [0.8, 1.2] (stretched and compressed).
inline std::vector<Spring> gridSprings(const std::vector<glm::vec3>& x, int columns, std::mt19937& rng) {
  std::vector<Spring> springs;
  std::uniform_real_distribution<float> scale(0.8f, 1.2f);
  auto at = [columns](int r, int c) { return uint32_t(r * columns + c); };
  auto add = [&](uint32_t a, uint32_t b, float k) {
    springs.push_back({a, b, scale(rng) * glm::length(x[a] - x[b]), k, 0.02f * k});
  };
  for (int r = 0; r < columns; ++r)
    for (int c = 0; c < columns; ++c) {
      if (c + 1 < columns) add(at(r, c), at(r, c + 1), 80.0f);
      if (r + 1 < columns) add(at(r, c), at(r + 1, c), 80.0f);
      if (r + 1 < columns && c + 1 < columns) add(at(r, c), at(r + 1, c + 1), 40.0f);
      if (c + 2 < columns) add(at(r, c), at(r, c + 2), 10.0f);
    }
  return springs;
}

}  // namespace mq::cloth::test
