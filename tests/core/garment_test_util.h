#pragma once
// Panels the garment tests share.

#include <string>

#include "core/garment/panel.h"

namespace mq::test {

// A width x height rectangle, counter-clockwise from the origin, its edges
// named bottom, right, top and left.
inline Panel rectanglePanel(const std::string& name, float width, float height) {
  Panel p;
  p.name = name;
  p.addLine("bottom", {0.0f, 0.0f});
  p.addLine("right", {width, 0.0f});
  p.addLine("top", {width, height});
  p.addLine("left", {0.0f, height});
  return p;
}

}  // namespace mq::test
