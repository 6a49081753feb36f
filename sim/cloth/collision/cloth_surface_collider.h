#pragma once
// The surface of other cloth as a collider: the inner garments an outer one
// is worn over (layering, sim/garment/garment_layers.h). Their current
// triangles in a 4-wide BVH refitted every move, like the body
// (body_collider.h), moving linearly from the last pose to the target over a
// step, with the inner cloth's velocity at every contact.
//
// Unlike the body, cloth is an open, two-sided surface:
// - The side an outer vertex belongs on is the side the inner surface's
//   triangles face. Garment meshes face outwards, away from the body (and
//   the welded cloth keeps that orientation), so this is also "away from the
//   body": a vertex on the other side (between the inner garment and the
//   body, however it got there) is pushed through to the outer side.
// - A hem, cuff, neck or waist opening ends the surface: when the nearest
//   point is on such a boundary edge (or a boundary vertex) and the vertex
//   lies beyond it rather than over it, the nearest point says nothing of
//   inside or outside: a vertex there on the side the surface does not face
//   gets no contact (the T-shirt inside the trousers' waist opening, above
//   the waistband, is left alone), one on the side it faces a contact that
//   only keeps it off the edge (never through the surface).

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "sim/cloth/collision/wide_tree.h"

namespace mq::cloth {

struct SurfaceContact {
  glm::vec3 point{0.0f}, normal{0.0f}, velocity{0.0f};
  float signedDistance = 0.0f;  // < 0: on the side the surface does not face
};

// How far behind an inner surface an outer cloth vertex is still seen (and
// pushed through to the outer side): as deep as the body's search, a few
// thicknesses; deeper, the nearest point is more likely another part of the garment.
inline float innerSurfaceSearchRadius(float thickness) { return std::max(0.02f, 3.0f * thickness); }

class ClothSurfaceCollider {
 public:
  // A new surface (topology): positions and triangles (3 per triangle,
  // facing the side outer cloth belongs on). The surface starts still there.
  void setMesh(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& triangles);
  // The surface at the end of the next step, reached after `stepTime` seconds
  // (the current target becomes the start).
  void setTarget(const std::vector<glm::vec3>& positions, float stepTime);
  // Positions at a fraction [0,1] of the way from the start to the target.
  void moveTo(float fraction);
  // The nearest contact within `radius`; false when there is none or when
  // the vertex lies beyond a boundary edge on the back side (see above).
  bool nearestContact(const glm::vec3& p, float radius, SurfaceContact& contact) const;

  bool empty() const { return triangles_.empty(); }
  size_t vertexCount() const { return current_.size(); }
  const std::vector<glm::vec3>& positions() const { return current_; }

 private:
  void updateNormals();
  // The normal that decides the side at barycentric weights `w` of triangle
  // `t`, and whether that feature (edge or vertex) is on the boundary.
  glm::vec3 featureNormal(uint32_t t, const glm::vec3& w, bool& onBoundary) const;

  std::vector<uint32_t> triangles_;
  std::vector<int32_t> edgeNeighbour_;  // 3 per triangle: the triangle across edge (i, i+1), or -1
  std::vector<uint8_t> boundaryVertex_;
  std::vector<glm::vec3> from_, to_, current_, velocity_;
  std::vector<glm::vec3> faceNormal_;    // unit, per triangle
  std::vector<glm::vec3> vertexNormal_;  // angle-weighted, unit, per vertex
  WideTree tree_;
};

}  // namespace mq::cloth
