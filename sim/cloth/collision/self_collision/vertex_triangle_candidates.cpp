// The search's vertex-triangle candidates: each vertex against the
// triangles of the triangle tree near it (a query per group of vertices
// close in the tree, a few groups' walks started together), screened four
// triangles at once (TriangleColumns), then the exact test at the start of
// the step. The exhaustive search (setExhaustive) is the tests' oracle.
#include <algorithm>
#include <array>

#include "sim/cloth/collision/proximity.h"
#include "sim/cloth/collision/self_collision/stages.h"

namespace mq::cloth {

using namespace self_collision;

void SelfCollision::findVertexTriangleCandidates(const Step& step) {
  const std::vector<glm::vec3>& x0 = step.x0;
  const std::vector<glm::vec3>& move = step.move;
  const float thickness = step.thickness;
  const bool swept = step.swept, checkSwept = step.checkSwept, bounded = step.bounded;
  const std::vector<Box>& sweptBoxes = step.sweptBoxes;
  const size_t n = step.s.size(), triangleCount = triangles_.size() / 3;
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
    const Box vertexSwept = step.sweptBox(v);
    const int32_t flat = vertexPlace_[v] == UINT32_MAX ? -1 : topFlatPlace_[vertexPlace_[v]];
    return VertexQuery{v, flat, swept && !checkSwept ? vertexSwept : step.relativeBox(v), vertexSwept};
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
    const float reach = thickness + step.closing({v}, {a, b, c});
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
      tree_.queryEntries(
          run.box, kRunSplit, [&](int32_t node) { return skipped(node, run); }, entries);
      for (size_t g = g0; g < g1; ++g) {
        const GroupQuery& group = groups[g - g0];
        // Each vertex against a leaf's four boxes and screens at once.
        tree_.queryLeavesFrom(
            entries, group.box,
            [&](int32_t leaf) {
              const uint32_t first = tree_.nodeInfo(leaf).first;
              for (uint32_t k = group.begin; k < group.end; ++k) {
                const VertexQuery& q = queries[k];
                unsigned mask = tree_.leafOverlaps(leaf, q.box);
                if (mask != 0)
                  mask &= triangleColumns_.screenFour(first, q.vertex, q.flat, x0[q.vertex], move[q.vertex], thickness);
                for (; mask != 0; mask &= mask - 1) testVertexTriangle(q, first + uint32_t(__builtin_ctz(mask)), out);
              }
            },
            [&](int32_t node) { return skipped(node, group); });
      }
    });
  }
  // In order of the vertex, then the triangle (the tree's order depends on the boxes).
  std::sort(vertexTriangle_.begin(), vertexTriangle_.end(), [](const VertexTriangle& a, const VertexTriangle& b) {
    return a.vertex != b.vertex ? a.vertex < b.vertex : a.triangle < b.triangle;
  });
}

}  // namespace mq::cloth
