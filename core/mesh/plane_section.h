#pragma once
// Where a plane cuts a closed triangle mesh: the section's closed loops, and
// the planar polygon measures the skinning metrics need (area, the loop
// around a point, a ray's exit distance, the part on one side of a line).
// Vertices exactly on the plane count as above it (a consistent symbolic
// perturbation), so every loop is closed on a 2-manifold.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace mq {

// A plane's 2D chart: points p map to ((p - origin) . u, (p - origin) . v).
struct PlaneChart {
  glm::dvec3 origin, normal, u, v;
  PlaneChart(const glm::dvec3& origin, const glm::dvec3& normal);
  glm::dvec2 toPlane(const glm::dvec3& p) const;
};

using Polygon2 = std::vector<glm::dvec2>;

// The closed loops of the section of the mesh by the chart's plane, in the
// chart's coordinates. Open chains (a mesh with holes) are dropped.
std::vector<Polygon2> sectionLoops(const std::vector<float>& positions, const std::vector<uint32_t>& triangles,
                                   const PlaneChart& chart);

double polygonArea(const Polygon2& polygon);  // absolute
bool polygonContains(const Polygon2& polygon, const glm::dvec2& point);
// The smallest loop containing `point`; nullptr when none does.
const Polygon2* loopAround(const std::vector<Polygon2>& loops, const glm::dvec2& point);
// Distance from `from` along the unit `direction` to the polygon's nearest
// edge ahead; -1 when the ray meets none.
double rayExitDistance(const Polygon2& polygon, const glm::dvec2& from, const glm::dvec2& direction);
// The polygon clipped to the half-plane (x - point) . direction >= 0.
Polygon2 clipToHalfPlane(const Polygon2& polygon, const glm::dvec2& point, const glm::dvec2& direction);

}  // namespace mq
