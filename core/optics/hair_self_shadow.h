#pragma once
// Hair self-shadowing: how much of a key light reaches each point of a set
// of strands through the strands in front of it (the survey's hair
// self-shadowing, section 2.6). Light falls off by Beer-Lambert with the
// number of strands crossed on the way, counted in one of two ways:
//  - PointCount: exact, the points ahead of each vertex in its column of a
//    grid across the light's rays (bilinear over the four nearest columns);
//  - OpacityMaps: Kim and Neumann's opacity shadow maps ("Opacity Shadow
//    Maps", 2001), `opacityMapCount` slices of the hair's depth along the
//    light, read by interpolation: faster on large grooms, converging to the
//    exact count as slices are added.
// Pure functions on the CPU (threaded): the hair actor turns the result into
// a per-vertex shader attribute.

#include <vector>

#include <glm/glm.hpp>

#include "core/hair/strands.h"

namespace mq::optics {

enum class HairShadowMethod {
  PointCount,   // exact: the points ahead of each vertex in its light column
  OpacityMaps,  // opacity shadow maps: opacityMapCount slices, linear in depth
};

struct HairShadowSettings {
  HairShadowMethod method = HairShadowMethod::PointCount;
  float perStrand = 0.05f;   // light lost per strand crossing (Beer-Lambert)
  float cellSize = 0.004f;   // metres: the light-aligned grid's cell
  float minShadow = 0.25f;   // floor: light scattered in from around
  int opacityMapCount = 32;  // OpacityMaps: slices from the hair's front to its back
};

// Per strand point, the light transmitted from `towardLight` (a direction,
// world), in [minShadow, 1]; 1 everywhere for strands of fewer than 2 points.
std::vector<float> hairSelfShadow(const Strands& strands, const glm::vec3& towardLight,
                                  const HairShadowSettings& settings);
std::vector<float> hairShadowByPointCount(const Strands& strands, const glm::vec3& towardLight,
                                          const HairShadowSettings& settings);
std::vector<float> hairShadowByOpacityMaps(const Strands& strands, const glm::vec3& towardLight,
                                           const HairShadowSettings& settings);

}  // namespace mq::optics
