#pragma once
// Per-vertex mean curvature of a triangle mesh, for the pre-integrated skin
// shader's curvature axis (Penner 2011; research brief §5.1: precomputed
// per vertex as NVIDIA FaceWorks does, not per pixel).
//
// Discrete Laplace-Beltrami with cotangent weights over mixed Voronoi areas
// (Meyer, Desbrun, Schröder and Barr, "Discrete differential-geometry
// operators for triangulated 2-manifolds", 2003):
//   Delta x_i = 1/(2 A_i) sum_j (cot a_ij + cot b_ij) (x_j - x_i) = -2 H n_i
// so H = -(Delta x_i . n_i) / 2: positive where the surface bulges along its
// normal (a sphere with outward normals has H = 1/R everywhere).
//
// Vertices at equal positions are welded first (exporters split them at uv
// seams), so a seam does not read as an open boundary. Boundary vertices
// get 0 (the Laplacian there measures the boundary, not the surface).

#include <cstdint>
#include <vector>

namespace mq {

// positions: 3 floats per vertex; triangles: 3 indices per triangle; normals:
// 3 floats per vertex (orientation of the sign). Returns H per vertex, in
// 1 / (position units).
// smoothingPasses > 0: the median over each vertex's ring, then that many
// ring averages. Marching-cubes and scanned meshes have slivers whose
// cotangents spike; a shader reading H would show them as specks.
std::vector<float> vertexMeanCurvature(const std::vector<float>& positions, const std::vector<float>& normals,
                                       const std::vector<uint32_t>& triangles, int smoothingPasses = 0);

}  // namespace mq
