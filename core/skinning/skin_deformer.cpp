#include "core/skinning/skin_deformer.h"

#include <cmath>

#include "core/util/thread_pool.h"

namespace mq {
namespace {

constexpr size_t kMinChunk = 4096;

// K influences known at compile time lets the compiler unroll and vectorise
// the 12-float blend.
template <int K>
void skinRange(size_t begin, size_t end, int k, const uint16_t* joints, const float* weights, const float* palette,
               const float* positions, const float* normals, float* outPositions, float* outNormals) {
  const int influences = K > 0 ? K : k;
  for (size_t v = begin; v < end; ++v) {
    float m[12] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < influences; ++i) {
      const float w = weights[v * influences + i];
      const float* p = palette + 12 * size_t(joints[v * influences + i]);
      for (int j = 0; j < 12; ++j) m[j] += w * p[j];
    }
    const float x = positions[3 * v], y = positions[3 * v + 1], z = positions[3 * v + 2];
    outPositions[3 * v] = m[0] * x + m[1] * y + m[2] * z + m[3];
    outPositions[3 * v + 1] = m[4] * x + m[5] * y + m[6] * z + m[7];
    outPositions[3 * v + 2] = m[8] * x + m[9] * y + m[10] * z + m[11];
    if (!normals) continue;
    const float a = normals[3 * v], b = normals[3 * v + 1], c = normals[3 * v + 2];
    const float nx = m[0] * a + m[1] * b + m[2] * c;
    const float ny = m[4] * a + m[5] * b + m[6] * c;
    const float nz = m[8] * a + m[9] * b + m[10] * c;
    const float len2 = nx * nx + ny * ny + nz * nz;
    const float inv = len2 > 0.0f ? 1.0f / std::sqrt(len2) : 0.0f;
    outNormals[3 * v] = nx * inv;
    outNormals[3 * v + 1] = ny * inv;
    outNormals[3 * v + 2] = nz * inv;
  }
}

}  // namespace

void buildSkinPalette(const SkinBinding& skin, const std::vector<glm::mat4>& worldFromBone,
                      std::vector<float>& palette) {
  palette.resize(12 * skin.jointBones.size());
  for (size_t j = 0; j < skin.jointBones.size(); ++j) {
    const int bone = skin.jointBones[j];
    const glm::mat4 worldFromBind =
        (bone >= 0 && bone < static_cast<int>(worldFromBone.size()) ? worldFromBone[bone] : glm::mat4(1.0f)) *
        skin.inverseBind[j];
    float* out = &palette[12 * j];
    for (int row = 0; row < 3; ++row)
      for (int col = 0; col < 4; ++col) out[4 * row + col] = worldFromBind[col][row];
  }
}

void skinVertices(const SkinBinding& skin, const std::vector<float>& palette, const float* positions,
                  const float* normals, size_t count, float* outPositions, float* outNormals, ThreadPool* pool) {
  const int k = skin.influencesPerVertex;
  const uint16_t* joints = skin.joints.data();
  const float* weights = skin.weights.data();
  const float* pal = palette.data();
  auto body = [&](size_t b, size_t e) {
    switch (k) {
      case 1:
        skinRange<1>(b, e, k, joints, weights, pal, positions, normals, outPositions, outNormals);
        break;
      case 2:
        skinRange<2>(b, e, k, joints, weights, pal, positions, normals, outPositions, outNormals);
        break;
      case 4:
        skinRange<4>(b, e, k, joints, weights, pal, positions, normals, outPositions, outNormals);
        break;
      case 8:
        skinRange<8>(b, e, k, joints, weights, pal, positions, normals, outPositions, outNormals);
        break;
      default:
        skinRange<0>(b, e, k, joints, weights, pal, positions, normals, outPositions, outNormals);
        break;
    }
  };
  if (pool)
    pool->parallelFor(0, count, kMinChunk, body);
  else
    body(0, count);
}

}  // namespace mq
