#include "core/garment/seam_weld.h"

#include <numeric>

namespace mq {
namespace {

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

}  // namespace

SeamWeld computeSeamWeld(size_t vertexCount, const std::vector<VertexPair>& pairs) {
  std::vector<uint32_t> parent(vertexCount);
  std::iota(parent.begin(), parent.end(), 0u);
  for (auto [a, b] : pairs) {
    uint32_t ra = findRoot(parent, a), rb = findRoot(parent, b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);  // the smallest index is the root
  }
  SeamWeld weld;
  weld.newIndex.assign(vertexCount, 0);
  std::vector<uint32_t> rootToNew(vertexCount, UINT32_MAX);
  for (uint32_t v = 0; v < vertexCount; ++v) {
    uint32_t root = findRoot(parent, v);
    if (rootToNew[root] == UINT32_MAX) {
      rootToNew[root] = uint32_t(weld.groupSize.size());
      weld.groupSize.push_back(0);
    }
    weld.newIndex[v] = rootToNew[root];
    ++weld.groupSize[rootToNew[root]];
  }
  return weld;
}

std::vector<float> weldAverage(const SeamWeld& weld, const std::vector<float>& values, int components) {
  std::vector<float> out(weld.newVertexCount() * components, 0.0f);
  for (size_t v = 0; v < weld.newIndex.size(); ++v)
    for (int c = 0; c < components; ++c) out[weld.newIndex[v] * components + c] += values[v * components + c];
  for (size_t n = 0; n < weld.newVertexCount(); ++n)
    for (int c = 0; c < components; ++c) out[n * components + c] /= float(weld.groupSize[n]);
  return out;
}

std::vector<float> weldSum(const SeamWeld& weld, const std::vector<float>& values) {
  std::vector<float> out(weld.newVertexCount(), 0.0f);
  for (size_t v = 0; v < weld.newIndex.size(); ++v) out[weld.newIndex[v]] += values[v];
  return out;
}

std::vector<uint32_t> weldTriangles(const SeamWeld& weld, const std::vector<uint32_t>& triangles) {
  std::vector<uint32_t> out;
  out.reserve(triangles.size());
  for (size_t t = 0; t < triangles.size(); t += 3) {
    uint32_t a = weld.newIndex[triangles[t]], b = weld.newIndex[triangles[t + 1]], c = weld.newIndex[triangles[t + 2]];
    if (a == b || b == c || a == c) continue;
    out.insert(out.end(), {a, b, c});
  }
  return out;
}

}  // namespace mq
