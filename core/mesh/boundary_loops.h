#pragma once
// The open rims of a triangle mesh: a sewn T-shirt has four (neck, hem, two
// cuffs), a skirt two, trousers three; a missed seam shows up as extra loops.
// Walked on OpenMesh's half-edge structure (boundary_loops_openmesh.cpp), so
// OpenMesh stays out of every header.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mq {

// Each loop lists its vertices in order, starting at its lowest index; for
// counter-clockwise triangles the walk runs clockwise seen from the front
// (the mesh on its right: OpenMesh's boundary half-edges face away from the
// triangles). Loops are ordered by their first vertex. Throws mq::Error naming the first triangle that makes the
// surface non-manifold (an edge in three triangles, a flipped neighbour, a repeated corner): boundaries are only
// defined on a manifold surface.
std::vector<std::vector<uint32_t>> boundaryLoops(size_t vertexCount, const std::vector<uint32_t>& triangles);

}  // namespace mq
