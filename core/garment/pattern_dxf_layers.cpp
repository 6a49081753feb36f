#include "core/garment/pattern_dxf_layers.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace mq::dxf_layers {

std::string placementText(const PanelPlacement& p) {
  const float values[] = {p.radius, p.center.x, p.center.y, p.center.z, p.axis.x,   p.axis.y,
                          p.axis.z, p.facing.x, p.facing.y, p.facing.z, p.anchor.x, p.anchor.y};
  std::string text = p.shape == PanelPlacement::Shape::Cylinder ? "cylinder" : "plane";
  for (float v : values) {
    char number[32];
    std::snprintf(number, sizeof number, " %.9g", double(v));
    text += number;
  }
  return text + " " + p.bone;
}

std::optional<PanelPlacement> placementFromText(const std::string& text) {
  std::istringstream in(text);
  std::string shape;
  in >> shape;
  if (shape != "cylinder" && shape != "plane") return std::nullopt;
  PanelPlacement p;
  p.shape = shape == "cylinder" ? PanelPlacement::Shape::Cylinder : PanelPlacement::Shape::Plane;
  float* fields[] = {&p.radius, &p.center.x, &p.center.y, &p.center.z, &p.axis.x,   &p.axis.y,
                     &p.axis.z, &p.facing.x, &p.facing.y, &p.facing.z, &p.anchor.x, &p.anchor.y};
  for (float* field : fields)
    if (!(in >> *field) || !std::isfinite(*field)) return std::nullopt;
  in >> std::ws;
  std::getline(in, p.bone);
  return p;
}

}  // namespace mq::dxf_layers
