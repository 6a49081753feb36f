#pragma once
// Body features against cloth triangles: a body vertex that pierces a cloth
// triangle between its vertices (a shin through the front of a trouser leg
// whose vertices are all outside the leg) or comes closer to it than the
// thickness. The vertex contacts of BodyCollider only see cloth vertices, so
// on a cloth coarser than the body (3 cm trouser triangles over a body of
// about 8 mm edges) a limb can pass between them.
//
// Candidates: the body's vertices, in runs of four nearby ones (Morton
// order), against a 4-wide BVH over the cloth's triangles (refitted every
// call, rebuilt when it has grown loose); each triangle the run's box meets
// gets cheap ball, plane and circle tests against the four vertices at once
// (SSE). The cloth belongs outside the body, so "out" for a triangle is the
// side the body vertex's outward normal points to; a triangle whose point
// under the vertex lies behind it by up to maxDepth() (unless that point is
// outside the body beyond a surface facing the other way: cloth beyond a
// thin body part) or in front of it by less than half the thickness is pushed
// along its normal until that point is half the thickness in front of the
// body vertex. The push is shared by the triangle's vertices by barycentric
// weight and inverse mass, so the point under the body vertex moves that far
// (Bridson, Fedkiw and Anderson 2002; no vertex more than 4 times that), and
// the approaching normal velocity relative to the body is removed the same
// way. Contacts are found in parallel and applied in a fixed order,
// Gauss-Seidel: deterministic. The simulator calls it after the vertex
// contacts, before the final elongation limit, which holds the vertices of
// pierced triangles like those a moving body part swept along; when that
// fails, reapply() pushes the same pairs out again between the rounds of the
// limit.

#include <cstdint>
#include <vector>

#include "sim/cloth/cloth_state.h"
#include "sim/cloth/collision/aabb_tree.h"
#include "sim/cloth/collision/body_collider.h"
#include "sim/cloth/collision/wide_tree.h"

namespace mq::cloth {

class BodyFeatureContact {
 public:
  // How the triangles near a run of body vertices are found: the tree, or
  // (a reference for tests) every triangle's box tested, with scalar tests.
  enum class Search { Tree, EveryTriangle };
  BodyFeatureContact(const std::vector<uint32_t>& clothTriangles, const std::vector<glm::vec3>& restPositions,
                     Search search = Search::Tree);
  // Pushes cloth triangles off the body's vertices (the body as it is now);
  // the cloth vertices it moves get touched[v] = max(touched[v], mark), mark
  // = piercedMark where a body vertex was through the triangle, else nearMark.
  // Returns the number of body vertex - cloth triangle contacts found.
  int resolve(ClothState& s, const BodyCollider& body, float thickness, std::vector<uint8_t>& touched, uint8_t nearMark,
              uint8_t piercedMark);
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

  // The body vertex - cloth triangle pairs of the last resolve() (those in
  // contact and those kept for reapply()), in the order they are applied.
  struct Pair {
    uint32_t bodyVertex, triangle;
    bool pierced, withinGap;
    bool operator==(const Pair& o) const {
      return bodyVertex == o.bodyVertex && triangle == o.triangle && pierced == o.pierced && withinGap == o.withinGap;
    }
  };
  std::vector<Pair> lastPairs() const;

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
  // Bit k set: body vertex k of the run passes the ball, plane and circle
  // tests of triangle t (k < count).
  unsigned nearMask(const float (&run)[3][4], int count, uint32_t t) const;
  unsigned nearMaskScalar(const float (&run)[3][4], int count, uint32_t t) const;

  Search search_;
  std::vector<uint32_t> triangles_;
  std::vector<Contact> contacts_;  // of the last resolve()
  float maxDepth_ = kMaxDepth;
  std::vector<Plane> planes_;
  std::vector<Box> boxes_;  // the triangles' boxes now
  WideTree tree_;           // over boxes_
  // The tree is refitted every call and rebuilt when its nodes' boxes have
  // grown by this factor since it was built (their sum of half-perimeters):
  // cloth keeps its neighbours, so a refitted tree stays good for long.
  static constexpr float kRebuildGrowth = 1.25f;
  float builtSize_ = 0.0f;
  // The corners of the body's triangles around each body vertex, for its
  // outward normal (CSR, the vertices in clusterOrder_'s order: read in sequence).
  std::vector<uint32_t> ringStart_;
  std::vector<glm::uvec3> ringCorners_;
  std::vector<uint32_t> clusterOrder_;  // body vertices, runs of nearby ones
  size_t bodyTriangleCount_ = 0;
};

}  // namespace mq::cloth
