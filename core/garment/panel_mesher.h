#pragma once
// Meshes a panel into triangles with a target edge length (CGAL's 2D
// constrained Delaunay mesher, in panel_mesher_cgal.cpp; no CGAL type here).

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/garment/panel.h"

namespace mq {

struct PanelMeshOptions {
  float targetEdgeLength = 0.02f;  // upper bound on triangle edge length (metres)
  // Optional segment count per panel edge for the boundary sampling (0 or
  // missing: from the target length). Seams give both sides the same count.
  std::vector<int> edgeSegments;
};

// A meshed panel in pattern space. Triangles are counter-clockwise.
struct PanelMesh {
  std::vector<glm::vec2> vertices;
  std::vector<uint32_t> triangles;  // 3 per triangle
  // Per panel edge: the boundary vertices along it from its start corner to
  // its end corner (both included), and their arc length from the start.
  std::vector<std::vector<uint32_t>> edgeVertices;
  std::vector<std::vector<float>> edgeArcLengths;

  size_t vertexCount() const { return vertices.size(); }
  size_t triangleCount() const { return triangles.size() / 3; }
  float area() const;
  float maxEdgeLength() const;
  float meanEdgeLength() const;
  // Splits boundary segment (edgeVertices[edge][k], [k+1]) at arc length s,
  // and the triangle on it; returns the new vertex.
  uint32_t splitBoundary(int edge, size_t k, float s);
};

// Throws mq::Error when the panel is invalid or the target length is not positive.
PanelMesh meshPanel(const Panel& panel, const PanelMeshOptions& options = {});

// Segment count used for an edge of length `length` at `targetEdgeLength`.
int boundarySegments(float length, float targetEdgeLength);

}  // namespace mq
