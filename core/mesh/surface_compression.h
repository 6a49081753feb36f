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
// Then, for the shader, the directions are smoothed over each vertex's ring
// (weighted by how compressed the neighbours are) and a phase is integrated
// along them: s grows by (r_u - r_v) . (a_u + a_v) / 2 from vertex to
// vertex, breadth first from one vertex of each compressed patch, then is
// evened out by a few Jacobi sweeps, so that sin(k s) draws straight
// parallel folds across the compression (s = r . a would bend them into
// rings wherever a turns).
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
  // the rest frame (xyz; zero where the surface is compressed by less than
  // kMinCompression, or too few edges meet to tell) and l/L along it (w; 1
  // where undetermined). phase (optional): 1 float per vertex, the rest-frame
  // distance along the directions (0 where there is no direction).
  void evaluate(const std::vector<float>& posedPositions, std::vector<float>& out,
                std::vector<float>* phase = nullptr) const;

  static constexpr float kMinCompression = 0.05f;  // 1 - l/L below which skinning noise is ignored

 private:
  void fitStretch(const std::vector<float>& posedPositions, std::vector<float>& out) const;
  void smoothDirections(const std::vector<float>& raw, std::vector<float>& out) const;
  void integratePhase(std::vector<float>& out, std::vector<float>& phase) const;

  std::vector<uint32_t> firstEdge_;              // CSR: vertex v's edges are [firstEdge_[v], firstEdge_[v + 1])
  std::vector<uint32_t> neighbour_;              // the edge's other vertex
  std::vector<float> inverseRestLengthSquared_;  // 1 / L_e^2
  std::vector<float> rows_;           // 3 floats per edge: (x^2, 2xy, y^2) of u_e in the vertex's tangent frame
  std::vector<float> tangentFrame_;   // 6 floats per vertex: t1, t2 (rest frame)
  std::vector<float> inverseNormal_;  // 6 floats per vertex: symmetric 3x3 inverse; zeros when singular
  std::vector<float> restPositions_;
};

}  // namespace mq
