#pragma once
// The spring graph of Provot's model, derived from a triangle mesh:
//  - structural springs: the mesh edges;
//  - shear springs: the two vertices opposite an interior edge (the other
//    diagonal of the quad two triangles form);
//  - bend lines: vertex triples (i, k, j) where i-k and k-j are edges and the
//    path is nearly straight (angle at k >= 150 degrees), i.e. Provot's
//    "two-ring" bend springs i-j on a grid; the cantilever bending model uses
//    the same triples.
// Each spring carries an area (the triangles it represents) used to turn the
// fabric's moduli into spring constants independent of the resolution.

#include <cstdint>
#include <vector>

#include "sim/cloth/cloth_state.h"

namespace mq::cloth {

struct SpringTopology {
  uint32_t a, b;
  float restLength;
  float area;  // m^2 of cloth the spring stands for
};

struct BendLine {
  uint32_t i, k, j;  // k is the middle vertex
  float length0;     // |x_k - x_i| at rest
  float length1;     // |x_j - x_k| at rest
  float width;       // m of cloth across the line
};

struct ClothTopology {
  std::vector<SpringTopology> structural, shear, bend;
  std::vector<BendLine> bendLines;
  std::vector<float> vertexArea;  // a third of the adjacent triangle areas
  float totalArea = 0.0f;
};

// Throws mq::Error for an empty mesh, indices out of range or degenerate data.
ClothTopology buildClothTopology(const ClothMesh& mesh);

}  // namespace mq::cloth
