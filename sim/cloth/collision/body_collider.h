#pragma once
// The animated skinned body as a collider: its triangles in two 4-wide BVHs
// of the same shape refitted every move that moves it, one over each
// triangle now (for the nearest-point search), one over each triangle and
// its motion in the last move (for the swept test), so both queries visit
// only the triangles they could meet. The nearest-point search bounds the
// distances of a tree node's triangles from below four at once (SSE) and
// finds the exact closest point only on those that could be the nearest.
// Between two frames the body moves linearly; a cloth vertex
// closer than `thickness` to the surface (or behind it) is pushed out with the
// contact response, relative to the body's velocity at the contact point.
// Inside/outside comes from the angle-weighted pseudo-normal of the nearest
// feature (face, edge or vertex; Baerentzen & Aanaes 2005), which is exact for
// a closed, outward-oriented surface even in creases such as the armpit, where
// the nearest triangle's own normal can point either way; vertices deeper than
// the search radius are not seen.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "sim/cloth/collision/wide_tree.h"

namespace mq::cloth {

struct BodyContact {
  glm::vec3 point, normal, velocity;
  float signedDistance;
  int32_t triangle = -1;  // nearestContact(): the nearest triangle (a hint for the next query)
};

// One point's (a cloth vertex's) last nearest query at a body pose, kept
// for its next queries: while the body keeps that pose, the surface is no
// nearer to the point than the distance found less the point's move since.
struct BodyQuery {
  uint64_t pose = 0;  // BodyCollider::pose() of the query; 0: none
  glm::vec3 point{0.0f};
  float radius = 0.0f;
  bool found = false;
  float clearance = 0.0f;              // when not found: the surface is no nearer than this (>= radius)
  BodyContact contact;                 // when found
  float distance2 = 0.0f;              // when found: the nearest triangle's squared distance, as the search had it
  glm::vec3 weights{0.0f};             // ... and the contact point's barycentric weights on it
  uint32_t queries = 0, searches = 0;  // counts for the stats: queries asked, and those that searched the body
  // The point's last segment without a hit (firstHitAlong()), and the move it was tested in.
  uint64_t missMove = 0;
  glm::vec3 missFrom{0.0f}, missTo{0.0f};
};

class BodyCollider {
 public:
  // Rest (or first) pose: flat positions (3 per vertex) and triangles.
  void setMesh(const std::vector<float>& positions, const std::vector<uint32_t>& triangles, float searchRadius);
  // The pose at the end of the next frame, reached after `frameTime` seconds.
  void setTarget(const std::vector<float>& positions, float frameTime);
  // Back to the pose at the start of the step (to redo a step).
  void restartStep() { moveTo(0.0f); }
  // Positions at a fraction [0,1] of the way from the last pose to the target.
  void moveTo(float fraction);
  // First crossing of the surface from outside to inside along the segment
  // from -> to (contact.point is the crossing); false when there is none.
  // Continuous in the body's motion too: `from` is where the vertex was
  // before the last moveTo(), and each triangle is tested against the
  // vertex's motion relative to that triangle (the triangle's own
  // displacement added to `from`), so a fast limb cannot sweep through a
  // still vertex and leave it inside or on its far side.
  bool firstHitAlong(const glm::vec3& from, const glm::vec3& to, BodyContact& contact) const;
  // Nearest contact within the search radius; false when there is none.
  bool nearestContact(const glm::vec3& p, BodyContact& contact) const {
    return nearestContact(p, contact, searchRadius_);
  }
  // ... within `radius` instead.
  bool nearestContact(const glm::vec3& p, BodyContact& contact, float radius) const {
    return nearestContact(p, contact, radius, -1);
  }
  // ... starting from triangle `hint` (e.g. the nearest one of the vertex's
  // last query; -1: none): the same answer, found sooner when the hint is
  // near, since its distance bounds the search from the start.
  bool nearestContact(const glm::vec3& p, BodyContact& contact, float radius, int32_t hint) const;
  // ... the same answer, from the point's last query `last` (updated): its
  // answer again when the point has not moved (same pose; within this
  // radius or not), its nearest triangle as the hint otherwise.
  bool nearestContact(const glm::vec3& p, BodyContact& contact, float radius, BodyQuery& last) const;
  // ... the same, without updating `last` (and false at once when it
  // proves none within the radius: provesNoneWithin()).
  bool nearestContactSince(const glm::vec3& p, BodyContact& contact, float radius, const BodyQuery& last) const;
  // Whether `last` proves, without a search, that nothing is within `radius`
  // of p (p is farther from its point than the surface was, less the radius).
  bool provesNoneWithin(const BodyQuery& last, const glm::vec3& p, float radius) const;
  // firstHitAlong(), but false at once when `last` holds the same segment
  // without a hit in this move (else it keeps this one when it has none).
  bool firstHitAlong(const glm::vec3& from, const glm::vec3& to, BodyContact& contact, BodyQuery& last) const;
  // Fastest vertex speed in the current frame (between the last pose and the target).
  float maxSpeed() const { return maxSpeed_; }

  bool empty() const { return triangles_.empty(); }
  const std::vector<glm::vec3>& positions() const { return current_; }
  // Each vertex's velocity in the current frame (from the last pose to the target).
  const std::vector<glm::vec3>& velocities() const { return velocity_; }
  std::vector<float> flatPositions() const;
  const std::vector<uint32_t>& triangles() const { return triangles_; }
  float searchRadius() const { return searchRadius_; }
  // Whether the last moveTo() moved the body at all.
  bool moved() const { return maxDisplacement_ > 0.0f; }

 private:
  // The normal that decides inside/outside for a closest point with
  // barycentric weights `w` on triangle `t`.
  glm::vec3 pseudoNormal(uint32_t t, const glm::vec3& w) const;
  glm::vec3 unitFaceNormal(uint32_t t) const;
  struct Nearest {
    int64_t triangle = -1;
    glm::vec3 weights{0.0f};
    float distance2;
    // When none is found: no triangle's squared distance is below this
    // (but for rounding), from the boxes and triangles passed over.
    float passed2 = 1e30f;
  };
  // Takes triangle t as `best` when it is nearer to p (of triangles equally
  // near, the lowest index wins: the answer does not depend on the order).
  // Returns t's squared distance.
  float considerTriangle(uint32_t t, const glm::vec3& p, Nearest& best) const;
  // considerTriangle() for the triangles in the tree node's `slotMask`, nearest
  // lower bound first, skipping those whose lower bound (four at once)
  // proves them farther than `best` with a margin for rounding: so the
  // triangles that could be the nearest are all considered, and the answer
  // is that of considering them all. best.passed2 takes the distances (or
  // lower bounds) of those not taken.
  void considerSlots(uint32_t node, int slotMask, const glm::vec3& p, Nearest& best) const;
  // The corners of the triangles in the tree's slots, after a move.
  void updateSlotCorners();
  glm::vec3 velocityAt(uint32_t t, const glm::vec3& w) const;
  // Whether `last` answers a query from p within `radius` as it is (the
  // same point at the same pose); then `within` tells whether it found a
  // contact there, and `contact` gets it.
  bool keptAnswer(const BodyQuery& last, const glm::vec3& p, float radius, BodyContact& contact, bool& within) const;
  Nearest searchNearest(const glm::vec3& p, float radius, int32_t hint) const;
  bool contactAt(const glm::vec3& p, const Nearest& best, BodyContact& contact) const;

  std::vector<uint32_t> triangles_;
  std::vector<int32_t> edgeNeighbour_;               // 3 per triangle: the triangle across edge (i, i+1), or -1
  std::vector<uint32_t> ringStart_, ringTriangles_;  // vertex -> triangles around it (CSR)
  std::vector<glm::vec3> from_, to_, current_, previous_, velocity_;
  float maxDisplacement_ = 0.0f;  // largest vertex move of the last moveTo()
  float maxSpeed_ = 0.0f;
  WideTree tree_;  // the triangles' boxes now
  // For each node of tree_, the corners of the triangles in its slots (four
  // lanes: corner, axis, slot), for considerSlots().
  struct alignas(16) SlotCorners {
    float corner[3][3][4];
  };
  std::vector<SlotCorners> slotCorners_;
  WideTree sweptTree_;  // ... grown over their motion in the last move
  float searchRadius_ = 0.02f;
  uint64_t pose_ = 0;
  uint64_t move_ = 0;  // counts the moves (moveTo() calls and setMesh()): firstHitAlong() depends on the last one
};

}  // namespace mq::cloth
