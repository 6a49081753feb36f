#pragma once
// The marks a sewing pattern carries besides its sewing line, shared by the
// SVG and DXF writers: the cutting line a seam allowance outside, the grain
// line, and the notch at the middle of a sewn edge.

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "core/garment/panel.h"

namespace mq {

// The polygon (pieces of at most 2 mm) the cutting line is offset from.
constexpr float kPatternOutlineSegment = 0.002f;  // metres

// Throws mq::Error unless 0 <= allowance <= 10 cm.
void checkSeamAllowance(float allowance);

// The sewing line moved `allowance` (0 or more) outwards, with mitred corners, and
// straight runs as single segments (a cutter gets one segment per side).
std::vector<glm::vec2> cuttingLine(const Panel& panel, float allowance);

// The grain line: pattern v (along the body), over the middle two thirds of
// the longest vertical chord inside the panel, the one nearest its centre
// among those almost as long, so that it stays inside a two-legged panel.
struct PatternSegment {
  glm::vec2 from{0.0f}, to{0.0f};
};
PatternSegment grainLine(const Panel& panel);

// The colour that marks seam `seam` (both its edges) in every pattern
// drawing: "#rrggbb", eight colours in turn.
const char* seamColour(size_t seam);

// A notch at the middle (by arc length) of an edge: `depth` metres into the
// panel, square to the edge.
PatternSegment edgeNotch(const Panel& panel, int edge, float depth);

}  // namespace mq
