#include "core/garment/pattern_svg.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace mq {
namespace {

constexpr float kMillimetres = 1000.0f;     // pattern metres to SVG user units
constexpr float kMargin = 20.0f;            // mm around the sheet and between panels
constexpr float kLabelHeight = 12.0f;       // mm, panel names
constexpr float kNotchDepth = 6.0f;         // mm into the panel
constexpr float kOutlineSegment = 0.002f;   // m, the polygon the cutting line is offset from
constexpr float kMaxSeamAllowance = 0.10f;  // m

const std::array<const char*, 8> kSeamColours = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd",
                                                 "#ff7f0e", "#17becf", "#e377c2", "#8c564b"};

std::string number(float millimetres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", double(millimetres));
  return text;
}

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Pattern space (metres, v up) to the sheet (mm, y down) for one panel.
struct SheetFrame {
  glm::vec2 patternMin{0.0f}, patternMax{0.0f};  // the panel's bounds with its allowance
  float left = 0.0f, top = 0.0f;                 // where patternMin.x, patternMax.y land
  glm::vec2 operator()(glm::vec2 p) const {
    return {left + (p.x - patternMin.x) * kMillimetres, top + (patternMax.y - p.y) * kMillimetres};
  }
  float width() const { return (patternMax.x - patternMin.x) * kMillimetres; }
  float height() const { return (patternMax.y - patternMin.y) * kMillimetres; }
};

std::string point(const SheetFrame& frame, glm::vec2 p) {
  const glm::vec2 q = frame(p);
  return number(q.x) + " " + number(q.y);
}

// The edge as path commands after a move to its start.
std::string edgeCommands(const SheetFrame& frame, const Panel& panel, int edge) {
  const PanelEdge& e = panel.edges[edge];
  const std::string end = point(frame, panel.edgeEnd(edge));
  switch (e.shape) {
    case EdgeShape::Quadratic:
      return "Q " + point(frame, e.control[0]) + " " + end;
    case EdgeShape::Cubic:
      return "C " + point(frame, e.control[0]) + " " + point(frame, e.control[1]) + " " + end;
    case EdgeShape::Line:
      break;
  }
  return "L " + end;
}

std::string sewingLine(const SheetFrame& frame, const Panel& panel) {
  std::string d = "M " + point(frame, panel.corners[0]);
  for (int e = 0; e < panel.edgeCount(); ++e) d += " " + edgeCommands(frame, panel, e);
  return d + " Z";
}

// The outline moved `distance` outwards, with mitred corners (a mitre is
// cut at twice the distance, as a pattern maker would square a sharp point).
std::vector<glm::vec2> offsetOutline(const std::vector<glm::vec2>& outline, float distance) {
  const size_t n = outline.size();
  std::vector<glm::vec2> out(n);
  for (size_t i = 0; i < n; ++i) {
    const glm::vec2 prev = outline[(i + n - 1) % n], here = outline[i], next = outline[(i + 1) % n];
    auto outward = [](glm::vec2 a, glm::vec2 b) {
      const glm::vec2 d = glm::normalize(b - a);
      return glm::vec2(d.y, -d.x);  // right of the direction: outside a counter-clockwise outline
    };
    const glm::vec2 n0 = outward(prev, here), n1 = outward(here, next);
    glm::vec2 bisector = n0 + n1;
    const float len = glm::length(bisector);
    bisector = len > 1e-6f ? bisector / len : n0;
    const float cosHalf = std::max(glm::dot(bisector, n0), 0.5f);
    out[i] = here + bisector * (distance / cosHalf);
  }
  return out;
}

// Without repeated points, and without points on the line through their
// neighbours (a straight edge's samples): a cutter gets one segment per side.
std::vector<glm::vec2> simplified(const std::vector<glm::vec2>& outline) {
  constexpr float kTolerance = 1e-6f;                          // metres
  auto onTheWay = [](glm::vec2 a, glm::vec2 b, glm::vec2 c) {  // b on the segment from a to c
    const glm::vec2 along = glm::normalize(c - a);
    const glm::vec2 off = b - a - along * glm::dot(b - a, along);
    return glm::length(off) <= kTolerance && glm::dot(b - a, c - b) > 0.0f;
  };
  std::vector<glm::vec2> out;
  for (glm::vec2 p : outline) {
    if (!out.empty() && glm::length(p - out.back()) <= kTolerance) continue;
    if (out.size() >= 2 && onTheWay(out[out.size() - 2], out.back(), p)) out.pop_back();
    out.push_back(p);
  }
  while (out.size() > 1 && glm::length(out.front() - out.back()) <= kTolerance) out.pop_back();
  while (out.size() > 3 && onTheWay(out[out.size() - 2], out.back(), out.front())) out.pop_back();
  return out;
}

std::string polygonPath(const SheetFrame& frame, const std::vector<glm::vec2>& polygon) {
  std::string d;
  for (size_t i = 0; i < polygon.size(); ++i) d += (i == 0 ? "M " : " L ") + point(frame, polygon[i]);
  return d + " Z";
}

glm::vec2 outlineCentroid(const std::vector<glm::vec2>& polygon) {
  glm::vec2 sum(0.0f);
  float twiceArea = 0.0f;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const glm::vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    const float cross = a.x * b.y - b.x * a.y;
    twiceArea += cross;
    sum += (a + b) * cross;
  }
  return std::abs(twiceArea) > 1e-12f ? sum / (3.0f * twiceArea) : polygon[0];
}

struct SeamMark {
  int seam;
  int edge;
};

// Per panel, the seams that sew its edges.
std::vector<std::vector<SeamMark>> seamMarks(const Garment& garment) {
  std::vector<std::vector<SeamMark>> marks(garment.panels.size());
  for (size_t s = 0; s < garment.seams.size(); ++s) {
    const Seam& seam = garment.seams[s];
    const int a = garment.findPanel(seam.panelA), b = garment.findPanel(seam.panelB);
    marks[a].push_back({int(s), garment.panels[a].findEdge(seam.edgeA)});
    marks[b].push_back({int(s), garment.panels[b].findEdge(seam.edgeB)});
  }
  return marks;
}

void writePanel(std::ostream& out, const Garment& garment, size_t index, const SheetFrame& frame,
                const std::vector<SeamMark>& marks, const std::vector<glm::vec2>& cutting) {
  const Panel& panel = garment.panels[index];
  out << "  <g id=\"panel-" << index << "\" data-name=\"" << escaped(panel.name) << "\">\n";
  if (!cutting.empty()) out << "    <path class=\"cut\" d=\"" << polygonPath(frame, cutting) << "\"/>\n";
  out << "    <path class=\"sew\" d=\"" << sewingLine(frame, panel) << "\"/>\n";
  for (const SeamMark& mark : marks) {
    const char* colour = kSeamColours[size_t(mark.seam) % kSeamColours.size()];
    out << "    <path class=\"seam\" stroke=\"" << colour << "\" d=\"M " << point(frame, panel.edgeStart(mark.edge))
        << " " << edgeCommands(frame, panel, mark.edge) << "\"/>\n";
    // A notch at the edge's middle, square to it, into the panel; the seam's number beside it.
    const glm::vec2 middle = panel.sampleEdge(mark.edge, 2)[1];
    const glm::vec2 tangent = panel.edgePoint(mark.edge, 0.51f) - panel.edgePoint(mark.edge, 0.49f);
    const glm::vec2 inward =
        glm::length(tangent) > 0.0f ? glm::normalize(glm::vec2(-tangent.y, tangent.x)) : glm::vec2(0.0f);
    const glm::vec2 tip = middle + inward * (kNotchDepth / kMillimetres);
    const glm::vec2 label = middle + inward * (2.5f * kNotchDepth / kMillimetres);
    out << "    <path class=\"notch\" d=\"M " << point(frame, middle) << " L " << point(frame, tip) << "\"/>\n";
    out << "    <text class=\"seam-label\" fill=\"" << colour << "\" x=\"" << number(frame(label).x) << "\" y=\""
        << number(frame(label).y) << "\">" << mark.seam + 1 << "</text>\n";
  }
  // The grain line: pattern v, across the middle two thirds of the panel's height.
  const std::vector<glm::vec2> polygon = panel.outline(kOutlineSegment);
  const glm::vec2 centre = outlineCentroid(polygon);
  float low = centre.y, high = centre.y;
  for (glm::vec2 p : polygon) low = std::min(low, p.y), high = std::max(high, p.y);
  const float reach = (high - low) / 3.0f;
  out << "    <path class=\"grain\" d=\"M " << point(frame, {centre.x, centre.y - reach}) << " L "
      << point(frame, {centre.x, centre.y + reach}) << "\" marker-start=\"url(#arrow)\" marker-end=\"url(#arrow)\"/>\n";
  const glm::vec2 name = frame(centre) + glm::vec2(0.4f * kLabelHeight, 0.0f);
  out << "    <text class=\"name\" x=\"" << number(name.x) << "\" y=\"" << number(name.y) << "\">"
      << escaped(panel.name) << "</text>\n";
  out << "  </g>\n";
}

}  // namespace

std::string patternSvg(const Garment& garment, const PatternSvgOptions& options) {
  garment.validate();
  const float allowance = options.seamAllowance;
  if (!(allowance >= 0.0f && allowance <= kMaxSeamAllowance))
    throw Error("the seam allowance must be between 0 and " + number(kMaxSeamAllowance * kMillimetres) + " mm");

  // Lay the panels out left to right, tops level, below the title.
  const float titleHeight = 2.0f * kLabelHeight;
  std::vector<SheetFrame> frames(garment.panels.size());
  std::vector<std::vector<glm::vec2>> cutting(garment.panels.size());
  float left = kMargin, tallest = 0.0f;
  for (size_t i = 0; i < garment.panels.size(); ++i) {
    const Panel& panel = garment.panels[i];
    std::vector<glm::vec2> bounds = panel.outline(kOutlineSegment);
    if (allowance > 0.0f) bounds = cutting[i] = simplified(offsetOutline(bounds, allowance));
    for (int e = 0; e < panel.edgeCount(); ++e)  // Bezier handles, so the arrows and labels fit as well
      for (glm::vec2 p : panel.sampleEdge(e, 8)) bounds.push_back(p);
    SheetFrame& frame = frames[i];
    frame.patternMin = frame.patternMax = bounds[0];
    for (glm::vec2 p : bounds)
      frame.patternMin = glm::min(frame.patternMin, p), frame.patternMax = glm::max(frame.patternMax, p);
    frame.left = left;
    frame.top = kMargin + titleHeight;
    left += frame.width() + kMargin;
    tallest = std::max(tallest, frame.height());
  }
  const float width = std::max(left, 100.0f), height = kMargin + titleHeight + tallest + kMargin;
  const std::vector<std::vector<SeamMark>> marks = seamMarks(garment);

  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(width) << "mm\" height=\"" << number(height)
      << "mm\" viewBox=\"0 0 " << number(width) << " " << number(height) << "\">\n"
      << "  <title>" << escaped(garment.name) << ": sewing pattern, 1:1, millimetres</title>\n"
      << "  <defs>\n"
      << "    <marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"5\" refY=\"5\" markerWidth=\"6\" markerHeight=\"6\" "
         "orient=\"auto-start-reverse\"><path d=\"M 0 0 L 10 5 L 0 10 z\"/></marker>\n"
      << "    <style>\n"
      << "      .sew { fill: #f4efe6; stroke: #000; stroke-width: 0.5; }\n"
      << "      .cut { fill: none; stroke: #000; stroke-width: 0.3; stroke-dasharray: 4 2; }\n"
      << "      .seam { fill: none; stroke-width: 1.2; }\n"
      << "      .notch { stroke: #000; stroke-width: 0.5; }\n"
      << "      .grain { stroke: #555; stroke-width: 0.5; }\n"
      << "      text { font-family: sans-serif; }\n"
      << "      .name { font-size: " << number(kLabelHeight) << "px; }\n"
      << "      .seam-label { font-size: " << number(0.6f * kLabelHeight)
      << "px; text-anchor: middle; dominant-baseline: middle; }\n"
      << "    </style>\n"
      << "  </defs>\n"
      << "  <text class=\"name\" x=\"" << number(kMargin) << "\" y=\"" << number(kMargin + kLabelHeight) << "\">"
      << escaped(garment.name) << " (" << garment.panels.size() << " panels, " << garment.seams.size()
      << " seams; 1:1, mm)</text>\n";
  for (size_t i = 0; i < garment.panels.size(); ++i) writePanel(out, garment, i, frames[i], marks[i], cutting[i]);
  out << "</svg>\n";
  return out.str();
}

void writePatternSvg(const std::string& path, const Garment& garment, const PatternSvgOptions& options) {
  const std::string svg = patternSvg(garment, options);
  writeFileAtomically(path, [&](std::ostream& out) { out << svg; });
}

}  // namespace mq
