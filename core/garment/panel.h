#pragma once
// A 2D sewing-pattern panel: a closed outline in metres, counter-clockwise in
// pattern space (u to the right, v up, the outside of the garment facing the
// viewer). Each edge is a straight line or a quadratic/cubic Bezier curve
// from its corner to the next corner.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/garment/panel_placement.h"

namespace mq {

enum class EdgeShape { Line, Quadratic, Cubic };

struct PanelEdge {
  std::string name;  // seams refer to edges by name
  EdgeShape shape = EdgeShape::Line;
  glm::vec2 control[2]{};  // Bezier control points (Quadratic uses control[0])
};

struct Panel {
  std::string name;
  std::vector<glm::vec2> corners;  // counter-clockwise
  std::vector<PanelEdge> edges;    // edges[i] runs from corners[i] to corners[i + 1 mod n]
  PanelPlacement placement;        // where the panel sits around the body

  int edgeCount() const { return static_cast<int>(edges.size()); }
  glm::vec2 edgeStart(int edge) const { return corners[edge]; }
  glm::vec2 edgeEnd(int edge) const { return corners[(edge + 1) % corners.size()]; }
  // The point at curve parameter t in [0, 1] (not arc length).
  glm::vec2 edgePoint(int edge, float t) const;
  float edgeLength(int edge) const;
  // `segments` + 1 points at equal arc length along the edge, both corners included.
  std::vector<glm::vec2> sampleEdge(int edge, int segments) const;
  // The closed outline as a polygon with pieces no longer than `maxSegment`
  // (each corner once, no repeated first point).
  std::vector<glm::vec2> outline(float maxSegment) const;
  // Signed area of outline(maxSegment): positive when counter-clockwise.
  float area(float maxSegment = 0.005f) const;
  int findEdge(const std::string& edgeName) const;  // -1 if absent

  // Adds a corner and the edge that leaves it; returns the edge index.
  int addLine(const std::string& edgeName, glm::vec2 corner);
  int addQuadratic(const std::string& edgeName, glm::vec2 corner, glm::vec2 control);
  int addCubic(const std::string& edgeName, glm::vec2 corner, glm::vec2 control0, glm::vec2 control1);

  // Throws mq::Error naming the panel when it has fewer than 3 corners,
  // mismatched edges, non-finite points, duplicate edge names or is clockwise.
  void validate() const;
};

float polygonSignedArea(const std::vector<glm::vec2>& polygon);

}  // namespace mq
