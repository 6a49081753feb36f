#pragma once
// A 4-wide bounding volume hierarchy for the body collider's queries. Each
// node holds its four children's boxes side by side (rows of four x, y, z
// minima and maxima), so one visit tests all four at once (SSE on x86-64),
// and a child is either a node or a single primitive, so there are no leaf
// lists to walk. Built once by median splits, refitted every move (the
// topology of a skinned body never changes). Half the depth of the binary
// AabbTree, and the boxes a visit compares are side by side in memory.

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "sim/cloth/collision/aabb_tree.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define MQ_WIDE_TREE_SSE 1
#endif

namespace mq::cloth {

class WideTree {
 public:
  // build() and refit() return the sum of the half-perimeters of the boxes
  // of the tree's nodes: grown much since the build, the tree has gone loose
  // (a cloth's tree, refitted as the cloth moves, is then rebuilt).
  float build(const std::vector<Box>& boxes);
  // New boxes for the same primitives.
  float refit(const std::vector<Box>& boxes);
  // Calls visit(primitive) for every primitive whose box overlaps `box`.
  template <class Visit>
  void query(const Box& box, Visit&& visit) const;
  // Calls visit(primitive) for the primitives whose box is no farther from p
  // than sqrt(best2), nearer boxes first; visit may lower the squared bound
  // `best2` (a nearest-point search: farther boxes are then skipped). Boxes
  // at the bound are visited, so a search can break ties by index.
  template <class Visit>
  void nearest(const glm::vec3& p, float& best2, Visit&& visit) const;
  // nearest(), with a node's primitives handed over together (for a test of
  // four at once): visitSlots(node, slots) with the bits of `slots` the
  // node's slots holding primitives whose boxes are within the bound; the
  // node's child nodes are visited after, nearer ones first.
  // prefetch(node) is called for the nodes put on the stack below the top
  // (visited later: their data can be on its way meanwhile). `passed2`, if
  // given, gets the least squared distance of the boxes passed over as
  // beyond the bound (so the primitives not handed to visitSlots are no
  // nearer than its root; not kept when the caller has a primitive within
  // the bound already, for the work it costs).
  template <class VisitSlots, class Prefetch>
  void nearestByNode(const glm::vec3& p, float& best2, VisitSlots&& visitSlots, Prefetch&& prefetch,
                     float* passed2) const;
  // Starts loading a node's boxes into the cache.
  void prefetchNode(int32_t node) const {
#ifdef MQ_WIDE_TREE_SSE
    const char* at = reinterpret_cast<const char*>(&nodes_[node]);
    _mm_prefetch(at, _MM_HINT_T0);
    _mm_prefetch(at + 64, _MM_HINT_T0);
#else
    (void)node;
#endif
  }
  // The primitive in slot `slot` of node `node`, or -1 (a child node or empty).
  int32_t primitiveAt(uint32_t node, int slot) const {
    const int32_t c = nodes_[node].child[slot];
    return c >= 0 || c == kNoChild ? -1 : ~c;
  }

  bool empty() const { return nodes_.empty(); }
  size_t nodeCount() const { return nodes_.size(); }

 private:
  static constexpr int32_t kNoChild = INT32_MIN;  // an empty slot (its box is empty)
  // Two whole cache lines.
  struct alignas(64) Node {
    float minX[4], minY[4], minZ[4], maxX[4], maxY[4], maxZ[4];
    int32_t child[4];                           // >= 0: a node; kNoChild: empty; otherwise primitive ~child
    int32_t nodeSlots = 0, primitiveSlots = 0;  // bit k: child[k] is a node / a primitive
  };
  int32_t buildNode(std::vector<uint32_t>& order, uint32_t first, uint32_t count,
                    const std::vector<glm::vec3>& centres);
  // Squared distances from p to the four boxes of n (huge for empty slots).
  static void squaredDistances(const Node& n, const glm::vec3& p, float out[4]);
  // Bit k set when d2[k] <= bound.
  static int withinMask(const float d2[4], float bound);
  // Lowers least[k] to d2[k] where that is above bound (four lanes, their
  // least taken once at the end of a search; empty slots' d2 are huge).
  static void lowerToBeyond(const float d2[4], float bound, float least[4]);
  // Bit k set when the box of slot k overlaps `box`.
  static int overlapMask(const Node& n, const Box& box);

  std::vector<Node> nodes_;  // children after their parent (root first)
};

inline void WideTree::squaredDistances(const Node& n, const glm::vec3& p, float out[4]) {
#ifdef MQ_WIDE_TREE_SSE
  const __m128 zero = _mm_setzero_ps();
  const __m128 px = _mm_set1_ps(p.x), py = _mm_set1_ps(p.y), pz = _mm_set1_ps(p.z);
  const __m128 dx =
      _mm_max_ps(_mm_max_ps(_mm_sub_ps(_mm_load_ps(n.minX), px), _mm_sub_ps(px, _mm_load_ps(n.maxX))), zero);
  const __m128 dy =
      _mm_max_ps(_mm_max_ps(_mm_sub_ps(_mm_load_ps(n.minY), py), _mm_sub_ps(py, _mm_load_ps(n.maxY))), zero);
  const __m128 dz =
      _mm_max_ps(_mm_max_ps(_mm_sub_ps(_mm_load_ps(n.minZ), pz), _mm_sub_ps(pz, _mm_load_ps(n.maxZ))), zero);
  _mm_storeu_ps(out, _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz)));
#else
  for (int k = 0; k < 4; ++k) {
    const float dx = std::max(std::max(n.minX[k] - p.x, p.x - n.maxX[k]), 0.0f);
    const float dy = std::max(std::max(n.minY[k] - p.y, p.y - n.maxY[k]), 0.0f);
    const float dz = std::max(std::max(n.minZ[k] - p.z, p.z - n.maxZ[k]), 0.0f);
    out[k] = dx * dx + dy * dy + dz * dz;
  }
#endif
}

inline int WideTree::withinMask(const float d2[4], float bound) {
#ifdef MQ_WIDE_TREE_SSE
  return _mm_movemask_ps(_mm_cmple_ps(_mm_loadu_ps(d2), _mm_set1_ps(bound)));
#else
  int mask = 0;
  for (int k = 0; k < 4; ++k) mask |= int(d2[k] <= bound) << k;
  return mask;
#endif
}

inline void WideTree::lowerToBeyond(const float d2[4], float bound, float least[4]) {
#ifdef MQ_WIDE_TREE_SSE
  // Within the bound: max(d2, huge); beyond: max(d2, 0) = d2.
  const __m128 d = _mm_loadu_ps(d2);
  const __m128 beyond = _mm_max_ps(d, _mm_and_ps(_mm_cmple_ps(d, _mm_set1_ps(bound)), _mm_set1_ps(1e30f)));
  _mm_storeu_ps(least, _mm_min_ps(_mm_loadu_ps(least), beyond));
#else
  for (int k = 0; k < 4; ++k)
    if (d2[k] > bound) least[k] = std::min(least[k], d2[k]);
#endif
}

inline int WideTree::overlapMask(const Node& n, const Box& b) {
#ifdef MQ_WIDE_TREE_SSE
  __m128 m = _mm_and_ps(_mm_cmple_ps(_mm_load_ps(n.minX), _mm_set1_ps(b.max.x)),
                        _mm_cmple_ps(_mm_set1_ps(b.min.x), _mm_load_ps(n.maxX)));
  m = _mm_and_ps(m, _mm_and_ps(_mm_cmple_ps(_mm_load_ps(n.minY), _mm_set1_ps(b.max.y)),
                               _mm_cmple_ps(_mm_set1_ps(b.min.y), _mm_load_ps(n.maxY))));
  m = _mm_and_ps(m, _mm_and_ps(_mm_cmple_ps(_mm_load_ps(n.minZ), _mm_set1_ps(b.max.z)),
                               _mm_cmple_ps(_mm_set1_ps(b.min.z), _mm_load_ps(n.maxZ))));
  return _mm_movemask_ps(m);
#else
  int mask = 0;
  for (int k = 0; k < 4; ++k)
    if (n.minX[k] <= b.max.x && b.min.x <= n.maxX[k] && n.minY[k] <= b.max.y && b.min.y <= n.maxY[k] &&
        n.minZ[k] <= b.max.z && b.min.z <= n.maxZ[k])
      mask |= 1 << k;
  return mask;
#endif
}

template <class Visit>
void WideTree::query(const Box& box, Visit&& visit) const {
  if (nodes_.empty()) return;
  int32_t stack[256];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    const int mask = overlapMask(n, box);
    for (int k = 0; k < 4; ++k) {
      if (!(mask & (1 << k))) continue;
      if (n.child[k] >= 0)
        stack[top++] = n.child[k];
      else
        visit(uint32_t(~n.child[k]));
    }
  }
}

template <class Visit>
void WideTree::nearest(const glm::vec3& p, float& best2, Visit&& visit) const {
  if (nodes_.empty()) return;
  struct Entry {
    int32_t child;
    float distance2;
  };
  Entry stack[256];
  int top = 0;
  stack[top++] = {0, 0.0f};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.distance2 > best2) continue;
    if (e.child < 0) {
      visit(uint32_t(~e.child));
      continue;
    }
    const Node& n = nodes_[e.child];
    float d2[4];
    squaredDistances(n, p, d2);
    // The children within the bound, farthest first: the nearest ends on top.
    Entry near[4];
    int count = 0;
    for (int k = 0; k < 4; ++k) {
      if (!(d2[k] <= best2)) continue;
      int j = count++;
      for (; j > 0 && near[j - 1].distance2 < d2[k]; --j) near[j] = near[j - 1];
      near[j] = {n.child[k], d2[k]};
    }
    for (int j = 0; j < count; ++j) stack[top++] = near[j];
  }
}

template <class VisitSlots, class Prefetch>
void WideTree::nearestByNode(const glm::vec3& p, float& best2, VisitSlots&& visitSlots, Prefetch&& prefetch,
                             float* passed2) const {
  float passed[4] = {1e30f, 1e30f, 1e30f, 1e30f};
  if (passed2) *passed2 = 1e30f;
  if (nodes_.empty()) return;
  // A search is a chain of dependent loads, a node's address and then its
  // boxes: so few branches (masks for the slots within the bound; only the
  // nearest child node put on top, the others in slot order, which with a
  // bound from a hint hardly matters), and the stack's nodes and distances
  // apart (read back as written, without a stalled store-to-load forward).
  int32_t stackNode[256];
  float stackDistance2[256];
  int top = 0;
  stackNode[0] = 0, stackDistance2[0] = 0.0f, ++top;
  while (top > 0) {
    --top;
    if (stackDistance2[top] > best2) {
      if (passed2) *passed2 = std::min(*passed2, stackDistance2[top]);
      continue;
    }
    const int32_t index = stackNode[top];
    const Node& n = nodes_[index];
    float d2[4];
    squaredDistances(n, p, d2);
    const int nearSlots = withinMask(d2, best2) & n.primitiveSlots;
    if (nearSlots) visitSlots(uint32_t(index), nearSlots);
    const int children = withinMask(d2, best2) & n.nodeSlots;  // the bound may be lower now
    if (passed2) lowerToBeyond(d2, best2, passed);
    if (!children) continue;
    int nearest = __builtin_ctz(unsigned(children));
    for (int k = nearest + 1; k < 4; ++k)
      if ((children >> k) & 1 && d2[k] < d2[nearest]) nearest = k;
    for (int k = 0; k < 4; ++k) {
      stackNode[top] = n.child[k], stackDistance2[top] = d2[k];
      if ((children >> k) & (k != nearest)) prefetch(n.child[k]);
      top += (children >> k) & (k != nearest);
    }
    stackNode[top] = n.child[nearest], stackDistance2[top] = d2[nearest], ++top;
  }
  if (passed2) *passed2 = std::min(std::min(*passed2, std::min(passed[0], passed[1])), std::min(passed[2], passed[3]));
}

}  // namespace mq::cloth
