#pragma once
// Measures of how well a skinning keeps the body's shape, as defined in the
// skinning research brief (M1-M4, M6): each compares the posed skin with the rest
// skin, on the character's meshes welded into one closed body (vertices with
// bit-equal rest positions merged, as exporters split them at UV seams).

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/character/posed_character.h"
#include "core/mesh/position_weld.h"

namespace mq {

class ImplicitBody;

class MetricBody {
 public:
  explicit MetricBody(const Character& character);

  // The posed meshes' positions on the welded vertices.
  std::vector<float> weld(const std::vector<PosedMesh>& posed) const;
  const std::vector<uint32_t>& triangles() const { return weld_.triangles; }
  size_t vertexCount() const { return weld_.vertexCount(); }

 private:
  PositionWeld weld_;  // over the meshes' vertices one after the other
};

// A hinge bend: the joint j (the child bone's head), the parent's and the
// child's unit directions at rest and posed, and which way the child turned:
// `inward` is the rest direction the child moved towards (hinge x d_child
// times the angle's sign).
struct BendFrame {
  glm::dvec3 jointRest, jointPosed;
  glm::dvec3 parentRest, childRest, parentPosed, childPosed;
  glm::dvec3 inward;
};

struct OuterSection {
  double thickness = -1.0;  // M1: distance from j to the skin along the outer direction, posed / rest
  double halfArea = -1.0;   // M1: the outer half of the section's area, posed / rest
};

// M1: the section by the bisecting plane (normal d_parent + d_child) through
// the joint, on the loop around the joint.
OuterSection outerSection(const std::vector<float>& rest, const std::vector<float>& posed,
                          const std::vector<uint32_t>& triangles, const BendFrame& bend);

// M2: the least ratio posed / rest of the section area around the axis,
// over planes perpendicular to `axis` through joint + s axis, s from
// `from` to `to` every `step` metres. -1 when no rest section exists.
double minimumSectionRatio(const std::vector<float>& rest, const std::vector<float>& posed,
                           const std::vector<uint32_t>& triangles, const glm::dvec3& joint, const glm::dvec3& axis,
                           double from, double to, double step);

// M3: the volume of the triangles whose rest centroid lies within `radius`
// of the rest joint, as cones to the joint (rest joint for the rest mesh,
// posed joint for the posed), posed / rest.
double localVolumeRatio(const std::vector<float>& rest, const std::vector<float>& posed,
                        const std::vector<uint32_t>& triangles, const glm::dvec3& jointRest,
                        const glm::dvec3& jointPosed, double radius);

// M4: triangle pairs that cross each other (CGAL, exact predicates); 0 for a
// body that is not 2-manifold is never returned: that throws.
size_t intersectingPairs(const std::vector<float>& positions, const std::vector<uint32_t>& triangles);

// M6, for a skin polygonised from an implicit body (the mannequin): the posed
// body's field (each primitive moved by its bone, about a signed distance,
// negative inside) at the posed vertices whose rest position lies within
// `radius` of `jointRest`. In metres; vertices 0 when none is that close.
struct BodyDeviation {
  size_t vertices = 0;
  double mean = 0.0;  // negative: sunk into the body
  double rms = 0.0;
  double largest = 0.0;    // largest |deviation|
  double beyond2mm = 0.0;  // share of the vertices more than 2 mm inside or outside
};
BodyDeviation implicitBodyDeviation(const ImplicitBody& posedBody, const std::vector<float>& rest,
                                    const std::vector<float>& posed, const glm::dvec3& jointRest, double radius);

}  // namespace mq
