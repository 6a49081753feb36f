#pragma once
// Welding sewn seams: every group of vertices joined (directly or through
// chains of seam pairs, e.g. an armpit where four panels meet) becomes one
// vertex. The map from old to new indices lets the solver carry its state
// and springs over to the welded mesh.

#include <cstdint>
#include <vector>

#include "core/garment/seam.h"

namespace mq {

struct SeamWeld {
  std::vector<uint32_t> newIndex;   // per old vertex
  std::vector<uint32_t> groupSize;  // per new vertex: how many old vertices it merges
  size_t newVertexCount() const { return groupSize.size(); }
  size_t mergedAway() const { return newIndex.size() - groupSize.size(); }
};

// New vertices are numbered in the order of their first old vertex.
SeamWeld computeSeamWeld(size_t vertexCount, const std::vector<VertexPair>& pairs);

// Per-vertex values with `components` floats each, averaged over each group.
std::vector<float> weldAverage(const SeamWeld& weld, const std::vector<float>& values, int components);
// Per-vertex values summed over each group (masses).
std::vector<float> weldSum(const SeamWeld& weld, const std::vector<float>& values);
// Remaps triangles and drops those that collapse (two corners welded together).
std::vector<uint32_t> weldTriangles(const SeamWeld& weld, const std::vector<uint32_t>& triangles);

}  // namespace mq
