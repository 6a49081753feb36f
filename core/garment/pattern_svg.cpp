#include "core/garment/pattern_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/garment/pattern_outline.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace mq {
namespace {

constexpr float kMillimetres = 1000.0f;  // pattern metres to SVG user units
constexpr float kMargin = 20.0f;         // mm around the sheet and between panels
constexpr float kLabelHeight = 12.0f;    // mm, panel names
constexpr float kNotchDepth = 6.0f;      // mm into the panel

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

std::string polygonPath(const SheetFrame& frame, const std::vector<glm::vec2>& polygon) {
  std::string d;
  for (size_t i = 0; i < polygon.size(); ++i) d += (i == 0 ? "M " : " L ") + point(frame, polygon[i]);
  return d + " Z";
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
    const char* colour = seamColour(size_t(mark.seam));
    out << "    <path class=\"seam\" stroke=\"" << colour << "\" d=\"M " << point(frame, panel.edgeStart(mark.edge))
        << " " << edgeCommands(frame, panel, mark.edge) << "\"/>\n";
    // A notch at the edge's middle, square to it, into the panel; the seam's number beside it.
    const PatternSegment notch = edgeNotch(panel, mark.edge, kNotchDepth / kMillimetres);
    const glm::vec2 middle = notch.from, tip = notch.to;
    const glm::vec2 label = middle + (tip - middle) * 2.5f;
    out << "    <path class=\"notch\" d=\"M " << point(frame, middle) << " L " << point(frame, tip) << "\"/>\n";
    out << "    <text class=\"seam-label\" fill=\"" << colour << "\" x=\"" << number(frame(label).x) << "\" y=\""
        << number(frame(label).y) << "\">" << mark.seam + 1 << "</text>\n";
  }
  const PatternSegment grain = grainLine(panel);
  out << "    <path class=\"grain\" d=\"M " << point(frame, grain.from) << " L " << point(frame, grain.to)
      << "\" marker-start=\"url(#arrow)\" marker-end=\"url(#arrow)\"/>\n";
  // The name beside the grain line, high up where a panel is widest (a trouser panel splits into legs below).
  const glm::vec2 name = frame(grain.from + 0.75f * (grain.to - grain.from)) + glm::vec2(0.4f * kLabelHeight, 0.0f);
  out << "    <text class=\"name\" x=\"" << number(name.x) << "\" y=\"" << number(name.y) << "\">"
      << escaped(panel.name) << "</text>\n";
  out << "  </g>\n";
}

}  // namespace

std::string patternSvg(const Garment& garment, const PatternSvgOptions& options) {
  garment.validate();
  const float allowance = options.seamAllowance;
  checkSeamAllowance(allowance);

  // Lay the panels out left to right, tops level, below the title.
  const float titleHeight = 2.0f * kLabelHeight;
  std::vector<SheetFrame> frames(garment.panels.size());
  std::vector<std::vector<glm::vec2>> cutting(garment.panels.size());
  float left = kMargin, tallest = 0.0f;
  for (size_t i = 0; i < garment.panels.size(); ++i) {
    const Panel& panel = garment.panels[i];
    std::vector<glm::vec2> bounds = panel.outline(kPatternOutlineSegment);
    if (allowance > 0.0f) bounds = cutting[i] = cuttingLine(panel, allowance);
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
