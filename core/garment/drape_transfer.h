#pragma once
// A drape carried from a garment's mesh to the mesh rebuilt after a pattern
// edit (a measurement, the particle distance): each new vertex takes the
// draped position of the same relative place in its panel's pattern,
// interpolated over the old mesh's triangle there. The two sides of a seam
// land together again, so the rebuilt garment continues from the drape
// (GarmentSimulation::startFromDrape) instead of being sewn from flat panels.
//
//   std::vector<float> warm = transferDrape(oldMesh, simulation.positions(), newMesh);

#include <vector>

#include "core/garment/garment.h"

namespace mq {

// `drape`: 3 floats per vertex of `before`. Returns 3 per vertex of `after`.
// Meshes without pattern coordinates, and panels the old mesh lacks, take
// the drape of the nearest old vertex in the rest placement. Throws Error
// when `drape` does not fit `before`.
std::vector<float> transferDrape(const GarmentMesh& before, const std::vector<float>& drape, const GarmentMesh& after);

}  // namespace mq
