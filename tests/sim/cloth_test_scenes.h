#pragma once
// Small cloth scenes shared by the cloth tests.

#include "core/garment/fabric.h"
#include "core/garment/sheet.h"
#include "sim/cloth/cloth_simulator.h"

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

}  // namespace mq::cloth::test
