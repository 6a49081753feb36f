#pragma once
// Pattern edges from a polyline outline another program wrote: the run is cut
// at its corners (given, or found where it bends), and each piece between
// corners becomes a straight edge or cubic Bezier curves within 0.5 mm.

#include <vector>

#include <glm/glm.hpp>

#include "core/garment/panel.h"

namespace mq {

struct FittedEdge {
  EdgeShape shape = EdgeShape::Line;  // Line or Cubic
  glm::vec2 start{0.0f};
  glm::vec2 control[2]{};
};

// `run`: points in metres from one corner to the next corner (or around to
// itself); `corner[i]`: point i must stay a corner. With findBends, points
// where the run turns by more than 20 degrees are corners too. The edges
// cover the run in order; the last ends at run.back().
std::vector<FittedEdge> fitOutlineRun(const std::vector<glm::vec2>& run, std::vector<bool> corner, bool findBends);

}  // namespace mq
