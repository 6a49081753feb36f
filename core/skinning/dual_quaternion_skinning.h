#pragma once
// Dual quaternion skinning (Kavan, Collins, Zara, O'Sullivan, "Geometric
// skinning with approximate dual quaternion blending", ACM TOG 27(4), 2008).
// Each skinning matrix worldFromMesh_j = [A_j | t_j] is split by the polar
// decomposition A_j = R_j S_j into a rigid part (R_j, t_j), held as a unit
// dual quaternion q_j, and a stretch S_j (identity for ordinary rigs). Per
// vertex:
//   b = sum_i w_i s_i q_i,  s_i = +-1 so every q_i lies in q_ref's hemisphere
//   p' = rigid(b / |b.real|) (sum_i w_i S_i) p
//   n' = rotation(b / |b.real|) (sum_i w_i S_i)^-T n
// Unlike LBS, the blended transform stays rigid, so a bend keeps the joint's
// section and a twist does not collapse to a candy wrapper.

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/mesh.h"

namespace mq {

class ThreadPool;

struct DualQuaternionPalette {
  // 8 floats per skin joint: the real part (x, y, z, w) then the dual part.
  std::vector<float> dualQuaternions;
  // 9 floats per skin joint, S_j row-major; used only when stretched.
  std::vector<float> stretches;
  bool stretched = false;  // some S_j differs from the identity
};

void buildDualQuaternionPalette(const SkinBinding& skin, const std::vector<glm::mat4>& worldFromBone,
                                DualQuaternionPalette& palette);

// Deforms `count` vertices; normals/outNormals may be null. Threaded results
// equal single-threaded ones bit for bit (vertices are independent).
void skinVerticesDualQuaternion(const SkinBinding& skin, const DualQuaternionPalette& palette, const float* positions,
                                const float* normals, size_t count, float* outPositions, float* outNormals,
                                ThreadPool* pool);

}  // namespace mq
