#pragma once
// A bounding volume hierarchy over primitives given by their boxes (triangles,
// or triangles swept over a time step): built by median splits on the longest
// axis, refitted bottom-up when the primitives move (the topology of a skinned
// body or a cloth never changes). Queries can walk it two levels at a time:
// each inner node's grandchildren's boxes kept side by side, tested at once.

#include <cstdint>
#include <functional>
#include <vector>

#ifdef __SSE2__
#include <immintrin.h>
#endif

#include <glm/glm.hpp>

namespace mq::cloth {

struct Box {
  glm::vec3 min{1e30f}, max{-1e30f};
  void extend(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void extend(const Box& o) {
    min = glm::min(min, o.min);
    max = glm::max(max, o.max);
  }
  // Branch-free (the six comparisons at once): traversals test many boxes
  // whose outcome does not follow a pattern.
  bool overlaps(const Box& o) const {
    return (min.x <= o.max.x) & (o.min.x <= max.x) & (min.y <= o.max.y) & (o.min.y <= max.y) & (min.z <= o.max.z) &
           (o.min.z <= max.z);
  }
};

class AabbTree {
 public:
  // Both return the tree's size: the sum of its nodes' half-perimeters (how
  // loose it has grown since it was built).
  float build(const std::vector<Box>& boxes);
  // New boxes for the same primitives.
  float refit(const std::vector<Box>& boxes);
  // Calls visit(primitive) for every primitive whose box overlaps `box`.
  template <class Visit>
  void query(const Box& box, Visit&& visit) const;
  // The same, but the subtrees of the nodes for which skip(node) is true are
  // not entered.
  template <class Visit, class Skip>
  void query(const Box& box, Visit&& visit, Skip&& skip) const;
  // The same, but visit(k) is given the primitive's place k (see primitive()).
  template <class Visit, class Skip>
  void queryPlaces(const Box& box, Visit&& visit, Skip&& skip) const;
  // The leaves whose box overlaps `box`: visitLeaf(leaf), the node of a
  // leaf (see nodeInfo(), leafOverlaps()). The tree is walked two levels at
  // a time (a node's grandchildren's boxes tested at once), and skip(node)
  // is asked only of those: it may leave out less than with query().
  template <class VisitLeaf, class Skip>
  void queryLeaves(const Box& box, VisitLeaf&& visitLeaf, Skip&& skip) const;
  // queryLeaves() in two parts, for many boxes near each other: the places
  // where the walks for the boxes within `around` part (the first nodes of
  // at most `split` primitives, or leaves, that overlap it and that skip()
  // keeps), then one box's walk from them. A walk from them visits the
  // leaves a walk from the root visits when the first part's skip leaves
  // out no node the second's keeps (it may visit more where a node the
  // second's skip leaves out is above an entry).
  struct Entry {
    int32_t node, grand;  // grand: the node's GrandNode, -1 for a leaf
  };
  template <class Skip>
  void queryEntries(const Box& around, uint32_t split, Skip&& skip, std::vector<Entry>& entries) const;
  template <class VisitLeaf, class Skip>
  void queryLeavesFrom(const std::vector<Entry>& entries, const Box& box, VisitLeaf&& visitLeaf, Skip&& skip) const;
  // Bit k set: the box of the leaf's primitive at place nodeInfo(leaf).first + k overlaps `box`.
  unsigned leafOverlaps(int32_t leaf, const Box& box) const { return overlapMask(leafQuads_[nodes_[leaf].quad], box); }
  // Calls visit(primitive) for the primitives whose box is closer to p than
  // `best`, nearer subtrees first; visit may lower `best` (a nearest-point
  // search: far subtrees are then skipped).
  template <class Visit>
  void nearest(const glm::vec3& p, float& best, Visit&& visit) const;

  // Every unordered pair of distinct primitives whose boxes overlap, once:
  // visit(i, j) from a traversal of the tree against itself, split into
  // independent jobs (at least `minJobs` when the tree is large enough) that
  // may run in parallel; runJob(job, visit) runs one.
  struct PairJob {
    int32_t a, b;  // a == b: the pairs within node a; otherwise between a and b
  };
  // With skipWithin, a node's own pairs are left out wherever skipWithin(node)
  // is true (pass the same to runJob).
  std::vector<PairJob> pairJobs(size_t minJobs, const std::function<bool(int32_t)>& skipWithin = {}) const;
  template <class Visit>
  void runJob(const PairJob& job, Visit&& visit) const;
  // The same, but the pairs within a node for which skipWithin(node) is true
  // are not visited (a part known to hold no pair of interest).
  template <class Visit, class SkipWithin>
  void runJob(const PairJob& job, Visit&& visit, SkipWithin&& skipWithin) const;
  // The same, with the pairs between two nodes for which skipBetween(a, b)
  // is true left out too (nodes whose boxes overlap but whose primitives are
  // known to hold no pair of interest, from data kept alongside the nodes),
  // and visit(i, j) given the primitives' places i, j (primitive(i) is the
  // primitive): data kept in the tree's order is read in sequence.
  template <class Visit, class SkipWithin, class SkipBetween>
  void runJobAtPlaces(const PairJob& job, Visit&& visit, SkipWithin&& skipWithin, SkipBetween&& skipBetween) const;
  // The same pairs, by leaf: visitQuad(i, first, mask) for the places
  // first + k whose bit k is set in mask (first: a leaf's first place, k < 4),
  // so that the caller can test place i against them at once.
  template <class VisitQuad, class SkipWithin, class SkipBetween>
  void runJobInQuads(const PairJob& job, VisitQuad&& visitQuad, SkipWithin&& skipWithin,
                     SkipBetween&& skipBetween) const;

  // The nodes, for data kept alongside them: node 0 is the root, children
  // follow their parent (a reverse sweep is bottom-up), a node covers the
  // primitives primitive(first) .. primitive(first + count - 1) and is a leaf
  // when left < 0.
  struct NodeInfo {
    int32_t left, right;
    uint32_t first, count;
  };
  size_t nodeCount() const { return nodes_.size(); }
  NodeInfo nodeInfo(size_t node) const {
    const Node& n = nodes_[node];
    return {n.left, n.right, n.first, n.count};
  }
  uint32_t primitive(uint32_t k) const { return order_[k]; }
  // The box of the primitive at place k.
  const Box& leafBox(uint32_t k) const { return leafBoxes_[k]; }

  bool empty() const { return nodes_.empty(); }

 private:
  float size() const;  // see build()
  struct Node {
    Box box;
    int32_t left = -1, right = -1;  // children; leaves have left = -1
    uint32_t first = 0, count = 0;  // the node's range in order_
    int32_t quad = -1;              // a leaf's boxes in leafQuads_
    float extent = 0.0f;            // the box's width + height + depth: pairsBetween splits the larger node
    void setBox(const Box& b) {
      box = b;
      const glm::vec3 sides = b.max - b.min;
      extent = sides.x + sides.y + sides.z;
    }
  };
  // A leaf's primitives' boxes as columns (the empty box in the lanes past
  // its count): one primitive is tested against all of them at once.
  struct alignas(16) LeafQuad {
    float minX[4], minY[4], minZ[4], maxX[4], maxY[4], maxZ[4];
  };
  // Bit k set: the leaf's k-th box overlaps `box`.
  static unsigned overlapMask(const LeafQuad& q, const Box& box);
  // An inner node's grandchildren (or a child, where that is a leaf), up
  // to four, their boxes as columns (the empty box in unused lanes).
  struct alignas(64) GrandNode {
    LeafQuad boxes;
    int32_t node[4];   // the nodes in the lanes, -1 if none
    int32_t below[4];  // the GrandNode of a lane's node, -1 for a leaf or none
  };
  int32_t buildGrandNode(int32_t node);
  // queryLeaves()'s walk below a GrandNode; a node for which enter(node,
  // grand) is false is not walked into (enter is asked of inner nodes only).
  template <class VisitLeaf, class Skip, class Enter>
  void walkGrandNodes(int32_t grand, const Box& box, VisitLeaf& visitLeaf, Skip& skip, Enter& enter) const;
  void gatherGrandBoxes();
  int32_t buildNode(uint32_t first, uint32_t count, const std::vector<Box>& boxes);
  // visit: as runJobInQuads()'s visitQuad.
  template <class Visit, class SkipWithin, class SkipBetween>
  void pairsWithin(int32_t node, Visit& visit, SkipWithin& skipWithin, SkipBetween& skipBetween) const;
  template <class Visit, class SkipBetween>
  void pairsBetween(int32_t a, int32_t b, Visit& visit, SkipBetween& skipBetween) const;
  void gatherLeafBoxes(const std::vector<Box>& boxes);

  std::vector<Node> nodes_;
  std::vector<uint32_t> order_;  // primitive indices, leaf ranges
  std::vector<Box> leafBoxes_;   // the primitives' boxes in order_'s order
  std::vector<LeafQuad> leafQuads_;
  std::vector<GrandNode> grandNodes_;  // grandNodes_[0]: the root's, when the root is not a leaf
  std::vector<glm::vec3> centres_;     // build()'s scratch
};

inline unsigned AabbTree::overlapMask(const LeafQuad& q, const Box& box) {
#ifdef __SSE2__
  auto below = [](const float* column, float value) { return _mm_cmple_ps(_mm_loadu_ps(column), _mm_set1_ps(value)); };
  auto above = [](const float* column, float value) { return _mm_cmpge_ps(_mm_loadu_ps(column), _mm_set1_ps(value)); };
  const __m128 x = _mm_and_ps(below(q.minX, box.max.x), above(q.maxX, box.min.x));
  const __m128 y = _mm_and_ps(below(q.minY, box.max.y), above(q.maxY, box.min.y));
  const __m128 z = _mm_and_ps(below(q.minZ, box.max.z), above(q.maxZ, box.min.z));
  return unsigned(_mm_movemask_ps(_mm_and_ps(_mm_and_ps(x, y), z)));
#else
  unsigned mask = 0;
  for (int k = 0; k < 4; ++k)
    mask |= unsigned((q.minX[k] <= box.max.x) & (box.min.x <= q.maxX[k]) & (q.minY[k] <= box.max.y) &
                     (box.min.y <= q.maxY[k]) & (q.minZ[k] <= box.max.z) & (box.min.z <= q.maxZ[k]))
            << k;
  return mask;
#endif
}

inline float squaredDistance(const Box& b, const glm::vec3& p) {
  const glm::vec3 d = glm::max(glm::max(b.min - p, p - b.max), glm::vec3(0.0f));
  return glm::dot(d, d);
}

// Boxes of the triangles of `positions`, grown by `margin`.
std::vector<Box> triangleBoxes(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& triangles,
                               float margin);

template <class Visit>
void AabbTree::query(const Box& box, Visit&& visit) const {
  query(box, visit, [](int32_t) { return false; });
}

template <class Visit, class Skip>
void AabbTree::query(const Box& box, Visit&& visit, Skip&& skip) const {
  queryPlaces(
      box, [&](uint32_t k) { visit(order_[k]); }, skip);
}

template <class Visit, class Skip>
void AabbTree::queryPlaces(const Box& box, Visit&& visit, Skip&& skip) const {
  if (nodes_.empty()) return;
  int32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int32_t index = stack[--top];
    const Node& n = nodes_[index];
    if (!n.box.overlaps(box) || skip(index)) continue;
    if (n.left < 0) {
      for (uint32_t k = n.first; k < n.first + n.count; ++k)
        if (leafBoxes_[k].overlaps(box)) visit(k);
    } else {
      stack[top++] = n.left;
      stack[top++] = n.right;
    }
  }
}

template <class VisitLeaf, class Skip, class Enter>
void AabbTree::walkGrandNodes(int32_t grand, const Box& box, VisitLeaf& visitLeaf, Skip& skip, Enter& enter) const {
  int32_t stack[64];
  int top = 0;
  stack[top++] = grand;
  while (top > 0) {
    const GrandNode& g = grandNodes_[stack[--top]];
    for (unsigned mask = overlapMask(g.boxes, box); mask != 0; mask &= mask - 1) {
      const int lane = __builtin_ctz(mask);
      if (skip(g.node[lane])) continue;
      if (g.below[lane] < 0)
        visitLeaf(g.node[lane]);
      else if (enter(g.node[lane], g.below[lane]))
        stack[top++] = g.below[lane];
    }
  }
}

template <class VisitLeaf, class Skip>
void AabbTree::queryLeaves(const Box& box, VisitLeaf&& visitLeaf, Skip&& skip) const {
  if (nodes_.empty() || !nodes_[0].box.overlaps(box) || skip(0)) return;
  if (nodes_[0].left < 0) return visitLeaf(0);
  auto always = [](int32_t, int32_t) { return true; };
  walkGrandNodes(0, box, visitLeaf, skip, always);
}

template <class Skip>
void AabbTree::queryEntries(const Box& around, uint32_t split, Skip&& skip, std::vector<Entry>& entries) const {
  entries.clear();
  if (nodes_.empty() || !nodes_[0].box.overlaps(around) || skip(0)) return;
  if (nodes_[0].left < 0 || nodes_[0].count <= split) return entries.push_back({0, nodes_[0].left < 0 ? -1 : 0});
  auto leaf = [&](int32_t node) { entries.push_back({node, -1}); };
  auto enter = [&](int32_t node, int32_t grand) {
    if (nodes_[node].count > split) return true;
    entries.push_back({node, grand});
    return false;
  };
  walkGrandNodes(0, around, leaf, skip, enter);
}

template <class VisitLeaf, class Skip>
void AabbTree::queryLeavesFrom(const std::vector<Entry>& entries, const Box& box, VisitLeaf&& visitLeaf,
                               Skip&& skip) const {
  auto always = [](int32_t, int32_t) { return true; };
  for (const Entry& e : entries) {
    if (!nodes_[e.node].box.overlaps(box) || skip(e.node)) continue;
    if (e.grand < 0)
      visitLeaf(e.node);
    else
      walkGrandNodes(e.grand, box, visitLeaf, skip, always);
  }
}

template <class Visit>
void AabbTree::nearest(const glm::vec3& p, float& best, Visit&& visit) const {
  if (nodes_.empty()) return;
  struct Entry {
    int32_t node;
    float distance2;
  };
  Entry stack[64];
  int top = 0;
  stack[top++] = {0, squaredDistance(nodes_[0].box, p)};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.distance2 >= best * best) continue;
    const Node& n = nodes_[e.node];
    if (n.left < 0) {
      for (uint32_t k = n.first; k < n.first + n.count; ++k)
        if (squaredDistance(leafBoxes_[k], p) < best * best) visit(order_[k]);
      continue;
    }
    const float l = squaredDistance(nodes_[n.left].box, p), r = squaredDistance(nodes_[n.right].box, p);
    // The nearer child on top of the stack: visited first.
    if (l <= r) {
      stack[top++] = {n.right, r};
      stack[top++] = {n.left, l};
    } else {
      stack[top++] = {n.left, l};
      stack[top++] = {n.right, r};
    }
  }
}

template <class Visit>
void AabbTree::runJob(const PairJob& job, Visit&& visit) const {
  runJob(job, visit, [](int32_t) { return false; });
}

template <class Visit, class SkipWithin>
void AabbTree::runJob(const PairJob& job, Visit&& visit, SkipWithin&& skipWithin) const {
  runJobAtPlaces(
      job, [&](uint32_t i, uint32_t j) { visit(order_[i], order_[j]); }, skipWithin,
      [](int32_t, int32_t) { return false; });
}

template <class Visit, class SkipWithin, class SkipBetween>
void AabbTree::runJobAtPlaces(const PairJob& job, Visit&& visit, SkipWithin&& skipWithin,
                              SkipBetween&& skipBetween) const {
  runJobInQuads(
      job,
      [&](uint32_t i, uint32_t first, unsigned mask) {
        for (; mask != 0; mask &= mask - 1) visit(i, first + uint32_t(__builtin_ctz(mask)));
      },
      skipWithin, skipBetween);
}

template <class VisitQuad, class SkipWithin, class SkipBetween>
void AabbTree::runJobInQuads(const PairJob& job, VisitQuad&& visitQuad, SkipWithin&& skipWithin,
                             SkipBetween&& skipBetween) const {
  if (job.a == job.b)
    pairsWithin(job.a, visitQuad, skipWithin, skipBetween);
  else
    pairsBetween(job.a, job.b, visitQuad, skipBetween);
}

template <class Visit, class SkipWithin, class SkipBetween>
void AabbTree::pairsWithin(int32_t node, Visit& visit, SkipWithin& skipWithin, SkipBetween& skipBetween) const {
  if (skipWithin(node)) return;
  const Node& n = nodes_[node];
  if (n.left >= 0) {
    pairsWithin(n.left, visit, skipWithin, skipBetween);
    pairsWithin(n.right, visit, skipWithin, skipBetween);
    pairsBetween(n.left, n.right, visit, skipBetween);
    return;
  }
  const LeafQuad& quad = leafQuads_[n.quad];
  for (uint32_t k = 0; k + 1 < n.count; ++k) {
    const unsigned after = ~((2u << k) - 1);  // the places past i
    const unsigned mask = overlapMask(quad, leafBoxes_[n.first + k]) & after;
    if (mask != 0) visit(n.first + k, n.first, mask);
  }
}

template <class Visit, class SkipBetween>
void AabbTree::pairsBetween(int32_t a, int32_t b, Visit& visit, SkipBetween& skipBetween) const {
  if (!nodes_[a].box.overlaps(nodes_[b].box)) return;
  // Depth first over a stack of node pairs whose boxes overlap (tested
  // before they are pushed), not by recursion: the pairs are the calls'.
  // Each pair pops one and pushes at most two: the stack holds at most the
  // two nodes' depths plus one.
  struct NodePair {
    int32_t a, b;
  };
  NodePair stack[128];
  int top = 0;
  stack[top++] = {a, b};
  while (top > 0) {
    const NodePair pair = stack[--top];
    const Node &na = nodes_[pair.a], &nb = nodes_[pair.b];
    if (skipBetween(pair.a, pair.b)) continue;
    if (na.left < 0 && nb.left < 0) {
      const LeafQuad& quad = leafQuads_[nb.quad];
      for (uint32_t i = na.first; i < na.first + na.count; ++i)
        if (const unsigned mask = overlapMask(quad, leafBoxes_[i])) visit(i, nb.first, mask);
      continue;
    }
    // Split the node that is not a leaf (the larger when neither is); a
    // child whose box misses the other node's is not pushed. Branch-free
    // (each child written, kept when it overlaps): the outcomes follow no
    // pattern. The right child first: the left is visited first.
    const bool splitA = nb.left < 0 || (na.left >= 0 && na.extent >= nb.extent);
    const Node& split = splitA ? na : nb;
    const Box& other = splitA ? nb.box : na.box;
    for (const int32_t child : {split.right, split.left}) {
      const Node& c = nodes_[child];
      stack[top] = splitA ? NodePair{child, pair.b} : NodePair{pair.a, child};
      top += int(c.box.overlaps(other));
      // What the pair reads once popped, fetched now (the walk waits on
      // memory): a leaf's boxes, or an inner node's right child (the left
      // one follows it in nodes_).
      __builtin_prefetch(c.left < 0 ? static_cast<const void*>(&leafQuads_[c.quad]) : &nodes_[c.right]);
    }
  }
}

}  // namespace mq::cloth
