#pragma once
// How much, and along which direction, a skinned surface is compressed at
// each vertex: the input of Volino's wrinkle height t(l/L) (survey §1.3.2;
// core/optics/volino_wrinkle.h), with l and L the posed and rest lengths
// across the fold.
//
// At each vertex the squared stretch along a rest tangent direction u is
// u^T C u, C the 2x2 right Cauchy-Green tensor in the rest tangent plane.
// C is fitted by least squares to the vertex's edges,
//   (l_e / L_e)^2 = u_e^T C u_e,  u_e = the rest edge projected and normalised,
// (3 unknowns, one equation per edge; the normal equations depend only on
// the rest mesh and are inverted once). The smallest eigenvalue of C gives
// l/L = sqrt(lambda_min) and its eigenvector the compression direction; the
// wrinkles run across it. A rigid motion gives C = I exactly: no wrinkles.
//
// Built once from the rest mesh; evaluate() is per frame, over flat arrays,
// a few dozen flops per edge.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mq {

class SurfaceCompression {
 public:
  SurfaceCompression() = default;
  SurfaceCompression(const std::vector<float>& restPositions, const std::vector<uint32_t>& triangles);

  size_t vertexCount() const { return inverseNormal_.size() / 6; }

  // posedPositions: 3 floats per vertex, same order as the rest mesh.
  // out: 4 floats per vertex: the unit direction of strongest compression in
  // the rest frame (xyz; zero where the surface is not compressed, or too few
  // edges meet to tell) and l/L along it (w; 1 where undetermined).
  void evaluate(const std::vector<float>& posedPositions, std::vector<float>& out) const;

 private:
  std::vector<uint32_t> firstEdge_;      // CSR: vertex v's edges are [firstEdge_[v], firstEdge_[v + 1])
  std::vector<uint32_t> neighbour_;      // the edge's other vertex
  std::vector<float> restLength_;        // L_e
  std::vector<float> projected_;         // u_e: 2 floats per edge, in the vertex's tangent frame
  std::vector<float> tangentFrame_;      // 6 floats per vertex: t1, t2 (rest frame)
  std::vector<float> inverseNormal_;     // 6 floats per vertex: symmetric 3x3 inverse; zeros when singular
};

}  // namespace mq
