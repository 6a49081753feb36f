#include "core/mesh/mesh_checks.h"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace mq {
namespace {

struct HalfEdge {
  uint32_t low, high;  // endpoints, sorted
  bool forward;        // the triangle runs low -> high
  bool operator<(const HalfEdge& o) const { return std::tie(low, high, forward) < std::tie(o.low, o.high, o.forward); }
};

void checkEdges(const std::vector<uint32_t>& triangles, MeshTopologyReport& report) {
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(triangles.size());
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = triangles[t + e], b = triangles[t + (e + 1) % 3];
      halfEdges.push_back({std::min(a, b), std::max(a, b), a < b});
    }
  std::sort(halfEdges.begin(), halfEdges.end());
  for (size_t i = 0; i < halfEdges.size();) {
    size_t j = i;
    while (j < halfEdges.size() && halfEdges[j].low == halfEdges[i].low && halfEdges[j].high == halfEdges[i].high) ++j;
    ++report.edges;
    const size_t uses = j - i;
    if (uses == 1) ++report.boundaryEdges;
    if (uses > 2) ++report.overSharedEdges;
    if (uses == 2 && halfEdges[i].forward == halfEdges[i + 1].forward) ++report.misorientedEdges;
    i = j;
  }
}

// A vertex is manifold when the opposite edges of its triangles, taken as
// links next -> previous, chain into one closed cycle.
void checkVertexFans(size_t vertexCount, const std::vector<uint32_t>& triangles, MeshTopologyReport& report) {
  std::vector<uint32_t> start(vertexCount + 1, 0);
  for (uint32_t v : triangles) ++start[v + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::pair<uint32_t, uint32_t>> links(triangles.size());
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
    for (int c = 0; c < 3; ++c)
      links[fill[triangles[t + c]]++] = {triangles[t + (c + 1) % 3], triangles[t + (c + 2) % 3]};
  for (size_t v = 0; v < vertexCount; ++v) {
    auto begin = links.begin() + start[v], end = links.begin() + start[v + 1];
    if (begin == end) {
      ++report.isolatedVertices;
      continue;
    }
    std::sort(begin, end);
    bool single = std::adjacent_find(begin, end, [](auto& a, auto& b) { return a.first == b.first; }) == end;
    size_t steps = 0;
    uint32_t at = begin->first;
    while (single) {
      auto it = std::lower_bound(begin, end, std::make_pair(at, uint32_t(0)));
      if (it == end || it->first != at) {
        single = false;
        break;
      }
      at = it->second;
      ++steps;
      if (at == begin->first || steps > size_t(end - begin)) break;
    }
    if (!single || at != begin->first || steps != size_t(end - begin)) ++report.nonManifoldVertices;
  }
}

size_t countComponents(size_t vertexCount, const std::vector<uint32_t>& triangles) {
  std::vector<uint32_t> parent(vertexCount);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<bool> used(vertexCount, false);
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
    for (int c = 0; c < 3; ++c) {
      used[triangles[t + c]] = true;
      parent[find(triangles[t + c])] = find(triangles[t + (c + 1) % 3]);
    }
  size_t components = 0;
  for (size_t v = 0; v < vertexCount; ++v) components += used[v] && find(uint32_t(v)) == v;
  return components;
}

}  // namespace

MeshTopologyReport checkTopology(size_t vertexCount, const std::vector<uint32_t>& triangles) {
  MeshTopologyReport report;
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const uint32_t a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
    report.degenerateTriangles += a == b || b == c || a == c;
  }
  checkEdges(triangles, report);
  checkVertexFans(vertexCount, triangles, report);
  report.components = countComponents(vertexCount, triangles);
  return report;
}

double signedVolume(const std::vector<float>& positions, const std::vector<uint32_t>& triangles) {
  double volume = 0.0;
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const float* a = &positions[3 * triangles[t]];
    const float* b = &positions[3 * triangles[t + 1]];
    const float* c = &positions[3 * triangles[t + 2]];
    // a . (b x c) / 6: the tetrahedron with the origin
    volume += (double(a[0]) * (double(b[1]) * c[2] - double(b[2]) * c[1]) +
               double(a[1]) * (double(b[2]) * c[0] - double(b[0]) * c[2]) +
               double(a[2]) * (double(b[0]) * c[1] - double(b[1]) * c[0])) /
              6.0;
  }
  return volume;
}

}  // namespace mq
