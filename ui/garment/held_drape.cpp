#include "ui/garment/held_drape.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <glm/glm.hpp>

#include "core/garment/drape_transfer.h"

namespace mq::ui {

std::vector<uint32_t> nearestBodyVertices(const std::vector<float>& garment, const std::vector<float>& body) {
  constexpr float kCell = 0.04f;
  std::unordered_map<int64_t, std::vector<uint32_t>> grid;
  auto cellOf = [](float x) { return int64_t(std::floor(x / kCell)); };
  auto key = [](int64_t x, int64_t y, int64_t z) { return (x & 0x1fffff) | ((y & 0x1fffff) << 21) | ((z & 0x1fffff) << 42); };
  for (size_t v = 0; v < body.size() / 3; ++v)
    grid[key(cellOf(body[3 * v]), cellOf(body[3 * v + 1]), cellOf(body[3 * v + 2]))].push_back(uint32_t(v));
  std::vector<uint32_t> nearest(garment.size() / 3, 0);
  if (body.empty()) return nearest;
  for (size_t g = 0; g < nearest.size(); ++g) {
    const glm::vec3 p(garment[3 * g], garment[3 * g + 1], garment[3 * g + 2]);
    const int64_t cx = cellOf(p.x), cy = cellOf(p.y), cz = cellOf(p.z);
    float best = INFINITY;
    for (int64_t ring = 0; ring < 16; ++ring) {
      for (int64_t x = cx - ring; x <= cx + ring; ++x)
        for (int64_t y = cy - ring; y <= cy + ring; ++y)
          for (int64_t z = cz - ring; z <= cz + ring; ++z) {
            if (std::max({std::abs(x - cx), std::abs(y - cy), std::abs(z - cz)}) != ring) continue;
            const auto cell = grid.find(key(x, y, z));
            if (cell == grid.end()) continue;
            for (uint32_t b : cell->second) {
              const glm::vec3 d = glm::vec3(body[3 * b], body[3 * b + 1], body[3 * b + 2]) - p;
              const float d2 = glm::dot(d, d);
              if (d2 < best) best = d2, nearest[g] = b;
            }
          }
      if (best < (ring * kCell) * (ring * kCell)) break;  // nothing in a further ring can be nearer
    }
  }
  return nearest;
}

HeldDrape HeldDrape::rebuiltAs(const GarmentMesh& before, const GarmentMesh& after) const {
  return HeldDrape(transferDrape(before, positions(), after), body());
}

void DrapeMemory::remember(const std::string& key, const HeldDrape& drape) {
  kept_.erase(std::remove_if(kept_.begin(), kept_.end(), [&](const auto& k) { return k.first == key; }), kept_.end());
  kept_.insert(kept_.begin(), {key, drape});
  if (kept_.size() > kKept) kept_.erase(kept_.begin() + kKept, kept_.end());
}

const HeldDrape* DrapeMemory::recall(const std::string& key) const {
  for (const auto& [k, drape] : kept_)
    if (k == key) return &drape;
  return nullptr;
}

}  // namespace mq::ui
