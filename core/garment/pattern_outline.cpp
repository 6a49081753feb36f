#include "core/garment/pattern_outline.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/error.h"

namespace mq {
namespace {

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
// neighbours (a straight edge's samples).
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

glm::vec2 polygonCentroid(const std::vector<glm::vec2>& polygon) {
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

// The longest interval of the vertical line at `x` inside the polygon.
PatternSegment longestVerticalChord(const std::vector<glm::vec2>& polygon, float x) {
  std::vector<float> crossings;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const glm::vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    if ((a.x <= x) == (b.x <= x)) continue;  // half-open, so a vertex is crossed once
    crossings.push_back(a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x));
  }
  std::sort(crossings.begin(), crossings.end());
  PatternSegment best{{x, 0.0f}, {x, 0.0f}};
  for (size_t i = 0; i + 1 < crossings.size(); i += 2)
    if (crossings[i + 1] - crossings[i] > best.to.y - best.from.y) best = {{x, crossings[i]}, {x, crossings[i + 1]}};
  return best;
}

}  // namespace

void checkSeamAllowance(float allowance) {
  constexpr float kMaxSeamAllowance = 0.10f;  // metres
  if (!(allowance >= 0.0f && allowance <= kMaxSeamAllowance))
    throw Error("the seam allowance must be between 0 and " + std::to_string(int(kMaxSeamAllowance * 1000.0f)) + " mm");
}

std::vector<glm::vec2> cuttingLine(const Panel& panel, float allowance) {
  return simplified(offsetOutline(panel.outline(kPatternOutlineSegment), allowance));
}

PatternSegment grainLine(const Panel& panel) {
  constexpr int kSamples = 41;
  constexpr float kAlmostAsLong = 0.9f;
  const std::vector<glm::vec2> polygon = panel.outline(kPatternOutlineSegment);
  float left = polygon[0].x, right = polygon[0].x;
  for (glm::vec2 p : polygon) left = std::min(left, p.x), right = std::max(right, p.x);
  std::vector<PatternSegment> chords;
  float longest = 0.0f;
  for (int i = 1; i <= kSamples; ++i) {
    chords.push_back(longestVerticalChord(polygon, left + (right - left) * float(i) / float(kSamples + 1)));
    longest = std::max(longest, chords.back().to.y - chords.back().from.y);
  }
  const float centre = polygonCentroid(polygon).x;
  PatternSegment chosen = chords[kSamples / 2];
  float nearest = INFINITY;
  for (const PatternSegment& chord : chords)
    if (chord.to.y - chord.from.y >= kAlmostAsLong * longest && std::abs(chord.from.x - centre) < nearest)
      chosen = chord, nearest = std::abs(chord.from.x - centre);
  const float reach = (chosen.to.y - chosen.from.y) / 3.0f, middle = 0.5f * (chosen.from.y + chosen.to.y);
  return {{chosen.from.x, middle - reach}, {chosen.from.x, middle + reach}};
}

const char* seamColour(size_t seam) {
  static const char* const colours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd",
                                        "#ff7f0e", "#17becf", "#e377c2", "#8c564b"};
  return colours[seam % std::size(colours)];
}

PatternSegment edgeNotch(const Panel& panel, int edge, float depth) {
  const glm::vec2 middle = panel.sampleEdge(edge, 2)[1];
  const glm::vec2 tangent = panel.edgePoint(edge, 0.51f) - panel.edgePoint(edge, 0.49f);
  const glm::vec2 inward =
      glm::length(tangent) > 0.0f ? glm::normalize(glm::vec2(-tangent.y, tangent.x)) : glm::vec2(0.0f);
  return {middle, middle + inward * depth};
}

}  // namespace mq
