#pragma once
// Thickness of a closed body at each vertex: the distance a ray travels
// inward, along -normal, before it leaves the body again. The skin shader's
// translucency reads it (research brief §5.1; oracle O24: at any vertex of a
// sphere of radius R it is the diameter 2R). Measured once on the rest mesh:
// limbs change little in thickness as they move.

#include <cstdint>
#include <vector>

namespace mq {

// positions, normals: 3 floats per vertex; triangles: 3 indices each.
// A vertex whose inward ray hits nothing (an open mesh) gets `missing`.
// Returns one distance per vertex, in position units.
std::vector<float> inwardThickness(const std::vector<float>& positions, const std::vector<float>& normals,
                                   const std::vector<uint32_t>& triangles, float missing);

}  // namespace mq
