#pragma once
// Painting the scalp with a brush: the region becomes an explicit face list
// on one mesh, and a dab adds (or erases) the faces whose centre lies within
// the brush's radius of the point under the cursor. Works on any mesh, a
// static head scan included; positions are the mesh as shown (posed).

#include <vector>

#include <glm/glm.hpp>

#include "core/character/character.h"
#include "core/hair/scalp.h"

namespace mq {

// `region` as a face list (Kind::Faces) on the mesh holding most of its
// faces; an empty face list on mesh 0 when the region has no face.
ScalpRegion scalpAsFaces(const Character& character, const ScalpRegion& region);

// The mesh a dab at `point` paints on: the one with the vertex nearest to it
// (meshPositions: each mesh's positions as shown). -1 when there is none.
int meshUnderBrush(const std::vector<std::vector<float>>& meshPositions, const glm::vec3& point);

// One dab on mesh `mesh` (its triangles, its positions as shown): faces
// whose centre is within `radius` of `point` are added, or removed with
// `erase`. A region on another mesh starts over on this one.
ScalpRegion paintScalp(const ScalpRegion& region, int mesh, const std::vector<uint32_t>& triangles,
                       const std::vector<float>& positions, const glm::vec3& point, float radius, bool erase);

}  // namespace mq
