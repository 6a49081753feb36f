#pragma once
// Cloth-cloth collisions with a BVH over the cloth's triangles: vertex-triangle
// and edge-edge proximity (Bridson, Fedkiw and Anderson 2002, simplified).
// Candidates are pairs whose boxes, swept over the step and grown by the
// thickness, overlap. Which side of each other two elements are on is read at
// the start of the step (x0), so an element that crossed during the step is
// pulled back to its side. At the end of the step every pair closer than the
// thickness along that side's normal is pushed apart (mass-weighted, like a
// position constraint) and loses its approaching relative normal velocity.
// Pairs are processed in a fixed order: deterministic. The vertices are
// looked up in the triangle tree a few at a time (those whose first triangle
// in the tree is in one small subtree), the walks of a few such groups started
// together, and each pair screened four triangles at once (TriangleColumns)
// before its exact test; the edge pairs from the edge tree against itself.
//
// A candidate also passes dist(x0) <= thickness + the largest difference of
// its vertices' moves in the step. When the moves differ much (a sleeve
// swinging), the searches test that for whole tree nodes from the boxes of
// their start positions and of their moves, so they leave out the parts
// that cannot meet however far the cloth moves (same candidates).
//
// Pairs within a flat patch are not looked for (after Volino and
// Magnenat-Thalmann's curvature test): a node of the edge or triangle tree
// whose elements are connected and whose triangles' normals, at the start and
// the end of the step, lie within 45 degrees of their mean is a surface that
// cannot fold onto itself, so its elements keep their mesh distances from each
// other. Edge pairs are skipped within such edge tree nodes, vertex-triangle
// pairs when the triangle and one of the vertex's triangles are in such a
// triangle tree node. The patch's contour is not tested (a patch that closes
// on itself in its plane is taken as flat too).

#include <array>
#include <cstdint>
#include <vector>

#include "sim/cloth/cloth_state.h"
#include "sim/cloth/collision/aabb_tree.h"
#include "sim/cloth/collision/triangle_reach.h"

namespace mq::cloth {

// The smallest of dot(axis, n) over the normals n given as columns (four at a
// time with SSE: the same products and sums, so the same result).
float smallestAlignment(const float* x, const float* y, const float* z, size_t count, const glm::vec3& axis);

// Unit normals as columns: perPlace of them for each place of a tree.
struct PlaceNormals {
  std::vector<float> x, y, z;
  uint32_t perPlace = 1;
  void resize(size_t places, uint32_t per) {
    perPlace = per;
    for (std::vector<float>* c : {&x, &y, &z}) c->resize(places * per);
  }
  void set(size_t k, const glm::vec3& n) { x[k] = n.x, y[k] = n.y, z[k] = n.z; }
};

// Where a part of the cloth is at the start of a step and how its vertices
// move in the step: the boxes of their start positions and of their moves,
// as rows (x, y, z, 0) in one cache line (compared four lanes at a time).
struct alignas(64) NodeMotion {
  glm::vec4 startMin{1e30f, 1e30f, 1e30f, 0.0f}, startMax{-1e30f, -1e30f, -1e30f, 0.0f};
  glm::vec4 moveMin{1e30f, 1e30f, 1e30f, 0.0f}, moveMax{-1e30f, -1e30f, -1e30f, 0.0f};
};

class SelfCollision {
 public:
  SelfCollision(const std::vector<uint32_t>& triangles, size_t vertexCount);
  // Returns the number of pairs that were closer than `thickness`.
  int resolve(ClothState& s, const std::vector<glm::vec3>& x0, float thickness, int passes);
  // The last resolve()'s candidate pairs.
  size_t vertexTriangleCandidates() const { return vertexTriangle_.size(); }
  size_t edgeEdgeCandidates() const { return edgeEdge_.size(); }
  // Whether the searches leave out the nodes and elements out of each
  // other's reach from their start boxes and move boxes (on by default, used
  // in the steps whose moves differ by more than twice the thickness; off,
  // they visit every pair whose boxes overlap: the candidates are the same).
  void setMotionBounds(bool on) { motionBounds_ = on; }
  // Whether every pair of elements is tested instead of searching the trees
  // (a reference for tests: the same candidates, slowly).
  void setExhaustive(bool on) { exhaustive_ = on; }
  // The last resolve()'s candidates, in their order: (vertex, triangle) and
  // (edge, edge) with the edges' vertices.
  std::vector<std::array<uint32_t, 2>> vertexTrianglePairs() const;
  std::vector<std::array<uint32_t, 4>> edgeEdgePairs() const;

 private:
  struct VertexTriangle {
    uint32_t vertex, triangle;
    glm::vec3 weights;  // closest point at x0
    float side;         // +1 / -1: the vertex's side of the triangle at x0
  };
  struct EdgeEdge {
    uint32_t e0, e1;
    glm::vec2 params;   // closest points at x0
    glm::vec3 normal0;  // direction from edge 1 to edge 0 at x0
  };
  // The candidate search, as stages (self_collision.cpp lists them; each is
  // in its file under self_collision/). Step: one step's shared state.
  struct Step;
  void findCandidates(const ClothState& s, const std::vector<glm::vec3>& x0, float thickness);
  void measureMoves(Step& step) const;                                          // element_boxes.cpp
  void findElementBoxes(Step& step) const;                                      // element_boxes.cpp
  void updateTrees(Step& step);                                                 // tree_update.cpp
  void findConnectedPatches();                                                  // tree_update.cpp, after a build
  void findVertexPlaces();                                                      // tree_update.cpp
  void findVertexGroups();                                                      // tree_update.cpp
  void findMotionBounds(Step& step);                                            // motion_bounds.cpp
  void findFlatPatches(const ClothState& s, const std::vector<glm::vec3>& x0);  // flat_patches.cpp
  void findVertexTriangleCandidates(const Step& step);                          // vertex_triangle_candidates.cpp
  void findEdgeEdgeCandidates(const Step& step);                                // edge_edge_candidates.cpp
  int applyVertexTriangle(ClothState& s, const VertexTriangle& c, float thickness) const;
  int applyEdgeEdge(ClothState& s, const EdgeEdge& c, float thickness) const;

  std::vector<uint32_t> triangles_;
  std::vector<std::pair<uint32_t, uint32_t>> edges_;
  std::vector<uint32_t> triangleEdges_;                 // 3 per triangle
  std::vector<std::array<uint32_t, 2>> edgeTriangles_;  // the (one or two) triangles of each edge
  size_t vertexCount_;
  AabbTree tree_;      // over the triangles' boxes
  AabbTree edgeTree_;  // over the edges' boxes
  std::vector<VertexTriangle> vertexTriangle_;
  std::vector<EdgeEdge> edgeEdge_;
  // The most triangles whose vertices are queried as one group, and the most vertices in a group.
  static constexpr uint32_t kGroupTriangles = 8, kGroupVertices = 3 * kGroupTriangles;
  // Groups whose walks start together, where the walk for their boxes' union
  // reaches nodes of at most kRunSplit triangles.
  static constexpr size_t kRunGroups = 8;
  static constexpr uint32_t kRunSplit = 128;
  // The trees are refitted every step and rebuilt when the sum of their
  // nodes' half-perimeters has grown by this factor since they were built
  // (the edge tree's, the triangle tree's): a cloth keeps its neighbours, so
  // a refitted tree stays good for long (a rebuild every few steps cost more
  // to build than it saved).
  static constexpr float kRebuildGrowth = 1.25f;
  float builtSizes_[2] = {0.0f, 0.0f};
  // Per node of the edge and triangle trees: its primitives are connected
  // (found at each build), and connected and flat in this step.
  std::vector<uint8_t> connectedEdgePatch_, connectedTrianglePatch_, flatEdgePatch_, flatTrianglePatch_;
  std::vector<uint32_t> vertexPlace_;  // per vertex: the place of one of its triangles in the triangle tree
  std::vector<uint32_t> vertexOrder_;  // the vertices by their place
  // The elements' vertices in their trees' order.
  std::vector<std::pair<uint32_t, uint32_t>> edgeAtPlace_;
  std::vector<std::array<uint32_t, 3>> triangleAtPlace_;
  // The vertex-triangle queries are made for groups of vertices at once: up
  // to kGroupVertices whose places lie in one small subtree of the triangle
  // tree (vertexOrder_[vertexBegin, vertexEnd), their places within
  // [placeFirst, placeFirst + placeCount)), or one vertex without a triangle
  // (placeCount 0).
  struct VertexGroup {
    uint32_t vertexBegin, vertexEnd, placeFirst, placeCount;
  };
  std::vector<VertexGroup> vertexGroups_;
  TriangleColumns triangleColumns_;  // per place of the triangle tree, for the vertex-triangle screen
  // Per place of the triangle and edge trees: its highest ancestor that is a
  // flat patch, -1 if none. Two places are in one flat patch when they have
  // the same such node (a vertex's place: that of its triangle).
  std::vector<int32_t> topFlatNode_, topFlatEdgeNode_, topFlatPlace_, topFlatEdgePlace_;
  std::vector<glm::vec3> triangleNormals_;  // per triangle: its unit normals at the start and the end of the step
  PlaceNormals triangleNormalsByPlace_, edgeNormalsByPlace_;
  std::vector<glm::vec3> nodeNormalSums_, edgeNodeNormalSums_;  // per node of the trees: its normals' sum
  std::vector<uint8_t> alignedNodes_, alignedEdgeNodes_;        // findFlatNodes()'s scratch
  // Per triangle and edge (in their trees' order), and per node of the trees.
  std::vector<NodeMotion> triangleMotions_, edgeMotions_, nodeMotions_, edgeNodeMotions_;
  // Per place of the edge tree, as columns (see EdgeColumns::resize).
  struct EdgeColumns {
    std::vector<uint32_t> v0, v1, edge;
    std::vector<float> midX, midY, midZ, halfX, halfY, halfZ, moveX, moveY, moveZ, spread;
    // The vertices' start positions and moves (vertex v0: index 0, v1: index 1).
    std::array<std::vector<float>, 2> startX, startY, startZ, stepX, stepY, stepZ;
    void resize(size_t places);
    // halfEdge: from the edge's midpoint to its vertex b.
    void set(size_t place, uint32_t e, uint32_t a, uint32_t b, const glm::vec3& mid, const glm::vec3& halfEdge,
             const glm::vec3& meanMove, float moveSpread);
    void setVertices(size_t place, const glm::vec3 (&start)[2], const glm::vec3 (&move)[2]);
    // Bit k set: the edges at places i and first + k share a vertex, or
    // their cheap bound keeps them apart (segmentsApart with the cheap
    // bound's reach).
    unsigned apartOrNeighbours(uint32_t i, uint32_t first, float thickness) const;
    // Bit k set: the edges at places i and first + k pass the exact test's
    // distance conditions (segmentsWithinReach, the same outcome); all set
    // without SSE.
    unsigned withinReach(uint32_t i, uint32_t first, float thickness) const;
  };
  EdgeColumns edgeColumns_;
  bool motionBounds_ = true, exhaustive_ = false;
  std::vector<uint32_t> moved_, checkedVT_, checkedEE_;  // resolve()'s pass clocks
};

}  // namespace mq::cloth
