// The search's flat patches (after Volino and Magnenat-Thalmann's curvature
// test): nodes of the trees whose elements are connected and whose
// triangles' normals stay within 45 degrees of their mean over the step.
// Their elements cannot meet each other: the searches leave such pairs out.
#include <algorithm>

#include "sim/cloth/collision/self_collision/stages.h"

namespace mq::cloth {

using namespace self_collision;

namespace {

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
    aligned[i] = smallestAlignment(&normals.x[first], &normals.y[first], &normals.z[first], count, sums[i] / length) >=
                 kFlatCosine;
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

}  // namespace

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

}  // namespace mq::cloth
