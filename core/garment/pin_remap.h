#pragma once
// Pins are garment-mesh vertex indices, and a rebuilt mesh (a measurement or
// the particle distance changed) numbers its vertices anew. remapPins
// carries each pin to the rebuilt mesh's vertex of the same panel nearest to
// where the pin sat in that panel's pattern, measured relative to the
// panel's pattern bounds: a pin at the top of a panel that got longer stays
// at its top. A panel the rebuilt garment lacks falls back to the nearest
// vertex in the rest pose.
//
//   g.pins.vertices = remapPins(buildGarmentMesh(old), old.pins.vertices, buildGarmentMesh(rebuilt));

#include <cstdint>
#include <vector>

#include "core/garment/garment.h"

namespace mq {

// Sorted, without duplicates (two pins may land on one vertex of a coarser
// mesh). Pins beyond `before`'s vertices are dropped.
std::vector<uint32_t> remapPins(const GarmentMesh& before, const std::vector<uint32_t>& pins, const GarmentMesh& after);

}  // namespace mq
