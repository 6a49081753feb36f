#include "ui/garment/held_drape.h"

#include <algorithm>

#include "core/garment/drape_transfer.h"

namespace mq::ui {

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
