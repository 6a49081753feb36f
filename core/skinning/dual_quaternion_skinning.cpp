#include "core/skinning/dual_quaternion_skinning.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <glm/gtc/quaternion.hpp>

#include "core/util/thread_pool.h"

namespace mq {
namespace {

constexpr size_t kMinChunk = 4096;
// |A^T A - I| below this counts as rigid: float round-off of a rotation.
constexpr float kRigidTolerance = 1e-4f;

// Polar decomposition A = R S (R a rotation, S symmetric positive).
void polarDecomposition(const glm::mat3& a, glm::mat3& rotation, glm::mat3& stretch) {
  Eigen::Matrix3d m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = a[c][r];
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  const Eigen::Matrix3d v = svd.matrixV();
  Eigen::Vector3d sigma = svd.singularValues();
  if ((u * v.transpose()).determinant() < 0.0) {  // a mirror: keep R proper, S takes the sign
    u.col(2) = -u.col(2);
    sigma(2) = -sigma(2);
  }
  const Eigen::Matrix3d r = u * v.transpose();
  const Eigen::Matrix3d s = v * sigma.asDiagonal() * v.transpose();
  for (int row = 0; row < 3; ++row)
    for (int c = 0; c < 3; ++c) {
      rotation[c][row] = float(r(row, c));
      stretch[c][row] = float(s(row, c));
    }
}

bool isRigid(const glm::mat3& a) {
  const glm::mat3 g = glm::transpose(a) * a;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (std::abs(g[c][r] - (r == c ? 1.0f : 0.0f)) > kRigidTolerance) return false;
  return true;
}

inline void cross(const float* a, const float* b, float* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// K influences and the stretch known at compile time let the compiler unroll
// the blend; K = 0 reads the count at run time.
template <int K, bool Stretched>
void skinRange(size_t begin, size_t end, int k, const uint16_t* jointsOf, const float* weightsOf, const float* dqs,
               const float* stretches, const float* positions, const float* normals, float* outPositions,
               float* outNormals) {
  const int influences = K > 0 ? K : k;
  for (size_t v = begin; v < end; ++v) {
    const uint16_t* joints = jointsOf + v * influences;
    const float* weights = weightsOf + v * influences;
    // The heaviest influence sets the hemisphere the others are brought to.
    int reference = 0;
    float heaviest = weights[0];
    for (int i = 1; i < influences; ++i) {
      reference = weights[i] > heaviest ? i : reference;
      heaviest = std::max(heaviest, weights[i]);
    }
    const float* ref = dqs + 8 * size_t(joints[reference]);
    float b[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    float s[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < influences; ++i) {
      const float* q = dqs + 8 * size_t(joints[i]);
      const float dot = q[0] * ref[0] + q[1] * ref[1] + q[2] * ref[2] + q[3] * ref[3];
      const float sw = std::copysign(weights[i], dot);  // antipodal q_i: same rotation, other hemisphere
      for (int c = 0; c < 8; ++c) b[c] += sw * q[c];
      if (Stretched)
        for (int c = 0; c < 9; ++c) s[c] += weights[i] * stretches[9 * size_t(joints[i]) + c];
    }
    const float len2 = b[0] * b[0] + b[1] * b[1] + b[2] * b[2] + b[3] * b[3];
    const float inv = len2 > 0.0f ? 1.0f / std::sqrt(len2) : 0.0f;
    for (float& c : b) c *= inv;
    const float* r = b;
    const float rw = b[3];
    const float* d = b + 4;
    const float dw = b[7];
    // Translation of the normalised dual quaternion: 2 (rw d - dw r + r x d).
    float rxd[3];
    cross(r, d, rxd);
    float t[3];
    for (int c = 0; c < 3; ++c) t[c] = 2.0f * (rw * d[c] - dw * r[c] + rxd[c]);

    // The rotation as a matrix, applied to the position and the normal.
    const float x2 = r[0] + r[0], y2 = r[1] + r[1], z2 = r[2] + r[2];
    const float xx = r[0] * x2, yy = r[1] * y2, zz = r[2] * z2;
    const float xy = r[0] * y2, xz = r[0] * z2, yz = r[1] * z2;
    const float wx = rw * x2, wy = rw * y2, wz = rw * z2;
    const float m[9] = {1.0f - (yy + zz), xy - wz, xz + wy, xy + wz,         1.0f - (xx + zz),
                        yz - wx,          xz - wy, yz + wx, 1.0f - (xx + yy)};
    float p[3] = {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]};
    if (Stretched) {
      const float q[3] = {p[0], p[1], p[2]};
      for (int row = 0; row < 3; ++row) p[row] = s[3 * row] * q[0] + s[3 * row + 1] * q[1] + s[3 * row + 2] * q[2];
    }
    for (int row = 0; row < 3; ++row)
      outPositions[3 * v + row] = m[3 * row] * p[0] + m[3 * row + 1] * p[1] + m[3 * row + 2] * p[2] + t[row];
    if (!normals) continue;
    float n[3] = {normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]};
    if (Stretched) {
      // S^-T n up to scale: the cofactor matrix of the symmetric S times n.
      const float q[3] = {n[0], n[1], n[2]};
      const float c00 = s[4] * s[8] - s[5] * s[7], c01 = s[5] * s[6] - s[3] * s[8], c02 = s[3] * s[7] - s[4] * s[6];
      const float c10 = s[2] * s[7] - s[1] * s[8], c11 = s[0] * s[8] - s[2] * s[6], c12 = s[1] * s[6] - s[0] * s[7];
      const float c20 = s[1] * s[5] - s[2] * s[4], c21 = s[2] * s[3] - s[0] * s[5], c22 = s[0] * s[4] - s[1] * s[3];
      n[0] = c00 * q[0] + c01 * q[1] + c02 * q[2];
      n[1] = c10 * q[0] + c11 * q[1] + c12 * q[2];
      n[2] = c20 * q[0] + c21 * q[1] + c22 * q[2];
    }
    float out[3];
    for (int row = 0; row < 3; ++row) out[row] = m[3 * row] * n[0] + m[3 * row + 1] * n[1] + m[3 * row + 2] * n[2];
    if (!Stretched) {
      // A rotation keeps the unit normal unit.
      for (int c = 0; c < 3; ++c) outNormals[3 * v + c] = out[c];
      continue;
    }
    const float nlen2 = out[0] * out[0] + out[1] * out[1] + out[2] * out[2];
    const float ninv = nlen2 > 0.0f ? 1.0f / std::sqrt(nlen2) : 0.0f;
    for (int c = 0; c < 3; ++c) outNormals[3 * v + c] = out[c] * ninv;
  }
}

template <bool Stretched>
void skinRangeFor(int k, size_t b, size_t e, const SkinBinding& skin, const DualQuaternionPalette& palette,
                  const float* positions, const float* normals, float* outPositions, float* outNormals) {
  const uint16_t* joints = skin.joints.data();
  const float* weights = skin.weights.data();
  const float* dqs = palette.dualQuaternions.data();
  const float* stretches = palette.stretches.data();
  switch (k) {
    case 1:
      skinRange<1, Stretched>(b, e, k, joints, weights, dqs, stretches, positions, normals, outPositions, outNormals);
      break;
    case 2:
      skinRange<2, Stretched>(b, e, k, joints, weights, dqs, stretches, positions, normals, outPositions, outNormals);
      break;
    case 4:
      skinRange<4, Stretched>(b, e, k, joints, weights, dqs, stretches, positions, normals, outPositions, outNormals);
      break;
    default:
      skinRange<0, Stretched>(b, e, k, joints, weights, dqs, stretches, positions, normals, outPositions, outNormals);
      break;
  }
}

}  // namespace

void buildDualQuaternionPalette(const SkinBinding& skin, const std::vector<glm::mat4>& worldFromBone,
                                DualQuaternionPalette& palette) {
  const size_t joints = skin.jointBones.size();
  palette.dualQuaternions.resize(8 * joints);
  palette.stretches.assign(9 * joints, 0.0f);
  palette.stretched = false;
  for (size_t j = 0; j < joints; ++j) {
    const int bone = skin.jointBones[j];
    const glm::mat4 m =
        (bone >= 0 && bone < static_cast<int>(worldFromBone.size()) ? worldFromBone[bone] : glm::mat4(1.0f)) *
        skin.inverseBind[j];
    const glm::mat3 a(m);
    glm::mat3 rotation = a, stretch(1.0f);
    if (!isRigid(a)) {
      polarDecomposition(a, rotation, stretch);
      palette.stretched = true;
    }
    const glm::quat r = glm::normalize(glm::quat_cast(rotation));
    const glm::vec3 t(m[3]);
    // Dual part: 1/2 (t, 0) * r.
    const glm::quat d = 0.5f * (glm::quat(0.0f, t.x, t.y, t.z) * r);
    float* out = &palette.dualQuaternions[8 * j];
    out[0] = r.x, out[1] = r.y, out[2] = r.z, out[3] = r.w;
    out[4] = d.x, out[5] = d.y, out[6] = d.z, out[7] = d.w;
    float* s = &palette.stretches[9 * j];
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 3; ++c) s[3 * row + c] = stretch[c][row];
  }
}

void skinVerticesDualQuaternion(const SkinBinding& skin, const DualQuaternionPalette& palette, const float* positions,
                                const float* normals, size_t count, float* outPositions, float* outNormals,
                                ThreadPool* pool) {
  const int k = skin.influencesPerVertex;
  auto body = [&](size_t b, size_t e) {
    if (palette.stretched)
      skinRangeFor<true>(k, b, e, skin, palette, positions, normals, outPositions, outNormals);
    else
      skinRangeFor<false>(k, b, e, skin, palette, positions, normals, outPositions, outNormals);
  };
  if (pool)
    pool->parallelFor(0, count, kMinChunk, body);
  else
    body(0, count);
}

}  // namespace mq
