#include "core/mesh/position_weld.h"

#include <array>
#include <cstring>
#include <map>

namespace mq {

std::vector<float> PositionWeld::gather(const std::vector<float>& positions) const {
  std::vector<float> out(3 * representative.size());
  for (size_t i = 0; i < representative.size(); ++i)
    for (int d = 0; d < 3; ++d) out[3 * i + d] = positions[3 * size_t(representative[i]) + d];
  return out;
}

PositionWeld weldByPosition(const std::vector<float>& positions, const std::vector<uint32_t>& triangles) {
  PositionWeld weld;
  std::map<std::array<uint32_t, 3>, uint32_t> byBits;
  std::vector<uint32_t>& weldedOf = weld.weldedIndex;
  weldedOf.resize(positions.size() / 3);
  for (size_t v = 0; v < weldedOf.size(); ++v) {
    std::array<uint32_t, 3> bits;
    std::memcpy(bits.data(), &positions[3 * v], sizeof bits);
    auto [it, inserted] = byBits.try_emplace(bits, uint32_t(weld.representative.size()));
    if (inserted) weld.representative.push_back(uint32_t(v));
    weldedOf[v] = it->second;
  }
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const uint32_t a = weldedOf[triangles[t]], b = weldedOf[triangles[t + 1]], c = weldedOf[triangles[t + 2]];
    if (a != b && b != c && a != c) weld.triangles.insert(weld.triangles.end(), {a, b, c});
  }
  return weld;
}

}  // namespace mq
