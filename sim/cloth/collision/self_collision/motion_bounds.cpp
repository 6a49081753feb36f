// The search's motion bounds: per element and per node of the trees, the
// box of their vertices at the start of the step and the box of their
// moves, so that the searches leave out whole nodes out of each other's
// reach however far the cloth moves (stages.h: withinReach).
#include <array>

#include "sim/cloth/collision/self_collision/stages.h"

namespace mq::cloth {

using namespace self_collision;

namespace {

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

}  // namespace

void SelfCollision::findMotionBounds(Step& step) {
  // The node bounds pay where the boxes are grown much by the motion (parts
  // of the cloth moving apart from the rest); where its moves differ little
  // they cost more than they leave out.
  step.bounded = motionBounds_ && step.deviation > 2.0f * step.thickness;
  if (step.bounded) {
    findElementMotions(
        tree_,
        [&](uint32_t t) {
          return std::array<uint32_t, 3>{triangles_[3 * t], triangles_[3 * t + 1], triangles_[3 * t + 2]};
        },
        step.x0, step.move, triangleMotions_);
    findElementMotions(
        edgeTree_,
        [&](uint32_t e) {
          return std::array<uint32_t, 2>{edges_[e].first, edges_[e].second};
        },
        step.x0, step.move, edgeMotions_);
    // The two trees' serial bottom-up sweeps at once.
    ThreadPool::shared().parallelBlocks(2, [&](size_t which) {
      if (which == 0)
        findNodeMotions(edgeTree_, edgeMotions_, edgeNodeMotions_);
      else
        findNodeMotions(tree_, triangleMotions_, nodeMotions_);
    });
  }
}

}  // namespace mq::cloth
