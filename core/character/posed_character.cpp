#include "core/character/posed_character.h"

#include <cmath>

#include "core/skinning/section_cones.h"
#include "core/skinning/skin_deformer.h"
#include "core/util/thread_pool.h"

namespace mq {

std::vector<float> concatenatedPositions(const std::vector<PosedMesh>& meshes) {
  std::vector<float> out;
  for (const PosedMesh& m : meshes) out.insert(out.end(), m.positions.begin(), m.positions.end());
  return out;
}

std::vector<uint32_t> concatenatedTriangles(const Character& character) {
  std::vector<uint32_t> out;
  uint32_t offset = 0;
  for (const Mesh& m : character.meshes) {
    for (uint32_t index : m.triangles) out.push_back(index + offset);
    offset += uint32_t(m.vertexCount());
  }
  return out;
}
namespace {

bool anyNonZero(const std::vector<float>& w) {
  for (float x : w)
    if (x != 0.0f) return true;
  return false;
}

// rest + sum_k w_k * delta_k, for positions and normals.
void applyMorphTargets(const Mesh& mesh, const std::vector<float>& weights, std::vector<float>& positions,
                       std::vector<float>& normals) {
  positions = mesh.positions;
  normals = mesh.normals;
  for (size_t t = 0; t < mesh.morphTargets.size() && t < weights.size(); ++t) {
    const float w = weights[t];
    if (w == 0.0f) continue;
    const MorphTarget& target = mesh.morphTargets[t];
    for (size_t i = 0; i < positions.size(); ++i) positions[i] += w * target.positionDeltas[i];
    if (target.normalDeltas.size() == normals.size())
      for (size_t i = 0; i < normals.size(); ++i) normals[i] += w * target.normalDeltas[i];
  }
  // Dual quaternion skinning rotates normals without rescaling them.
  for (size_t i = 0; i + 2 < normals.size(); i += 3) {
    const float len =
        std::sqrt(normals[i] * normals[i] + normals[i + 1] * normals[i + 1] + normals[i + 2] * normals[i + 2]);
    if (len > 0.0f)
      for (int d = 0; d < 3; ++d) normals[i + d] /= len;
  }
}

void transformRigid(const glm::mat4& m, const float* positions, const float* normals, size_t count, float* outPositions,
                    float* outNormals) {
  const glm::mat3 r(m);
  for (size_t v = 0; v < count; ++v) {
    const glm::vec3 p = glm::vec3(m * glm::vec4(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2], 1.0f));
    for (int d = 0; d < 3; ++d) outPositions[3 * v + d] = p[d];
    if (!normals) continue;
    glm::vec3 n = r * glm::vec3(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
    const float len = glm::length(n);
    if (len > 0.0f) n /= len;
    for (int d = 0; d < 3; ++d) outNormals[3 * v + d] = n[d];
  }
}

}  // namespace

void PosedCharacter::skinMesh(SkinningMethod method, const Mesh& mesh, const float* positions, const float* normals,
                              float* outPositions, float* outNormals, ThreadPool* pool) {
  const size_t n = mesh.vertexCount();
  if (method == SkinningMethod::Lbs) {
    buildSkinPalette(mesh.skin, worldFromBone_, palette_);
    skinVertices(mesh.skin, palette_, positions, normals, n, outPositions, outNormals, pool);
    return;
  }
  buildDualQuaternionPalette(mesh.skin, worldFromBone_, dualPalette_);
  skinVerticesDualQuaternion(mesh.skin, dualPalette_, positions, normals, n, outPositions, outNormals, pool);
}

const SectionCones& PosedCharacter::conesOf(size_t meshIndex, const Mesh& mesh, const Skeleton& skeleton) {
  if (mesh.sectionCones) return *mesh.sectionCones;
  ownCones_.resize(std::max(ownCones_.size(), meshIndex + 1));
  ownConesKey_.resize(ownCones_.size(), nullptr);
  if (!ownCones_[meshIndex] || ownConesKey_[meshIndex] != mesh.positions.data()) {
    ownCones_[meshIndex] = bindSectionCones(mesh, skeleton);
    ownConesKey_[meshIndex] = mesh.positions.data();
  }
  return *ownCones_[meshIndex];
}

void prepareSkinning(Character& character) {
  if (character.skinning != SkinningMethod::Cones) return;
  for (Mesh& mesh : character.meshes)
    if (!mesh.skin.empty() && !mesh.sectionCones) mesh.sectionCones = bindSectionCones(mesh, character.skeleton);
}

void PosedCharacter::evaluate(const Character& character, const Pose& pose,
                              const std::vector<std::vector<float>>& morphWeights, ThreadPool* pool) {
  if (character.helperBones.empty()) {
    character.skeleton.worldTransforms(pose, worldFromBone_);
  } else {
    drivenPose_ = pose;
    driveHelperBones(character.helperBones, character.skeleton, drivenPose_);
    character.skeleton.worldTransforms(drivenPose_, worldFromBone_);
  }
  meshes_.resize(character.meshes.size());
  for (size_t i = 0; i < character.meshes.size(); ++i) {
    const Mesh& mesh = character.meshes[i];
    PosedMesh& out = meshes_[i];
    const size_t n = mesh.vertexCount();
    out.positions.resize(3 * n);
    out.normals.resize(mesh.normals.size());

    const std::vector<float>& weights = i < morphWeights.size() ? morphWeights[i] : mesh.morphWeights;
    const float* positions = mesh.positions.data();
    const float* normals = mesh.normals.empty() ? nullptr : mesh.normals.data();
    if (!mesh.morphTargets.empty() && anyNonZero(weights)) {
      applyMorphTargets(mesh, weights, morphedPositions_, morphedNormals_);
      positions = morphedPositions_.data();
      normals = morphedNormals_.empty() ? nullptr : morphedNormals_.data();
    }
    float* outNormals = normals ? out.normals.data() : nullptr;
    if (!mesh.skin.empty()) {
      skinMesh(character.skinning, mesh, positions, normals, out.positions.data(), outNormals, pool);
      if (character.skinning == SkinningMethod::Cones)
        correctWithSectionCones(mesh, conesOf(i, mesh, character.skeleton), worldFromBone_, out.positions.data(),
                                outNormals, pool);
    } else {
      const glm::mat4 worldFromMesh =
          (mesh.attachBone >= 0 ? worldFromBone_[mesh.attachBone] : glm::mat4(1.0f)) * mesh.boneFromMesh;
      transformRigid(worldFromMesh, positions, normals, n, out.positions.data(), outNormals);
    }
  }
}

void PosedCharacter::evaluate(const Character& character, int clipIndex, float time, const PoseEdits* edits,
                              ThreadPool* pool) {
  evaluate(character, samplePose(character, clipIndex, time, edits), sampleMorphWeights(character, clipIndex, time),
           pool);
}

}  // namespace mq
