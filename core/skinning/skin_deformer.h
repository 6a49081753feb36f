#pragma once
// Linear blend skinning of positions and normals (smooth skinning; rigid
// skinning is the one-influence case):
//   p = sum_i w_i * (worldFromBone_i * boneFromMesh_i) p_bind
//   n = normalise(sum_i w_i * R_i n_bind)   (R_i: the rotation parts)
// The hot loop runs over flat arrays and splits vertices across threads.

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/mesh.h"

namespace mq {

class ThreadPool;

// Skinning matrices of one skin as 3x4 row-major blocks (12 floats each):
// worldFromMesh_j = worldFromBone[jointBones[j]] * inverseBind[j].
void buildSkinPalette(const SkinBinding& skin, const std::vector<glm::mat4>& worldFromBone,
                      std::vector<float>& palette);

// Deforms `count` vertices. normals/outNormals may be null.
// pool == nullptr runs on the calling thread.
void skinVertices(const SkinBinding& skin, const std::vector<float>& palette, const float* positions,
                  const float* normals, size_t count, float* outPositions, float* outNormals, ThreadPool* pool);

}  // namespace mq
