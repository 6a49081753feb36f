#pragma once
// A mesh with its bit-equal positions merged into one vertex (exporters split
// vertices at UV and normal seams, which leaves a closed surface open), and
// the triangles the merge collapses dropped.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mq {

struct PositionWeld {
  std::vector<uint32_t> representative;  // welded vertex -> its first original vertex
  std::vector<uint32_t> triangles;       // over the welded vertices
  std::vector<uint32_t> weldedIndex;     // original vertex -> welded vertex

  size_t vertexCount() const { return representative.size(); }
  // The welded vertices' positions, read from `positions` (3 floats per
  // original vertex, e.g. the same mesh posed).
  std::vector<float> gather(const std::vector<float>& positions) const;
};

PositionWeld weldByPosition(const std::vector<float>& positions, const std::vector<uint32_t>& triangles);

}  // namespace mq
