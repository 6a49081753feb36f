#include "sim/cloth/collision/self_collision.h"

#include <algorithm>
#include <cmath>
#include <map>

#ifdef __SSE2__
#include <immintrin.h>
#endif

#include "sim/cloth/collision/proximity.h"
#include "sim/cloth/collision/segment_reach.h"
#include "core/util/thread_pool.h"

namespace mq::cloth {

namespace {

constexpr size_t kBlocks = 64;
#ifdef __SSE2__
constexpr bool kScreened = true;  // EdgeColumns::apartOrNeighbours screens the edge pairs
#else
constexpr bool kScreened = false;
#endif

bool sharesVertex(uint32_t a0, uint32_t a1, uint32_t b0, uint32_t b1) {
  return a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1;
}

constexpr uint32_t kNoTriangle = UINT32_MAX;
constexpr float kFlatCosine = 0.7071f;  // cos 45 degrees: a patch's normals within it of its axis are flat

}  // namespace

float smallestAlignment(const float* x, const float* y, const float* z, size_t count, const glm::vec3& axis) {
  float smallest = 1e30f;
  size_t k = 0;
#ifdef __SSE2__
  const __m128 ax = _mm_set1_ps(axis.x), ay = _mm_set1_ps(axis.y), az = _mm_set1_ps(axis.z);
  __m128 lanes = _mm_set1_ps(smallest);
  for (; k + 4 <= count; k += 4) {
    const __m128 dot = _mm_add_ps(_mm_add_ps(_mm_mul_ps(ax, _mm_loadu_ps(x + k)), _mm_mul_ps(ay, _mm_loadu_ps(y + k))),
                                  _mm_mul_ps(az, _mm_loadu_ps(z + k)));
    lanes = _mm_min_ps(lanes, dot);
  }
  alignas(16) float four[4];
  _mm_store_ps(four, lanes);
  smallest = std::min(std::min(four[0], four[1]), std::min(four[2], four[3]));
#endif
  for (; k < count; ++k) smallest = std::min(smallest, axis.x * x[k] + axis.y * y[k] + axis.z * z[k]);
  return smallest;
}

namespace {

// A triangle's unit normal; zero when it has collapsed (no patch holding it is flat).
glm::vec3 unitNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float l = glm::length(n);
  return l > 1e-12f ? n / l : glm::vec3(0.0f);
}

// Runs body(begin, end) over [0, count) in chunks of `chunk`, in parallel.
template <class Body>
void inChunks(size_t count, size_t chunk, Body&& body) {
  ThreadPool::shared().parallelBlocks((count + chunk - 1) / chunk,
                                      [&](size_t b) { body(b * chunk, std::min(count, (b + 1) * chunk)); });
}

// Per node of `tree`: whether its primitives are connected through shared
// vertices (a union-find over each node's primitives; vertices(primitive)
// gives a primitive's vertices).
template <class Vertices>
std::vector<uint8_t> connectedNodes(const AabbTree& tree, size_t vertexCount, Vertices&& vertices) {
  std::vector<uint8_t> connected(tree.nodeCount(), 0);
  std::vector<uint32_t> parent(vertexCount), seenAt(vertexCount, UINT32_MAX);
  auto root = [&](uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (size_t i = 0; i < connected.size(); ++i) {
    const AabbTree::NodeInfo node = tree.nodeInfo(i);
    size_t components = 0;
    for (uint32_t k = node.first; k < node.first + node.count; ++k) {
      const auto corners = vertices(tree.primitive(k));
      for (uint32_t v : corners)
        if (seenAt[v] != i) seenAt[v] = uint32_t(i), parent[v] = v, ++components;
      for (size_t c = 1; c < corners.size(); ++c) {
        const uint32_t r0 = root(corners[0]), rc = root(corners[c]);
        if (r0 != rc) parent[r0] = rc, --components;
      }
    }
    connected[i] = components == 1;
  }
  return connected;
}

// Per node of `tree`: connected, and the normals of its places (`normals`:
// perPlace of them at each place) all within kFlatCosine of their mean
// (their sum, kept per node in `sums`). Bottom-up; the normals of a node are
// only compared with their mean when its children's are with theirs
// (`aligned`, scratch): a part spread wider than 45 degrees around its own
// mean is rarely within 45 degrees of a larger part's.
void findFlatNodes(const AabbTree& tree, const std::vector<uint8_t>& connected, const PlaceNormals& normals,
                   std::vector<glm::vec3>& sums, std::vector<uint8_t>& aligned, std::vector<uint8_t>& flat) {
  const size_t nodes = tree.nodeCount();
  const uint32_t per = normals.perPlace;
  sums.resize(nodes);
  aligned.assign(nodes, 0);
  flat.assign(nodes, 0);
  for (size_t i = nodes; i-- > 0;) {
    const AabbTree::NodeInfo node = tree.nodeInfo(i);
    const size_t first = size_t(node.first) * per, count = size_t(node.count) * per;
    bool candidate = true;
    if (node.left >= 0) {
      sums[i] = sums[node.left] + sums[node.right];
      candidate = aligned[node.left] && aligned[node.right];
    } else {
      glm::vec3 sum(0.0f);
      for (size_t k = first; k < first + count; ++k) sum += glm::vec3(normals.x[k], normals.y[k], normals.z[k]);
      sums[i] = sum;
    }
    const float length = glm::length(sums[i]);
    if (!candidate || !(length > 1e-6f)) continue;
    aligned[i] = smallestAlignment(&normals.x[first], &normals.y[first], &normals.z[first], count,
                                   sums[i] / length) >= kFlatCosine;
    flat[i] = aligned[i] && connected[i];
  }
}

// Per place of `tree`: the highest node over it (or itself) that is `flat`,
// -1 if none. Two places lie in one flat node when theirs is the same node.
// Top-down: children follow their parent (topNode: per node, scratch).
void findTopFlatPlaces(const AabbTree& tree, const std::vector<uint8_t>& flat, std::vector<int32_t>& topNode,
                       std::vector<int32_t>& places) {
  topNode.assign(tree.nodeCount(), -1);
  places.resize(tree.empty() ? 0 : tree.nodeInfo(0).count);
  for (size_t i = 0; i < topNode.size(); ++i) {
    const AabbTree::NodeInfo node = tree.nodeInfo(i);
    if (topNode[i] < 0 && flat[i]) topNode[i] = int32_t(i);
    if (node.left >= 0)
      topNode[node.left] = topNode[node.right] = topNode[i];
    else
      std::fill_n(places.begin() + node.first, node.count, topNode[i]);
  }
}

// Per place of `tree`: the value of the primitive there (in parallel).
template <class T>
std::vector<T> placeOrdered(const AabbTree& tree, const std::vector<T>& byPrimitive) {
  std::vector<T> byPlace(byPrimitive.size());
  inChunks(byPlace.size(), 4096, [&](size_t k0, size_t k1) {
    for (size_t k = k0; k < k1; ++k) byPlace[k] = byPrimitive[tree.primitive(uint32_t(k))];
  });
  return byPlace;
}

// Grows m to hold o (row by row).
inline void extend(NodeMotion& m, const NodeMotion& o) {
#ifdef __SSE2__
  float* rows = &m.startMin.x;
  const float* other = &o.startMin.x;
  for (int r = 0; r < 16; r += 8) {
    _mm_store_ps(rows + r, _mm_min_ps(_mm_load_ps(rows + r), _mm_load_ps(other + r)));
    _mm_store_ps(rows + r + 4, _mm_max_ps(_mm_load_ps(rows + r + 4), _mm_load_ps(other + r + 4)));
  }
#else
  m.startMin = glm::min(m.startMin, o.startMin), m.startMax = glm::max(m.startMax, o.startMax);
  m.moveMin = glm::min(m.moveMin, o.moveMin), m.moveMax = glm::max(m.moveMax, o.moveMax);
#endif
}
// A vertex's motion: where it starts and how it moves.
inline NodeMotion pointMotion(const glm::vec3& start, const glm::vec3& move) {
  NodeMotion m;
  m.startMin = m.startMax = glm::vec4(start, 0.0f);
  m.moveMin = m.moveMax = glm::vec4(move, 0.0f);
  return m;
}

// Whether elements whose vertices start within `gap` of each other and
// whose moves differ by up to `farthest` (both squared) can pass the exact
// test dist(x0) <= thickness + closing. Slightly generous, so that rounding
// never drops a pair the exact test keeps.
inline bool withinReach(float gap2, float farthest2, float thickness) {
  if (gap2 <= thickness * thickness) return true;
  return std::sqrt(gap2) <= 1.001f * (thickness + std::sqrt(farthest2)) + 1e-6f;
}
// Whether two nodes' elements can pass it: their start boxes are within the
// thickness plus the largest difference of two of their moves (four lanes at
// a time, the fourth zero).
#ifdef __SSE2__
inline bool withinReach(__m128 aStartMin, __m128 aStartMax, __m128 aMoveMin, __m128 aMoveMax, __m128 bStartMin,
                        __m128 bStartMax, __m128 bMoveMin, __m128 bMoveMax, float thickness) {
  const __m128 zero = _mm_setzero_ps(), sign = _mm_set1_ps(-0.0f);
  const __m128 gap = _mm_max_ps(_mm_max_ps(_mm_sub_ps(aStartMin, bStartMax), _mm_sub_ps(bStartMin, aStartMax)), zero);
  const __m128 far = _mm_max_ps(_mm_andnot_ps(sign, _mm_sub_ps(aMoveMax, bMoveMin)),
                                _mm_andnot_ps(sign, _mm_sub_ps(bMoveMax, aMoveMin)));
  // Horizontal sums of the squares: gap2 in lane 0, far2 in lane 2 of the pair.
  const __m128 g2 = _mm_mul_ps(gap, gap), f2 = _mm_mul_ps(far, far);
  const __m128 s1 = _mm_add_ps(_mm_unpacklo_ps(g2, f2), _mm_unpackhi_ps(g2, f2));  // g0+g2 f0+f2 g1+g3 f1+f3
  const __m128 s2 = _mm_add_ps(s1, _mm_movehl_ps(s1, s1));                         // gap2 far2 . .
  return withinReach(_mm_cvtss_f32(s2), _mm_cvtss_f32(_mm_shuffle_ps(s2, s2, 1)), thickness);
}
inline __m128 row(const glm::vec4& v) { return _mm_load_ps(&v.x); }
// A point as a row, built in registers (a NodeMotion built on the stack and
// read back at once stalls on the store).
inline __m128 row(const glm::vec3& p) { return _mm_setr_ps(p.x, p.y, p.z, 0.0f); }
#endif

// The box of an element's vertices at the start of the step (and at its end
// when `end` is given) grown by `grow`: the box Box::extend makes, in registers.
template <size_t N>
Box grownBox(const std::array<uint32_t, N>& vertices, const std::vector<glm::vec3>& start,
             const std::vector<glm::vec3>* end, float grow) {
#ifdef __SSE2__
  __m128 lo = row(start[vertices[0]]), hi = lo;
  for (uint32_t v : vertices) {
    const __m128 p = row(start[v]);
    lo = _mm_min_ps(lo, p), hi = _mm_max_ps(hi, p);
    if (end) {
      const __m128 q = row((*end)[v]);
      lo = _mm_min_ps(lo, q), hi = _mm_max_ps(hi, q);
    }
  }
  const __m128 g = _mm_set1_ps(grow);
  alignas(16) float low[4], high[4];
  _mm_store_ps(low, _mm_sub_ps(lo, g)), _mm_store_ps(high, _mm_add_ps(hi, g));
  return Box{{low[0], low[1], low[2]}, {high[0], high[1], high[2]}};
#else
  Box b;
  for (uint32_t v : vertices) {
    b.extend(start[v]);
    if (end) b.extend((*end)[v]);
  }
  b.min -= glm::vec3(grow);
  b.max += glm::vec3(grow);
  return b;
#endif
}
inline bool withinReach(const NodeMotion& a, const NodeMotion& b, float thickness) {
#ifdef __SSE2__
  return withinReach(row(a.startMin), row(a.startMax), row(a.moveMin), row(a.moveMax), row(b.startMin),
                     row(b.startMax), row(b.moveMin), row(b.moveMax), thickness);
#else
  const glm::vec4 gap = glm::max(glm::max(a.startMin - b.startMax, b.startMin - a.startMax), glm::vec4(0.0f));
  const glm::vec4 far = glm::max(glm::abs(a.moveMax - b.moveMin), glm::abs(b.moveMax - a.moveMin));
  return withinReach(glm::dot(gap, gap), glm::dot(far, far), thickness);
#endif
}
// The same for a node's elements and a vertex.
inline bool withinReach(const NodeMotion& a, const glm::vec3& start, const glm::vec3& move, float thickness) {
#ifdef __SSE2__
  const __m128 p = row(start), d = row(move);
  return withinReach(row(a.startMin), row(a.startMax), row(a.moveMin), row(a.moveMax), p, p, d, d, thickness);
#else
  return withinReach(a, pointMotion(start, move), thickness);
#endif
}

// Per element (in the tree's order) of `tree`: the box of its vertices at
// the start of the step and the box of their moves (vertices(primitive)
// gives a primitive's vertices), in parallel.
template <class Vertices>
void findElementMotions(const AabbTree& tree, Vertices&& vertices, const std::vector<glm::vec3>& x0,
                        const std::vector<glm::vec3>& move, std::vector<NodeMotion>& elements) {
  elements.resize(tree.nodeCount() == 0 ? 0 : tree.nodeInfo(0).count);
  inChunks(elements.size(), 2048, [&](size_t k0, size_t k1) {
    for (size_t k = k0; k < k1; ++k) {
      NodeMotion& m = elements[k];
      m = {};
#ifdef __SSE2__
      // In registers (see row()).
      __m128 startMin = row(m.startMin), startMax = row(m.startMax), moveMin = row(m.moveMin), moveMax = row(m.moveMax);
      for (uint32_t v : vertices(tree.primitive(uint32_t(k)))) {
        const __m128 p = row(x0[v]), d = row(move[v]);
        startMin = _mm_min_ps(startMin, p), startMax = _mm_max_ps(startMax, p);
        moveMin = _mm_min_ps(moveMin, d), moveMax = _mm_max_ps(moveMax, d);
      }
      _mm_store_ps(&m.startMin.x, startMin), _mm_store_ps(&m.startMax.x, startMax);
      _mm_store_ps(&m.moveMin.x, moveMin), _mm_store_ps(&m.moveMax.x, moveMax);
#else
      for (uint32_t v : vertices(tree.primitive(uint32_t(k)))) extend(m, pointMotion(x0[v], move[v]));
#endif
    }
  });
}

// The same per node of `tree`, bottom-up from its elements'.
void findNodeMotions(const AabbTree& tree, const std::vector<NodeMotion>& elements, std::vector<NodeMotion>& motions) {
  motions.resize(tree.nodeCount());
  for (size_t i = motions.size(); i-- > 0;) {
    const AabbTree::NodeInfo node = tree.nodeInfo(i);
    NodeMotion& m = motions[i];
    if (node.left >= 0) {
      m = motions[node.left];
      extend(m, motions[node.right]);
    } else {
      m = elements[node.first];
      for (uint32_t k = node.first + 1; k < node.first + node.count; ++k) extend(m, elements[k]);
    }
  }
}

// Runs body(item, outBlock) over [0, count) in fixed blocks, in parallel, and
// concatenates the blocks' outputs in order: deterministic.
template <class T, class Body>
std::vector<T> collectInBlocks(size_t count, Body&& body) {
  std::vector<std::vector<T>> blocks(kBlocks);
  const size_t size = (count + kBlocks - 1) / kBlocks;
  ThreadPool::shared().parallelBlocks(kBlocks, [&](size_t b) {
    for (size_t i = b * size; i < std::min(count, (b + 1) * size); ++i) body(i, blocks[b]);
  });
  size_t total = 0;
  for (const auto& b : blocks) total += b.size();
  std::vector<T> all;
  all.reserve(total);
  for (auto& b : blocks) all.insert(all.end(), b.begin(), b.end());
  return all;
}

}  // namespace

// The edges' vertices and cheap bounds (see findCandidates) by place in the
// edge tree, as columns padded by three places: four places from any one
// are read at once.
void SelfCollision::EdgeColumns::resize(size_t places) {
  for (std::vector<uint32_t>* c : {&v0, &v1, &edge}) c->resize(places + 3, UINT32_MAX);
  for (std::vector<float>* c : {&midX, &midY, &midZ, &halfX, &halfY, &halfZ, &moveX, &moveY, &moveZ, &spread})
    c->resize(places + 3, 0.0f);
  for (int end = 0; end < 2; ++end)
    for (std::vector<float>* c : {&startX[end], &startY[end], &startZ[end], &stepX[end], &stepY[end], &stepZ[end]})
      c->resize(places + 3, 0.0f);
}

void SelfCollision::EdgeColumns::set(size_t k, uint32_t e, uint32_t a, uint32_t b, const glm::vec3& mid,
                                     const glm::vec3& halfEdge, const glm::vec3& meanMove, float moveSpread) {
  edge[k] = e, v0[k] = a, v1[k] = b;
  midX[k] = mid.x, midY[k] = mid.y, midZ[k] = mid.z;
  halfX[k] = halfEdge.x, halfY[k] = halfEdge.y, halfZ[k] = halfEdge.z;
  moveX[k] = meanMove.x, moveY[k] = meanMove.y, moveZ[k] = meanMove.z, spread[k] = moveSpread;
}

void SelfCollision::EdgeColumns::setVertices(size_t k, const glm::vec3 (&start)[2], const glm::vec3 (&move)[2]) {
  for (int end = 0; end < 2; ++end) {
    startX[end][k] = start[end].x, startY[end][k] = start[end].y, startZ[end][k] = start[end].z;
    stepX[end][k] = move[end].x, stepY[end][k] = move[end].y, stepZ[end][k] = move[end].z;
  }
}

inline unsigned SelfCollision::EdgeColumns::withinReach(uint32_t i, uint32_t first, float thickness) const {
#ifdef MQ_SEGMENT_REACH_SSE
  auto own = [&](const std::vector<float>& c) { return _mm_set1_ps(c[i]); };
  auto column = [&](const std::vector<float>& c) { return _mm_loadu_ps(&c[first]); };
  // The exact test takes the edge of lower index first: per lane, the own
  // edge or the other's.
  const __m128 ownFirst = _mm_castsi128_ps(_mm_cmplt_epi32(
      _mm_set1_epi32(int(edge[i])), _mm_loadu_si128(reinterpret_cast<const __m128i*>(&edge[first]))));
  auto pick = [&](const std::vector<float>& c, bool firstEdge) {
    const __m128 a = own(c), b = column(c);
    return firstEdge ? _mm_or_ps(_mm_and_ps(ownFirst, a), _mm_andnot_ps(ownFirst, b))
                     : _mm_or_ps(_mm_and_ps(ownFirst, b), _mm_andnot_ps(ownFirst, a));
  };
  auto point = [&](int end, bool firstEdge) {
    return Vec3x4{pick(startX[end], firstEdge), pick(startY[end], firstEdge), pick(startZ[end], firstEdge)};
  };
  // The largest difference of the two edges' vertices' moves (the same
  // either way round: a difference's negation is exact).
  __m128 worst = _mm_setzero_ps();
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const __m128 dx = _mm_sub_ps(own(stepX[a]), column(stepX[b])), dy = _mm_sub_ps(own(stepY[a]), column(stepY[b]));
      const __m128 dz = _mm_sub_ps(own(stepZ[a]), column(stepZ[b]));
      worst = _mm_max_ps(worst, _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz)));
    }
  const __m128 reach = _mm_add_ps(_mm_set1_ps(thickness), _mm_sqrt_ps(worst));
  return segmentsWithinReach(point(0, true), point(1, true), point(0, false), point(1, false), reach);
#else
  (void)i, (void)first, (void)thickness;
  return 0xFu;  // testEdgeEdge tests them one by one
#endif
}

inline unsigned SelfCollision::EdgeColumns::apartOrNeighbours(uint32_t i, uint32_t first, float thickness) const {
#ifdef __SSE2__
  auto column = [&](const std::vector<float>& c) { return _mm_loadu_ps(&c[first]); };
  auto own = [&](const std::vector<float>& c) { return _mm_set1_ps(c[i]); };
  auto offset = [&](const std::vector<float>& x, const std::vector<float>& y, const std::vector<float>& z) {
    return Vec3x4{_mm_sub_ps(own(x), column(x)), _mm_sub_ps(own(y), column(y)), _mm_sub_ps(own(z), column(z))};
  };
  auto length = [&](const Vec3x4& d) {
    return _mm_sqrt_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(d.x, d.x), _mm_mul_ps(d.y, d.y)), _mm_mul_ps(d.z, d.z)));
  };
  const __m128i a0 = _mm_set1_epi32(int(v0[i])), a1 = _mm_set1_epi32(int(v1[i]));
  const __m128i b0 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&v0[first]));
  const __m128i b1 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&v1[first]));
  const __m128i shared = _mm_or_si128(_mm_or_si128(_mm_cmpeq_epi32(a0, b0), _mm_cmpeq_epi32(a0, b1)),
                                      _mm_or_si128(_mm_cmpeq_epi32(a1, b0), _mm_cmpeq_epi32(a1, b1)));
  const __m128 bound = _mm_add_ps(_mm_add_ps(_mm_set1_ps(thickness), length(offset(moveX, moveY, moveZ))),
                                  _mm_add_ps(own(spread), column(spread)));
  const Vec3x4 ownHalf{own(halfX), own(halfY), own(halfZ)}, otherHalf{column(halfX), column(halfY), column(halfZ)};
  return unsigned(_mm_movemask_ps(_mm_castsi128_ps(shared))) |
         segmentsApart(offset(midX, midY, midZ), ownHalf, otherHalf, bound);
#else
  (void)i, (void)first, (void)thickness;
  return 0;  // testEdgeEdge tests them one by one (kScreened false)
#endif
}

SelfCollision::SelfCollision(const std::vector<uint32_t>& triangles, size_t vertexCount)
    : triangles_(triangles), vertexCount_(vertexCount) {
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> index;
  triangleEdges_.resize(triangles.size());
  for (size_t t = 0; t < triangles.size(); t += 3)
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = triangles[t + c], b = triangles[t + (c + 1) % 3];
      const auto key = std::minmax(a, b);
      auto [it, added] = index.emplace(std::make_pair(key.first, key.second), uint32_t(edges_.size()));
      if (added) edges_.push_back({key.first, key.second}), edgeTriangles_.push_back({kNoTriangle, kNoTriangle});
      triangleEdges_[t + c] = it->second;
      auto& sides = edgeTriangles_[it->second];
      // A third triangle on an edge (non-manifold) makes no patch flat: its edge's second side is left unknown.
      if (sides[0] == kNoTriangle)
        sides[0] = uint32_t(t / 3);
      else if (sides[1] == kNoTriangle)
        sides[1] = uint32_t(t / 3);
      else
        sides[0] = sides[1] = kNoTriangle - 1;
    }
}

// Which nodes of the trees hold connected primitives (after each build), and
// where each vertex is in the triangle tree (the place of one of its triangles).
void SelfCollision::findConnectedPatches() {
  // The edge tree's part and the triangle tree's at once (independent).
  ThreadPool::shared().parallelBlocks(2, [&](size_t which) {
    if (which == 0) {
      connectedEdgePatch_ = connectedNodes(edgeTree_, vertexCount_, [&](uint32_t e) {
        return std::array<uint32_t, 2>{edges_[e].first, edges_[e].second};
      });
      edgeAtPlace_.resize(edges_.size());
      for (uint32_t k = 0; k < edges_.size(); ++k) edgeAtPlace_[k] = edges_[edgeTree_.primitive(k)];
    } else {
      connectedTrianglePatch_ = connectedNodes(tree_, vertexCount_, [&](uint32_t t) {
        return std::array<uint32_t, 3>{triangles_[3 * t], triangles_[3 * t + 1], triangles_[3 * t + 2]};
      });
      findVertexPlaces();
    }
  });
}

// The triangles' vertices in the tree's order, and the vertex groups.
void SelfCollision::findVertexPlaces() {
  triangleAtPlace_.resize(triangles_.size() / 3);
  for (uint32_t k = 0; k < triangleAtPlace_.size(); ++k) {
    const uint32_t t = tree_.primitive(k);
    triangleAtPlace_[k] = {triangles_[3 * t], triangles_[3 * t + 1], triangles_[3 * t + 2]};
  }
  vertexPlace_.assign(vertexCount_, UINT32_MAX);
  for (uint32_t k = 0; k < triangles_.size() / 3; ++k)
    for (int c = 0; c < 3; ++c) {
      uint32_t& place = vertexPlace_[triangles_[3 * tree_.primitive(k) + c]];
      place = std::min(place, k);
    }
  vertexOrder_.resize(vertexCount_);
  for (uint32_t v = 0; v < vertexCount_; ++v) vertexOrder_[v] = v;
  std::sort(vertexOrder_.begin(), vertexOrder_.end(), [&](uint32_t a, uint32_t b) {
    return vertexPlace_[a] != vertexPlace_[b] ? vertexPlace_[a] < vertexPlace_[b] : a < b;
  });
  findVertexGroups();
}

// The vertex groups: the subtrees of at most kGroupTriangles triangles that
// are highest in the tree, left to right (their places ascending, as in
// vertexOrder_), then every vertex without a triangle on its own.
void SelfCollision::findVertexGroups() {
  vertexGroups_.clear();
  uint32_t next = 0;  // in vertexOrder_
  auto addGroup = [&](uint32_t placeFirst, uint32_t placeCount) {
    const uint32_t begin = next;
    while (next < vertexOrder_.size() && vertexPlace_[vertexOrder_[next]] < placeFirst + placeCount) ++next;
    // A leaf larger than a group (its vertices over several groups with its places).
    for (uint32_t i = begin; i < next; i += kGroupVertices)
      vertexGroups_.push_back({i, std::min(next, i + kGroupVertices), placeFirst, placeCount});
  };
  if (!tree_.empty()) {
    int32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const AabbTree::NodeInfo node = tree_.nodeInfo(stack[--top]);
      if (node.left < 0 || node.count <= kGroupTriangles) {
        addGroup(node.first, node.count);
      } else {
        stack[top++] = node.right;  // the left child first
        stack[top++] = node.left;
      }
    }
  }
  for (; next < vertexOrder_.size(); ++next) vertexGroups_.push_back({next, next + 1, 0, 0});
}

// Which nodes of the trees are connected patches whose triangles keep their
// normals within 45 degrees of their mean over the step.
void SelfCollision::findFlatPatches(const ClothState& s, const std::vector<glm::vec3>& x0) {
  const size_t triangleCount = triangles_.size() / 3;
  triangleNormals_.resize(2 * triangleCount);
  inChunks(triangleCount, 1024, [&](size_t t0, size_t t1) {
    for (size_t t = t0; t < t1; ++t) {
      const uint32_t a = triangles_[3 * t], b = triangles_[3 * t + 1], c = triangles_[3 * t + 2];
      triangleNormals_[2 * t] = unitNormal(x0[a], x0[b], x0[c]);
      triangleNormals_[2 * t + 1] = unitNormal(s.x[a], s.x[b], s.x[c]);
    }
  });
  // By place: a triangle's two normals; an edge's triangles' four (a
  // boundary edge's one triangle twice; a non-manifold edge's zero).
  triangleNormalsByPlace_.resize(triangleCount, 2);
  inChunks(triangleCount, 4096, [&](size_t k0, size_t k1) {
    for (size_t k = k0; k < k1; ++k) {
      const uint32_t t = tree_.primitive(uint32_t(k));
      for (uint32_t j = 0; j < 2; ++j) triangleNormalsByPlace_.set(2 * k + j, triangleNormals_[2 * t + j]);
    }
  });
  edgeNormalsByPlace_.resize(edges_.size(), 4);
  inChunks(edges_.size(), 4096, [&](size_t k0, size_t k1) {
    for (size_t k = k0; k < k1; ++k) {
      const auto [t0, t1] = edgeTriangles_[edgeTree_.primitive(uint32_t(k))];
      const bool manifold = t0 < kNoTriangle - 1;
      const uint32_t other = t1 == kNoTriangle ? t0 : t1;
      for (uint32_t j = 0; j < 2; ++j) {
        edgeNormalsByPlace_.set(4 * k + j, manifold ? triangleNormals_[2 * t0 + j] : glm::vec3(0.0f));
        edgeNormalsByPlace_.set(4 * k + 2 + j, manifold ? triangleNormals_[2 * other + j] : glm::vec3(0.0f));
      }
    }
  });
  // The serial bottom-up and top-down sweeps of the two trees at once.
  ThreadPool::shared().parallelBlocks(2, [&](size_t which) {
    if (which == 0) {
      findFlatNodes(edgeTree_, connectedEdgePatch_, edgeNormalsByPlace_, edgeNodeNormalSums_, alignedEdgeNodes_,
                    flatEdgePatch_);
      findTopFlatPlaces(edgeTree_, flatEdgePatch_, topFlatEdgeNode_, topFlatEdgePlace_);
    } else {
      findFlatNodes(tree_, connectedTrianglePatch_, triangleNormalsByPlace_, nodeNormalSums_, alignedNodes_,
                    flatTrianglePatch_);
      findTopFlatPlaces(tree_, flatTrianglePatch_, topFlatNode_, topFlatPlace_);
    }
  });
}

void SelfCollision::findCandidates(const ClothState& s, const std::vector<glm::vec3>& x0, float thickness) {
  const size_t n = s.size(), triangleCount = triangles_.size() / 3;
  // How every vertex moved in the step. Two elements can close their gap by
  // at most the largest difference of their vertices' moves (a sheet falling
  // as a whole closes none).
  // The moves and their lengths in parallel, the sums in order (the same
  // float sums for any thread count).
  std::vector<glm::vec3> move(n);
  std::vector<float> offMean(n);  // per vertex: its move's length, then its distance from the mean move
  inChunks(n, 2048, [&](size_t v0, size_t v1) {
    for (size_t v = v0; v < v1; ++v) move[v] = s.x[v] - x0[v], offMean[v] = glm::length(move[v]);
  });
  glm::vec3 meanMove(0.0f);
  float meanMotion = 0.0f;
  for (size_t v = 0; v < n; ++v) meanMove += move[v], meanMotion += offMean[v];
  meanMove /= float(std::max<size_t>(n, 1));
  meanMotion /= float(std::max<size_t>(n, 1));
  inChunks(n, 2048, [&](size_t v0, size_t v1) {
    for (size_t v = v0; v < v1; ++v) offMean[v] = glm::length(move[v] - meanMove);
  });
  float deviation = 0.0f;  // largest distance of a move from the mean move
  for (size_t v = 0; v < n; ++v) deviation = std::max(deviation, offMean[v]);
  auto closing = [&](std::initializer_list<uint32_t> first, std::initializer_list<uint32_t> second) {
    float worst = 0.0f;
    for (uint32_t a : first)
      for (uint32_t b : second) {
        const glm::vec3 d = move[a] - move[b];
        worst = std::max(worst, glm::dot(d, d));
      }
    return std::sqrt(worst);
  };
  // Element boxes for the broad phase. Swept over the step (start and end,
  // grown by the thickness) when the cloth's moves differ much (a pair is a
  // candidate only when those overlap); otherwise no such condition: any two
  // elements closing by up to twice the deviation qualify ("relative" boxes:
  // at the start, grown by half the thickness plus their own vertices'
  // largest distance from the mean move). Either way a candidate passes the
  // exact test below, dist(x0) <= thickness + closing; the traversals check
  // it for whole nodes too (nodeMotions_), which keeps them out of the parts
  // that move rigidly, however far the cloth moves as a whole.
  const bool swept = !(2.0f * deviation < meanMotion + thickness);
  auto sweptBox = [&](std::initializer_list<uint32_t> vertices) {
    Box b;
    for (uint32_t v : vertices) b.extend(x0[v]), b.extend(s.x[v]);
    b.min -= glm::vec3(thickness);
    b.max += glm::vec3(thickness);
    return b;
  };
  auto relativeBox = [&](std::initializer_list<uint32_t> vertices) {
    Box b;
    float grow = 0.0f;
    for (uint32_t v : vertices) b.extend(x0[v]), grow = std::max(grow, offMean[v]);
    grow += 0.5f * thickness;
    b.min -= glm::vec3(grow);
    b.max += glm::vec3(grow);
    return b;
  };
  auto extentSum = [](const std::vector<Box>& boxes) {
    double sum = 0.0;
    for (const Box& b : boxes) sum += double(b.max.x - b.min.x) + double(b.max.y - b.min.y) + double(b.max.z - b.min.z);
    return sum;
  };
  // The trees hold whichever kind is smaller in all; when they hold relative
  // boxes in swept mode, the swept boxes are checked on each pair.
  std::vector<Box> boxes(triangleCount), edgeBoxes(edges_.size()), sweptBoxes, sweptEdgeBoxes;
  if (swept) sweptBoxes.resize(triangleCount), sweptEdgeBoxes.resize(edges_.size());
  // In parallel (each element on its own: the same boxes).
  // The same boxes as relativeBox() and sweptBox(), in registers.
  auto relativeElementBox = [&](const auto& vertices) {
    float grow = 0.0f;
    for (uint32_t v : vertices) grow = std::max(grow, offMean[v]);
    return grownBox(vertices, x0, nullptr, grow + 0.5f * thickness);
  };
  auto sweptElementBox = [&](const auto& vertices) { return grownBox(vertices, x0, &s.x, thickness); };
  inChunks(triangleCount, 4096, [&](size_t t0, size_t t1) {
    for (size_t t = t0; t < t1; ++t) {
      const std::array<uint32_t, 3> corners{triangles_[3 * t], triangles_[3 * t + 1], triangles_[3 * t + 2]};
      boxes[t] = relativeElementBox(corners);
      if (swept) sweptBoxes[t] = sweptElementBox(corners);
    }
  });
  inChunks(edges_.size(), 4096, [&](size_t e0, size_t e1) {
    for (size_t e = e0; e < e1; ++e) {
      const std::array<uint32_t, 2> ends{edges_[e].first, edges_[e].second};
      edgeBoxes[e] = relativeElementBox(ends);
      if (swept) sweptEdgeBoxes[e] = sweptElementBox(ends);
    }
  });
  bool checkSwept = false;  // the trees hold relative boxes, candidates need swept ones to overlap
  if (swept) {
    checkSwept = extentSum(boxes) + extentSum(edgeBoxes) < extentSum(sweptBoxes) + extentSum(sweptEdgeBoxes);
    if (!checkSwept) boxes.swap(sweptBoxes), edgeBoxes.swap(sweptEdgeBoxes);
  }
  // The mesh keeps its topology: the trees are refitted to the new boxes and
  // rebuilt when they have grown loose, as the cloth's shape drifts from the
  // one they were built for (the candidates depend on the tree only through
  // its flat patches, whose pairs left out are neighbours in the cloth's plane).
  // Both trees at once, one per thread.
  bool rebuild = tree_.empty() || edgeTree_.empty();
  if (!rebuild) {
    float sizes[2];
    ThreadPool::shared().parallelBlocks(2, [&](size_t which) {
      sizes[which] = which == 0 ? edgeTree_.refit(edgeBoxes) : tree_.refit(boxes);
    });
    rebuild = sizes[0] > kRebuildGrowth * builtSizes_[0] || sizes[1] > kRebuildGrowth * builtSizes_[1];
  }
  if (rebuild) {
    ThreadPool::shared().parallelBlocks(2, [&](size_t which) {
      builtSizes_[which] = which == 0 ? edgeTree_.build(edgeBoxes) : tree_.build(boxes);
    });
    findConnectedPatches();
  }
  // The swept boxes checked on each pair in the trees' order (read in sequence).
  if (checkSwept) {
    sweptBoxes = placeOrdered(tree_, sweptBoxes);
    sweptEdgeBoxes = placeOrdered(edgeTree_, sweptEdgeBoxes);
  }
  // The node bounds pay where the boxes are grown much by the motion (parts
  // of the cloth moving apart from the rest); where its moves differ little
  // they cost more than they leave out.
  const bool bounded = motionBounds_ && deviation > 2.0f * thickness;
  if (bounded) {
    findElementMotions(tree_, [&](uint32_t t) {
      return std::array<uint32_t, 3>{triangles_[3 * t], triangles_[3 * t + 1], triangles_[3 * t + 2]};
    }, x0, move, triangleMotions_);
    findElementMotions(edgeTree_, [&](uint32_t e) {
      return std::array<uint32_t, 2>{edges_[e].first, edges_[e].second};
    }, x0, move, edgeMotions_);
    // The two trees' serial bottom-up sweeps at once.
    ThreadPool::shared().parallelBlocks(2, [&](size_t which) {
      if (which == 0)
        findNodeMotions(edgeTree_, edgeMotions_, edgeNodeMotions_);
      else
        findNodeMotions(tree_, triangleMotions_, nodeMotions_);
    });
  }
  findFlatPatches(s, x0);
  // The screen before the exact vertex-triangle test (corners, flat patches
  // and a cheap bound, as for the edges below), by place.
  triangleColumns_.resize(triangleCount);
  inChunks(triangleCount, 4096, [&](size_t k0, size_t k1) {
    for (size_t k = k0; k < k1; ++k) {
      const std::array<uint32_t, 3>& corners = triangleAtPlace_[k];
      const glm::vec3 start[3] = {x0[corners[0]], x0[corners[1]], x0[corners[2]]};
      const glm::vec3 moves[3] = {move[corners[0]], move[corners[1]], move[corners[2]]};
      triangleColumns_.set(k, corners, topFlatPlace_[k], triangleReach(start, moves));
    }
  });
  // A vertex's query: its box (of the trees' kind) and swept box, and its
  // highest flat patch.
  struct VertexQuery {
    uint32_t vertex;
    int32_t flat;
    Box box, swept;
  };
  auto vertexQuery = [&](uint32_t v) {
    const Box vertexSwept = sweptBox({v});
    const int32_t flat = vertexPlace_[v] == UINT32_MAX ? -1 : topFlatPlace_[vertexPlace_[v]];
    return VertexQuery{v, flat, swept && !checkSwept ? vertexSwept : relativeBox({v}), vertexSwept};
  };
  // Whether a vertex and the triangle at a place in the tree pass the screen.
  auto screened = [&](const VertexQuery& q, uint32_t place) {
    return triangleColumns_.screen(place, q.vertex, q.flat, x0[q.vertex], move[q.vertex], thickness);
  };
  // A vertex and the triangle at a place in the tree whose boxes overlap and
  // that passed the screen: within reach.
  auto testVertexTriangle = [&](const VertexQuery& q, uint32_t place, std::vector<VertexTriangle>& out) {
    const uint32_t v = q.vertex;
    if (bounded && !withinReach(triangleMotions_[place], x0[v], move[v], thickness)) return;
    if (checkSwept && !q.swept.overlaps(sweptBoxes[place])) return;
    const auto [a, b, c] = triangleAtPlace_[place];
    const glm::vec3 w = closestTriangleWeights(x0[v], x0[a], x0[b], x0[c]);
    const glm::vec3 normal = glm::cross(x0[b] - x0[a], x0[c] - x0[a]);
    const glm::vec3 offset = x0[v] - (w.x * x0[a] + w.y * x0[b] + w.z * x0[c]);
    const float reach = thickness + closing({v}, {a, b, c});
    if (glm::dot(offset, offset) > reach * reach) return;
    const float side = glm::dot(offset, normal) >= 0.0f ? 1.0f : -1.0f;
    out.push_back({v, tree_.primitive(place), w, side});
  };
  if (exhaustive_) {
    vertexTriangle_ = collectInBlocks<VertexTriangle>(n, [&](size_t v, std::vector<VertexTriangle>& out) {
      const VertexQuery q = vertexQuery(uint32_t(v));
      for (uint32_t place = 0; place < triangleCount; ++place)
        if (q.box.overlaps(tree_.leafBox(place)) && screened(q, place)) testVertexTriangle(q, place, out);
    });
  } else {
    // One query per vertex group (vertices close in the tree, so close in
    // space) with the group's box and motion, then each vertex against the
    // triangles found: the pairs of the vertices' own queries. The groups in
    // the tree's order, a few at a time: their walks start where they part
    // (their nodes near the root are the same), one after the other walks
    // the same nodes.
    struct GroupQuery {
      uint32_t begin = 0, end = 0, placeFirst = 0, placeCount = 0;  // its vertices' queries [begin, end)
      Box box;
      NodeMotion motion;
    };
    // Not into a node out of the vertices' reach, nor into a flat patch that
    // holds all their places (no triangle there can reach them).
    auto skipped = [&](int32_t node, const GroupQuery& g) {
      if (bounded && !withinReach(nodeMotions_[node], g.motion, thickness)) return true;
      if (!flatTrianglePatch_[node] || g.placeCount == 0) return false;
      const AabbTree::NodeInfo info = tree_.nodeInfo(node);
      return g.placeFirst - info.first < info.count && g.placeFirst + g.placeCount - info.first <= info.count;
    };
    const size_t runs = (vertexGroups_.size() + kRunGroups - 1) / kRunGroups;
    vertexTriangle_ = collectInBlocks<VertexTriangle>(runs, [&](size_t r, std::vector<VertexTriangle>& out) {
      const size_t g0 = r * kRunGroups, g1 = std::min(vertexGroups_.size(), g0 + kRunGroups);
      GroupQuery groups[kRunGroups];
      // Scratch kept per thread: a step makes a few hundred runs.
      thread_local std::vector<VertexQuery> queries;
      thread_local std::vector<AabbTree::Entry> entries;
      queries.clear();
      // The run's box, motion and places hold its groups' (no places: a vertex without a triangle).
      GroupQuery run;
      uint32_t placeEnd = 0;
      bool placeless = false;
      run.placeFirst = UINT32_MAX;
      for (size_t g = g0; g < g1; ++g) {
        const VertexGroup& group = vertexGroups_[g];
        GroupQuery& q = groups[g - g0];
        q.begin = uint32_t(queries.size());
        for (uint32_t i = group.vertexBegin; i < group.vertexEnd; ++i) {
          const uint32_t v = vertexOrder_[i];
          queries.push_back(vertexQuery(v));
          q.box.extend(queries.back().box);
          if (bounded) extend(q.motion, pointMotion(x0[v], move[v]));
        }
        q.end = uint32_t(queries.size());
        q.placeFirst = group.placeFirst, q.placeCount = group.placeCount;
        run.box.extend(q.box);
        if (bounded) extend(run.motion, q.motion);
        placeless |= group.placeCount == 0;
        run.placeFirst = std::min(run.placeFirst, group.placeFirst);
        placeEnd = std::max(placeEnd, group.placeFirst + group.placeCount);
      }
      run.placeCount = placeless ? 0 : placeEnd - run.placeFirst;
      // The run's box, motion and places hold each group's: its walk leaves
      // out no node a group's walk keeps.
      tree_.queryEntries(run.box, kRunSplit, [&](int32_t node) { return skipped(node, run); }, entries);
      for (size_t g = g0; g < g1; ++g) {
        const GroupQuery& group = groups[g - g0];
        // Each vertex against a leaf's four boxes and screens at once.
        tree_.queryLeavesFrom(entries, group.box, [&](int32_t leaf) {
          const uint32_t first = tree_.nodeInfo(leaf).first;
          for (uint32_t k = group.begin; k < group.end; ++k) {
            const VertexQuery& q = queries[k];
            unsigned mask = tree_.leafOverlaps(leaf, q.box);
            if (mask != 0)
              mask &= triangleColumns_.screenFour(first, q.vertex, q.flat, x0[q.vertex], move[q.vertex], thickness);
            for (; mask != 0; mask &= mask - 1) testVertexTriangle(q, first + uint32_t(__builtin_ctz(mask)), out);
          }
        }, [&](int32_t node) { return skipped(node, group); });
      }
    });
  }
  // In order of the vertex, then the triangle (the tree's order depends on the boxes).
  std::sort(vertexTriangle_.begin(), vertexTriangle_.end(), [](const VertexTriangle& a, const VertexTriangle& b) {
    return a.vertex != b.vertex ? a.vertex < b.vertex : a.triangle < b.triangle;
  });
  // Edge pairs from the edge tree against itself. A cheap bound first, from
  // each edge's midpoint, half length, mean move and move spread: any two of
  // their vertices' moves differ by at most |mean_e - mean_f| + spread_e +
  // spread_f, so a pair it rejects fails the exact test below too. The
  // four-lane screen (EdgeColumns::apartOrNeighbours) bounds their distance
  // along the line through their midpoints instead of by their half lengths
  // (tighter: most close pairs of a curved part are left out before the exact
  // test).
  struct EdgeBound {
    glm::vec3 mid;
    float halfLength;
    glm::vec3 meanMove;
    float spread;
  };
  std::vector<EdgeBound> bounds(edges_.size());  // by place
  EdgeColumns& columns = edgeColumns_;
  columns.resize(edges_.size());
  inChunks(edges_.size(), 4096, [&](size_t k0, size_t k1) {
    for (size_t k = k0; k < k1; ++k) {
      const auto [p0, p1] = edgeAtPlace_[k];
      const EdgeBound& b = bounds[k] = {0.5f * (x0[p0] + x0[p1]), 0.5f * glm::length(x0[p0] - x0[p1]),
                                        0.5f * (move[p0] + move[p1]), 0.5f * glm::length(move[p0] - move[p1])};
      columns.set(k, edgeTree_.primitive(uint32_t(k)), p0, p1, b.mid, 0.5f * (x0[p1] - x0[p0]), b.meanMove, b.spread);
      columns.setVertices(k, {x0[p0], x0[p1]}, {move[p0], move[p1]});
    }
  });
  // Two edges at places of the edge tree whose boxes overlap, not in one
  // flat patch (screened: not neighbours and within the four-lane screen's
  // bound, as EdgeColumns::apartOrNeighbours found).
  auto testEdgeEdge = [&](uint32_t placeI, uint32_t placeK, std::vector<EdgeEdge>& out, bool screened) {
    // Neighbours first, from the edges' vertices in the tree's order (read in sequence).
    const auto [a0, a1] = edgeAtPlace_[placeI];
    const auto [b0, b1] = edgeAtPlace_[placeK];
    if (!screened && sharesVertex(a0, a1, b0, b1)) return;
    if (bounded && !withinReach(edgeMotions_[placeI], edgeMotions_[placeK], thickness)) return;
    if (checkSwept && !sweptEdgeBoxes[placeI].overlaps(sweptEdgeBoxes[placeK])) return;
    if (!screened) {
      const EdgeBound &bi = bounds[placeI], &bk = bounds[placeK];
      const float bound = thickness + glm::length(bi.meanMove - bk.meanMove) + (bi.spread + bk.spread);
      if (glm::length(bi.mid - bk.mid) - (bi.halfLength + bk.halfLength) > 1.0001f * bound + 1e-6f) return;
    }
    // The exact test with the edges in their order (the lower index first).
    const uint32_t i = edgeTree_.primitive(placeI), k = edgeTree_.primitive(placeK);
    const bool ordered = i < k;
    const uint32_t e = ordered ? i : k, f = ordered ? k : i;
    const uint32_t p0 = ordered ? a0 : b0, p1 = ordered ? a1 : b1, q0 = ordered ? b0 : a0, q1 = ordered ? b1 : a1;
    if (!segmentsWithinReach(x0[p0], x0[p1], x0[q0], x0[q1], thickness + closing({p0, p1}, {q0, q1}))) return;
    const glm::vec2 st = closestSegmentParameters(x0[p0], x0[p1], x0[q0], x0[q1]);
    const glm::vec3 d = glm::mix(x0[p0], x0[p1], st.x) - glm::mix(x0[q0], x0[q1], st.y);
    out.push_back({e, f, st, d / glm::length(d)});
  };
  std::vector<std::vector<EdgeEdge>> found;
  if (exhaustive_) {
    const uint32_t places = uint32_t(edges_.size());
    found.resize(places);
    ThreadPool::shared().parallelBlocks(places, [&](size_t i) {
      const Box& box = edgeBoxes[edgeTree_.primitive(uint32_t(i))];
      const int32_t flat = topFlatEdgePlace_[i];
      for (uint32_t k = uint32_t(i) + 1; k < places; ++k) {
        if ((flat >= 0 && flat == topFlatEdgePlace_[k]) || !box.overlaps(edgeBoxes[edgeTree_.primitive(k)])) continue;
        testEdgeEdge(uint32_t(i), k, found[i], false);
      }
    });
  } else {
    auto flatEdgePatch = [&](int32_t node) { return flatEdgePatch_[node] != 0; };
    auto outOfReach = [&](int32_t a, int32_t b) {
      return bounded && !withinReach(edgeNodeMotions_[a], edgeNodeMotions_[b], thickness);
    };
    const std::vector<AabbTree::PairJob> jobs = edgeTree_.pairJobs(4 * kBlocks, flatEdgePatch);
    found.resize(jobs.size());
    ThreadPool::shared().parallelBlocks(jobs.size(), [&](size_t j) {
      // The neighbours and the cheap bound above for four pairs at once,
      // then the exact test's distance conditions (few pairs pass them).
      edgeTree_.runJobInQuads(jobs[j], [&](uint32_t placeI, uint32_t first, unsigned mask) {
        mask &= columns.apartOrNeighbours(placeI, first, thickness) ^ 0xFu;
        if (mask != 0) mask &= columns.withinReach(placeI, first, thickness);
        for (; mask != 0; mask &= mask - 1)
          testEdgeEdge(placeI, first + uint32_t(__builtin_ctz(mask)), found[j], kScreened);
      }, flatEdgePatch, outOfReach);
    });
  }
  // In order of the first edge, then the other (the jobs' order depends on the tree).
  edgeEdge_.clear();
  for (const auto& f : found) edgeEdge_.insert(edgeEdge_.end(), f.begin(), f.end());
  std::sort(edgeEdge_.begin(), edgeEdge_.end(),
            [](const EdgeEdge& a, const EdgeEdge& b) { return a.e0 != b.e0 ? a.e0 < b.e0 : a.e1 < b.e1; });
}

// Pushes the weighted point sum_k w_k x_k of a pair apart along n until its
// gap is `thickness`, sharing the move by inverse mass (a position
// constraint), and removes the approaching part of the relative velocity.
template <size_t N>
static int separate(ClothState& s, const uint32_t (&v)[N], const float (&w)[N], const glm::vec3& n, float thickness) {
  glm::vec3 gapPoint(0.0f), relVelocity(0.0f);
  float denom = 0.0f;
  for (size_t k = 0; k < N; ++k) {
    gapPoint += w[k] * s.x[v[k]];
    relVelocity += w[k] * s.v[v[k]];
    denom += w[k] * w[k] * s.invMass[v[k]];
  }
  const float gap = glm::dot(gapPoint, n);
  if (gap >= thickness || denom <= 0.0f) return 0;
  const float push = (thickness - gap) / denom;
  const float vn = glm::dot(relVelocity, n);
  const float stop = vn < 0.0f ? -vn / denom : 0.0f;
  for (size_t k = 0; k < N; ++k) {
    s.x[v[k]] += (push * w[k] * s.invMass[v[k]]) * n;
    s.v[v[k]] += (stop * w[k] * s.invMass[v[k]]) * n;
  }
  return 1;
}

int SelfCollision::applyVertexTriangle(ClothState& s, const VertexTriangle& c, float thickness) const {
  const uint32_t a = triangles_[3 * c.triangle], b = triangles_[3 * c.triangle + 1], d = triangles_[3 * c.triangle + 2];
  const glm::vec3 normal = glm::cross(s.x[b] - s.x[a], s.x[d] - s.x[a]);
  const float l = glm::length(normal);
  if (l <= 0.0f) return 0;
  const glm::vec3 n = (c.side / l) * normal;
  // Only a vertex over the triangle (not beside it in its plane) is in contact.
  const glm::vec3 offset = s.x[c.vertex] - (c.weights.x * s.x[a] + c.weights.y * s.x[b] + c.weights.z * s.x[d]);
  if (glm::length(offset - glm::dot(offset, n) * n) > thickness) return 0;
  const uint32_t v[4] = {c.vertex, a, b, d};
  const float w[4] = {1.0f, -c.weights.x, -c.weights.y, -c.weights.z};
  return separate(s, v, w, n, thickness);
}

int SelfCollision::applyEdgeEdge(ClothState& s, const EdgeEdge& c, float thickness) const {
  const auto [p0, p1] = edges_[c.e0];
  const auto [q0, q1] = edges_[c.e1];
  const glm::vec3 offset = glm::mix(s.x[p0], s.x[p1], c.params.x) - glm::mix(s.x[q0], s.x[q1], c.params.y);
  if (glm::length(offset - glm::dot(offset, c.normal0) * c.normal0) > thickness) return 0;
  const uint32_t v[4] = {p0, p1, q0, q1};
  const float w[4] = {1.0f - c.params.x, c.params.x, -(1.0f - c.params.y), -c.params.y};
  return separate(s, v, w, c.normal0, thickness);
}

std::vector<std::array<uint32_t, 2>> SelfCollision::vertexTrianglePairs() const {
  std::vector<std::array<uint32_t, 2>> pairs;
  for (const VertexTriangle& c : vertexTriangle_) pairs.push_back({c.vertex, c.triangle});
  return pairs;
}

std::vector<std::array<uint32_t, 4>> SelfCollision::edgeEdgePairs() const {
  std::vector<std::array<uint32_t, 4>> pairs;
  for (const EdgeEdge& c : edgeEdge_)
    pairs.push_back({edges_[c.e0].first, edges_[c.e0].second, edges_[c.e1].first, edges_[c.e1].second});
  return pairs;
}

int SelfCollision::resolve(ClothState& s, const std::vector<glm::vec3>& x0, float thickness, int passes) {
  findCandidates(s, x0, thickness);
  int contacts = 0;
  // A pair whose four vertices have not moved since it was last found apart
  // is apart still: later passes skip it (moved_: the clock of each vertex's
  // last push, checked_: of each pair's last test).
  moved_.assign(s.size(), 0);
  checkedVT_.assign(vertexTriangle_.size(), 0);
  checkedEE_.assign(edgeEdge_.size(), 0);
  uint32_t clock = 1;
  auto stale = [&](uint32_t checked, const uint32_t (&v)[4]) {
    return moved_[v[0]] >= checked || moved_[v[1]] >= checked || moved_[v[2]] >= checked || moved_[v[3]] >= checked;
  };
  auto touch = [&](const uint32_t (&v)[4]) {
    for (uint32_t k : v) moved_[k] = clock;
  };
  for (int pass = 0; pass < passes; ++pass) {
    int active = 0;
    for (size_t k = 0; k < vertexTriangle_.size(); ++k) {
      const VertexTriangle& c = vertexTriangle_[k];
      const uint32_t* t = &triangles_[3 * c.triangle];
      const uint32_t v[4] = {c.vertex, t[0], t[1], t[2]};
      if (pass > 0 && !stale(checkedVT_[k], v)) continue;
      checkedVT_[k] = ++clock;
      if (applyVertexTriangle(s, c, thickness)) ++active, touch(v);
    }
    for (size_t k = 0; k < edgeEdge_.size(); ++k) {
      const EdgeEdge& c = edgeEdge_[k];
      const uint32_t v[4] = {edges_[c.e0].first, edges_[c.e0].second, edges_[c.e1].first, edges_[c.e1].second};
      if (pass > 0 && !stale(checkedEE_[k], v)) continue;
      checkedEE_[k] = ++clock;
      if (applyEdgeEdge(s, c, thickness)) ++active, touch(v);
    }
    if (pass == 0) contacts = active;
    if (active == 0) break;
  }
  return contacts;
}

}  // namespace mq::cloth
