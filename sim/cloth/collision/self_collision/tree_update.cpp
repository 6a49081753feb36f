// The search's second stage: the triangle and edge trees refitted to the
// step's element boxes, or rebuilt when they have grown loose, with what a
// build decides (connected patches, the elements and vertices by place, the
// vertex groups).
#include <algorithm>
#include <array>

#include "sim/cloth/collision/self_collision/stages.h"

namespace mq::cloth {

using namespace self_collision;

namespace {

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

}  // namespace

void SelfCollision::updateTrees(Step& step) {
  const std::vector<Box>& boxes = step.boxes;
  const std::vector<Box>& edgeBoxes = step.edgeBoxes;
  std::vector<Box>& sweptBoxes = step.sweptBoxes;
  std::vector<Box>& sweptEdgeBoxes = step.sweptEdgeBoxes;
  // The mesh keeps its topology: the trees are refitted to the new boxes and
  // rebuilt when they have grown loose, as the cloth's shape drifts from the
  // one they were built for (the candidates depend on the tree only through
  // its flat patches, whose pairs left out are neighbours in the cloth's plane).
  // Both trees at once, one per thread.
  bool rebuild = tree_.empty() || edgeTree_.empty();
  if (!rebuild) {
    float sizes[2];
    ThreadPool::shared().parallelBlocks(
        2, [&](size_t which) { sizes[which] = which == 0 ? edgeTree_.refit(edgeBoxes) : tree_.refit(boxes); });
    rebuild = sizes[0] > kRebuildGrowth * builtSizes_[0] || sizes[1] > kRebuildGrowth * builtSizes_[1];
  }
  if (rebuild) {
    ThreadPool::shared().parallelBlocks(
        2, [&](size_t which) { builtSizes_[which] = which == 0 ? edgeTree_.build(edgeBoxes) : tree_.build(boxes); });
    findConnectedPatches();
  }
  // The swept boxes checked on each pair in the trees' order (read in sequence).
  if (step.checkSwept) {
    sweptBoxes = placeOrdered(tree_, sweptBoxes);
    sweptEdgeBoxes = placeOrdered(edgeTree_, sweptEdgeBoxes);
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

}  // namespace mq::cloth
