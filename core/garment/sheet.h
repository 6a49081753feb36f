#pragma once
// The simplest garment: a rectangular sheet of N x M vertices, triangulated
// as a grid (two triangles per quad, alternating diagonals so the sheet has
// no preferred shear direction).

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace mq {

struct SheetSpec {
  int columns = 32;        // vertices along the width (N)
  int rows = 32;           // vertices along the height (M)
  float width = 1.0f;      // m, along `widthAxis`
  float height = 1.0f;     // m, along `heightAxis`
  glm::vec3 origin{0.0f};  // position of vertex (row 0, column 0)
  glm::vec3 widthAxis{1.0f, 0.0f, 0.0f};
  glm::vec3 heightAxis{0.0f, 0.0f, 1.0f};
};

struct Sheet {
  int columns = 0, rows = 0;
  std::vector<float> positions;     // 3 per vertex, row-major: index = row * columns + column
  std::vector<uint32_t> triangles;  // 3 per triangle
  std::vector<float> uvs;           // 2 per vertex, in [0,1]

  uint32_t index(int row, int column) const { return static_cast<uint32_t>(row * columns + column); }
  size_t vertexCount() const { return positions.size() / 3; }
};

// Throws mq::Error for fewer than 2 x 2 vertices or a non-positive size.
Sheet makeSheet(const SheetSpec& spec);

// A sheet centred at `centre`, horizontal (in the XZ plane, Y up).
SheetSpec horizontalSheet(int n, float size, const glm::vec3& centre);

}  // namespace mq
