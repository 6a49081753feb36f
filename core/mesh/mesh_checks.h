#pragma once
// Checks of a triangle mesh's validity as the boundary of a solid: closed,
// 2-manifold, consistently oriented, one piece, outward facing, and free of
// self-intersections. Used by tests and by mesh generators' sanity checks.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace mq {

struct MeshTopologyReport {
  size_t edges = 0;
  size_t boundaryEdges = 0;        // used by one triangle
  size_t overSharedEdges = 0;      // used by more than two triangles
  size_t misorientedEdges = 0;     // two triangles run the edge the same way
  size_t nonManifoldVertices = 0;  // the triangles around it are not one closed fan
  size_t isolatedVertices = 0;     // in no triangle
  size_t degenerateTriangles = 0;  // a repeated vertex index
  size_t components = 0;           // connected pieces (through shared vertices)

  // Every edge shared by exactly two oppositely oriented triangles, every
  // vertex a single fan, nothing degenerate or unused.
  bool closedManifold() const {
    return boundaryEdges == 0 && overSharedEdges == 0 && misorientedEdges == 0 && nonManifoldVertices == 0 &&
           isolatedVertices == 0 && degenerateTriangles == 0;
  }
};

MeshTopologyReport checkTopology(size_t vertexCount, const std::vector<uint32_t>& triangles);

// Volume enclosed by a closed mesh (divergence theorem); positive when the
// triangles wind counter-clockwise seen from outside.
double signedVolume(const std::vector<float>& positions, const std::vector<uint32_t>& triangles);

// Pairs of triangles (indices) that intersect anywhere other than in the
// vertices and edges they share; exact predicates (CGAL). The mesh must be a
// 2-manifold (see checkTopology).
std::vector<std::pair<size_t, size_t>> selfIntersections(const std::vector<float>& positions,
                                                         const std::vector<uint32_t>& triangles);

}  // namespace mq
