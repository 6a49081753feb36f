#pragma once
// The k nearest points of a point set to each of many query points (a k-d
// tree, nanoflann): garment vertices to body vertices, a rebuilt mesh's
// vertices to the old one's.

#include <cstdint>
#include <vector>

namespace mq {

// queries and set: 3 floats per point. Returns k indices into `set` per
// query, nearest first (fewer than k only when the set is smaller; empty
// when the set is).
std::vector<uint32_t> nearestPoints(const std::vector<float>& queries, const std::vector<float>& set, int k);

}  // namespace mq
