#include "core/garment/panel.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/util/error.h"

namespace mq {
namespace {

// Dense samples of a curve, used to measure and invert arc length.
constexpr int kArcSamples = 256;

struct ArcTable {
  std::vector<glm::vec2> points;
  std::vector<float> lengths;  // cumulative, lengths[0] = 0
};

ArcTable arcTable(const Panel& panel, int edge) {
  ArcTable table;
  int samples = panel.edges[edge].shape == EdgeShape::Line ? 1 : kArcSamples;
  table.points.reserve(samples + 1);
  table.lengths.reserve(samples + 1);
  for (int i = 0; i <= samples; ++i) {
    glm::vec2 p = panel.edgePoint(edge, float(i) / float(samples));
    table.lengths.push_back(i == 0 ? 0.0f : table.lengths.back() + glm::length(p - table.points.back()));
    table.points.push_back(p);
  }
  return table;
}

glm::vec2 pointAtLength(const ArcTable& table, float s) {
  auto it = std::lower_bound(table.lengths.begin(), table.lengths.end(), s);
  if (it == table.lengths.begin()) return table.points.front();
  if (it == table.lengths.end()) return table.points.back();
  size_t i = size_t(it - table.lengths.begin());
  float span = table.lengths[i] - table.lengths[i - 1];
  float t = span > 0.0f ? (s - table.lengths[i - 1]) / span : 0.0f;
  return glm::mix(table.points[i - 1], table.points[i], t);
}

bool finite(glm::vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

glm::vec2 Panel::edgePoint(int edge, float t) const {
  const PanelEdge& e = edges[edge];
  glm::vec2 a = edgeStart(edge), b = edgeEnd(edge);
  float s = 1.0f - t;
  switch (e.shape) {
    case EdgeShape::Line:
      return glm::mix(a, b, t);
    case EdgeShape::Quadratic:
      return s * s * a + 2.0f * s * t * e.control[0] + t * t * b;
    case EdgeShape::Cubic:
      return s * s * s * a + 3.0f * s * s * t * e.control[0] + 3.0f * s * t * t * e.control[1] + t * t * t * b;
  }
  return a;
}

float Panel::edgeLength(int edge) const { return arcTable(*this, edge).lengths.back(); }

std::vector<glm::vec2> Panel::sampleEdge(int edge, int segments) const {
  segments = std::max(segments, 1);
  ArcTable table = arcTable(*this, edge);
  float total = table.lengths.back();
  std::vector<glm::vec2> points;
  points.reserve(segments + 1);
  for (int i = 0; i <= segments; ++i) points.push_back(pointAtLength(table, total * float(i) / float(segments)));
  points.front() = edgeStart(edge);  // exact corners, so neighbouring edges share them
  points.back() = edgeEnd(edge);
  return points;
}

std::vector<glm::vec2> Panel::outline(float maxSegment) const {
  std::vector<glm::vec2> polygon;
  for (int e = 0; e < edgeCount(); ++e) {
    int segments = std::max(1, int(std::ceil(edgeLength(e) / maxSegment)));
    std::vector<glm::vec2> points = sampleEdge(e, segments);
    polygon.insert(polygon.end(), points.begin(), points.end() - 1);
  }
  return polygon;
}

float polygonSignedArea(const std::vector<glm::vec2>& polygon) {
  double twiceArea = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    glm::vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    twiceArea += double(a.x) * b.y - double(b.x) * a.y;
  }
  return float(0.5 * twiceArea);
}

float Panel::area(float maxSegment) const { return polygonSignedArea(outline(maxSegment)); }

int Panel::findEdge(const std::string& edgeName) const {
  for (int e = 0; e < edgeCount(); ++e)
    if (edges[e].name == edgeName) return e;
  return -1;
}

int Panel::addLine(const std::string& edgeName, glm::vec2 corner) {
  corners.push_back(corner);
  edges.push_back({edgeName, EdgeShape::Line, {}});
  return edgeCount() - 1;
}

int Panel::addQuadratic(const std::string& edgeName, glm::vec2 corner, glm::vec2 control) {
  corners.push_back(corner);
  edges.push_back({edgeName, EdgeShape::Quadratic, {control, control}});
  return edgeCount() - 1;
}

int Panel::addCubic(const std::string& edgeName, glm::vec2 corner, glm::vec2 control0, glm::vec2 control1) {
  corners.push_back(corner);
  edges.push_back({edgeName, EdgeShape::Cubic, {control0, control1}});
  return edgeCount() - 1;
}

namespace {

// A panel larger than this is a typing mistake, not a garment (metres).
constexpr float kMaxPanelExtent = 10.0f;
constexpr int kMaxPanelEdges = 256;
constexpr int kSegmentsPerCurve = 16;

bool within(glm::vec2 p, float extent) { return std::abs(p.x) <= extent && std::abs(p.y) <= extent; }

float cross(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

bool segmentsCross(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d) {
  const float d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const float d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0.0f) != (d2 > 0.0f)) && ((d3 > 0.0f) != (d4 > 0.0f)) && d1 != 0.0f && d2 != 0.0f && d3 != 0.0f &&
         d4 != 0.0f;
}

// Whether two non-adjacent segments of the closed polyline cross.
bool crossesItself(const std::vector<glm::vec2>& ring) {
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const glm::vec2 a = ring[i], b = ring[(i + 1) % n];
    const glm::vec2 lo = glm::min(a, b), hi = glm::max(a, b);
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through the closing corner
      const glm::vec2 c = ring[j], d = ring[(j + 1) % n];
      if (std::max(c.x, d.x) < lo.x || std::min(c.x, d.x) > hi.x || std::max(c.y, d.y) < lo.y ||
          std::min(c.y, d.y) > hi.y)
        continue;
      if (segmentsCross(a, b, c, d)) return true;
    }
  }
  return false;
}

}  // namespace

void Panel::validate() const {
  auto fail = [&](const std::string& problem) { throw Error("panel '" + name + "': " + problem); };
  if (corners.size() < 3) fail("needs at least 3 corners, has " + std::to_string(corners.size()));
  if (edges.size() != corners.size())
    fail(std::to_string(corners.size()) + " corners but " + std::to_string(edges.size()) + " edges");
  if (edgeCount() > kMaxPanelEdges) fail("has more than " + std::to_string(kMaxPanelEdges) + " edges");
  std::set<std::string> names;
  for (int e = 0; e < edgeCount(); ++e) {
    if (!finite(corners[e]) || !finite(edges[e].control[0]) || !finite(edges[e].control[1]))
      fail("edge " + std::to_string(e) + " has a non-finite point");
    if (!within(corners[e], kMaxPanelExtent) || !within(edges[e].control[0], kMaxPanelExtent) ||
        !within(edges[e].control[1], kMaxPanelExtent))
      fail("edge " + std::to_string(e) + " has a point more than 10 m from the pattern's origin");
    if (!edges[e].name.empty() && !names.insert(edges[e].name).second)
      fail("two edges are named '" + edges[e].name + "'");
    if (edgeLength(e) <= 1e-6f) fail("edge " + std::to_string(e) + " has zero length");
  }
  std::vector<glm::vec2> ring;
  for (int e = 0; e < edgeCount(); ++e) {
    const std::vector<glm::vec2> points = sampleEdge(e, edges[e].shape == EdgeShape::Line ? 1 : kSegmentsPerCurve);
    ring.insert(ring.end(), points.begin(), points.end() - 1);
  }
  if (crossesItself(ring)) fail("outline crosses itself");
  if (area() <= 0.0f) fail("outline must be counter-clockwise with a positive area");
}

}  // namespace mq
