#pragma once
// Body features against cloth triangles: a body vertex that pierces a cloth
// triangle between its vertices (a shin through the front of a trouser leg
// whose vertices are all outside the leg) or comes closer to it than the
// thickness. The vertex contacts of BodyCollider only see cloth vertices, so
// on a cloth coarser than the body (3 cm trouser triangles over a body of
// about 8 mm edges) a limb can pass between them.
//
// Candidates: the body's vertices, in runs of nearby ones (Morton order),
// against a BVH over the cloth's triangles (refitted every call, rebuilt now
// and then), then cheap ball, plane and circle tests. The cloth belongs
// outside the body, so "out" for a triangle is the side the body vertex's
// outward normal points to; a triangle whose point under the vertex lies
// behind it by up to maxDepth() (unless that point is outside the body
// beyond a surface facing the other way: cloth beyond a thin body part) or in
// front of it by less than half the thickness is pushed along its normal
// until that point is half the thickness in front of the body vertex. The
// push is shared by the triangle's vertices by barycentric weight and inverse
// mass, so the point under the body vertex moves that far (Bridson, Fedkiw
// and Anderson 2002; no vertex more than 4 times that), and the approaching
// normal velocity relative to the body is removed the same way. Contacts are
// found in parallel and applied in a fixed order, Gauss-Seidel:
// deterministic. The simulator calls it after the vertex contacts, before the
// final elongation limit, which holds the vertices of pierced triangles like
// those a moving body part swept along; when that fails, reapply() pushes the
// same pairs out again between the rounds of the limit.

#include <cstdint>
#include <vector>

#include "sim/cloth/cloth_state.h"
#include "sim/cloth/collision/aabb_tree.h"
#include "sim/cloth/collision/body_collider.h"

namespace mq::cloth {

class BodyFeatureContact {
 public:
  BodyFeatureContact(const std::vector<uint32_t>& clothTriangles, const std::vector<glm::vec3>& restPositions);
  // Pushes cloth triangles off the body's vertices (the body as it is now);
  // the cloth vertices it moves get touched[v] = max(touched[v], mark), mark
  // = piercedMark where a body vertex was through the triangle, else nearMark.
  // Returns the number of body vertex - cloth triangle contacts found.
  int resolve(ClothState& s, const BodyCollider& body, float thickness, std::vector<uint8_t>& touched,
              uint8_t nearMark, uint8_t piercedMark);
  // The pairs of the last resolve() (and those a little beyond its gap)
  // pushed apart again, against the same body pose, to a smaller gap (out of
  // the skin with the least displacement): after the elongation limit, which
  // pulls cloth stretched over a bent knee back through it. Sets pushed[v]
  // = 1 for the cloth vertices it moves; returns the pushes made.
  int reapply(ClothState& s, const BodyCollider& body, float thickness, std::vector<uint8_t>& pushed) const;

  // How deep behind a cloth triangle a body vertex is still pushed out of
  // it: half the cloth's mean edge length, within these bounds (m).
  static constexpr float kMinDepth = 0.005f, kMaxDepth = 0.02f;
  float maxDepth() const { return maxDepth_; }

 private:
  struct Contact {
    uint32_t bodyVertex, triangle;
    glm::vec3 weights;          // of the triangle's point under the body vertex
    float side;                 // +1 / -1: the triangle's normal times this points out of the body
    glm::vec3 surfaceVelocity;  // the body vertex's
    bool pierced;               // the body vertex was in front of the triangle
    bool withinGap;             // in contact when found (else kept for reapply())
  };
  void prepareBody(const BodyCollider& body);
  // Planes, bounding circles and the tree of the cloth's triangles now.
  void updateTriangles(const ClothState& s, float thickness);
  std::vector<Contact> findContacts(const ClothState& s, const BodyCollider& body, float thickness) const;
  // Moves the triangle's point under the body vertex `gap` in front of it.
  bool apply(ClothState& s, const BodyCollider& body, const Contact& c, float gap) const;

  struct Plane {
    glm::vec3 normal;  // unit (zero for a degenerate triangle)
    float offset;      // dot(normal, a point of the triangle)
    glm::vec3 centroid;
    float reach;  // circumscribing radius about the centroid plus the thickness
  };
  std::vector<uint32_t> triangles_;
  std::vector<Contact> contacts_;  // of the last resolve()
  float maxDepth_ = kMaxDepth;
  std::vector<Plane> planes_;
  AabbTree tree_;
  static constexpr int kRebuildEvery = 16;  // calls between tree rebuilds (refitted in between)
  int callsSinceBuild_ = 0;
  // Body vertex -> its triangles (CSR), for outward vertex normals.
  std::vector<uint32_t> ringStart_, ringTriangles_;
  std::vector<uint32_t> clusterOrder_;  // body vertices, runs of nearby ones
  size_t bodyTriangleCount_ = 0;
};

}  // namespace mq::cloth
