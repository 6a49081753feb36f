#pragma once
// Hair roots spread over the scalp by Poisson-disk sampling: no two roots
// closer than a minimum distance, so the hair has no bald patches and no
// clusters. Dart throwing over dense random candidates on the triangles,
// with a 2D grid over the scalp's projection along its mean normal (an
// orthographic projection never lengthens a distance, so the 3x3 cells
// around a candidate hold every root within the minimum distance).

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/hair/scalp.h"

namespace mq {

struct HairRoots {
  std::vector<float> positions;  // 3 per root, world space
  std::vector<float> normals;    // 3 per root, unit
  float minDistance = 0.0f;      // the Poisson-disk radius they respect

  size_t size() const { return positions.size() / 3; }
  glm::vec3 position(size_t i) const { return {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]}; }
  glm::vec3 normal(size_t i) const { return {normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]}; }
};

// Roots for a density in hairs per cm^2, at most maxCount.
size_t rootCountForDensity(const ScalpSurface& scalp, float hairsPerCm2, size_t maxCount);

// Exactly `count` roots (fewer only if the scalp is degenerate), deterministic for a seed.
HairRoots sampleRoots(const ScalpSurface& scalp, size_t count, uint32_t seed);

}  // namespace mq
