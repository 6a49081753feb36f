#include "core/character/character.h"

#include "core/character/implicit_body.h"
#include "core/mesh/tangents.h"

#include <cmath>
#include <stdexcept>

namespace mq {

size_t Character::vertexCount() const {
  size_t n = 0;
  for (const Mesh& m : meshes) n += m.vertexCount();
  return n;
}

size_t Character::triangleCount() const {
  size_t n = 0;
  for (const Mesh& m : meshes) n += m.triangleCount();
  return n;
}

int Character::maxInfluences() const {
  int k = 0;
  for (const Mesh& m : meshes) k = std::max(k, m.skin.maxInfluences());
  return k;
}

int Character::findClip(const std::string& nameOrIndex) const {
  for (size_t i = 0; i < clips.size(); ++i)
    if (clips[i].name == nameOrIndex) return static_cast<int>(i);
  char* end = nullptr;
  const long index = std::strtol(nameOrIndex.c_str(), &end, 10);
  if (!nameOrIndex.empty() && end && *end == '\0' && index >= 0 && index < static_cast<long>(clips.size()))
    return static_cast<int>(index);
  return -1;
}

namespace {

// Texture coordinates, tangents and material ranges of one mesh.
void validateSurface(const Mesh& m, size_t materialCount, const std::string& where) {
  const size_t n = m.vertexCount();
  if (!m.uvs.empty() && m.uvs.size() != 2 * n)
    throw std::runtime_error(where + "texture coordinate count differs from vertex count");
  if (!m.uvs1.empty() && m.uvs1.size() != 2 * n)
    throw std::runtime_error(where + "second texture coordinate count differs from vertex count");
  if (!m.tangents.empty() && m.tangents.size() != 4 * n)
    throw std::runtime_error(where + "tangent count differs from vertex count");
  for (const Submesh& r : m.drawRanges()) {
    if (r.material < -1 || r.material >= static_cast<int>(materialCount))
      throw std::runtime_error(where + "material index " + std::to_string(r.material) + " out of range");
    if (static_cast<size_t>(r.firstTriangle) + r.triangleCount > m.triangleCount())
      throw std::runtime_error(where + "a material's triangle range runs past the last triangle");
  }
}

}  // namespace

namespace {

// A uniform scale S conjugates every rigid or affine matrix, S M S^-1: the
// linear part stays, the translation scales.
void scaleTranslation(glm::mat4& m, float factor) { m[3] = glm::vec4(glm::vec3(m[3]) * factor, m[3].w); }

std::shared_ptr<const ImplicitBody> scaledBody(const ImplicitBody& body, float factor) {
  auto scaled = std::make_shared<ImplicitBody>(body);
  scaled->scale(factor);
  return scaled;
}

}  // namespace

void Character::scaleUniformly(float factor) {
  for (Mesh& mesh : meshes) {
    for (float& p : mesh.positions) p *= factor;
    for (MorphTarget& t : mesh.morphTargets)
      for (float& d : t.positionDeltas) d *= factor;
    scaleTranslation(mesh.boneFromMesh, factor);
    for (glm::mat4& m : mesh.skin.inverseBind) scaleTranslation(m, factor);
    mesh.dropSkinningBindings();
    if (mesh.implicitBody) mesh.implicitBody = scaledBody(*mesh.implicitBody, factor);
  }
  for (SkinBinding& skin : skinsBeforeHelpers)
    for (glm::mat4& m : skin.inverseBind) scaleTranslation(m, factor);
  for (int b = 0; b < skeleton.boneCount(); ++b) {
    Bone& bone = skeleton.bone(b);
    bone.rest.translation *= factor;
    scaleTranslation(bone.parentFromOffset, factor);
  }
  for (Clip& clip : clips)
    for (BoneChannel& channel : clip.boneChannels)
      for (float& v : channel.translation.values) v *= factor;
}

void Character::addMissingTangents() {
  for (Mesh& mesh : meshes) {
    if (!mesh.tangents.empty()) continue;
    for (const Submesh& range : mesh.drawRanges()) {
      if (range.material < 0 || range.material >= static_cast<int>(materials.size())) continue;
      const TextureRef& normalMap = materials[range.material].normalTexture;
      const std::vector<float>& uvs = normalMap.texCoord == 1 ? mesh.uvs1 : mesh.uvs;
      if (!normalMap.present() || uvs.size() != 2 * mesh.vertexCount()) continue;
      computeVertexTangents(mesh.positions, mesh.normals, uvs, mesh.triangles, mesh.tangents);
      break;
    }
  }
}

void Character::validate() const {
  const int bones = skeleton.boneCount();
  for (const Mesh& m : meshes) {
    const size_t n = m.vertexCount();
    const std::string where = "mesh '" + m.name + "': ";
    if (m.positions.size() != 3 * n) throw std::runtime_error(where + "position array is not a multiple of 3");
    if (!m.normals.empty() && m.normals.size() != 3 * n)
      throw std::runtime_error(where + "normal count differs from vertex count");
    for (uint32_t i : m.triangles)
      if (i >= n) throw std::runtime_error(where + "triangle index " + std::to_string(i) + " out of range");
    for (float p : m.positions)
      if (!std::isfinite(p)) throw std::runtime_error(where + "non-finite vertex position");
    for (const MorphTarget& t : m.morphTargets)
      if (t.positionDeltas.size() != 3 * n)
        throw std::runtime_error(where + "morph target size differs from vertex count");
    validateSurface(m, materials.size(), where);
    const SkinBinding& s = m.skin;
    if (s.empty()) continue;
    const size_t k = s.influencesPerVertex;
    if (s.joints.size() != n * k || s.weights.size() != n * k)
      throw std::runtime_error(where + "skin weights do not cover every vertex");
    if (s.inverseBind.size() != s.jointBones.size())
      throw std::runtime_error(where + "inverse bind matrix count differs from joint count");
    for (int b : s.jointBones)
      if (b < 0 || b >= bones) throw std::runtime_error(where + "skin joint refers to a missing bone");
    for (uint16_t j : s.joints)
      if (j >= s.jointBones.size()) throw std::runtime_error(where + "vertex joint index out of range");
  }
  for (const Material& material : materials)
    for (const TextureSlot& slot : material.textureSlots())
      if (slot.ref->image >= static_cast<int>(images.size()))
        throw std::runtime_error("material '" + material.name + "': texture refers to a missing image");
  for (const Clip& c : clips) {
    try {
      c.validate();
    } catch (const std::exception& e) {
      throw std::runtime_error("clip '" + c.name + "': " + e.what());
    }
  }
}

Pose samplePose(const Character& character, int clipIndex, float time, const PoseEdits* edits) {
  Pose pose = character.skeleton.restPose();
  if (clipIndex >= 0 && clipIndex < static_cast<int>(character.clips.size()))
    character.clips[clipIndex].applyToPose(time, pose);
  if (edits)
    for (const auto& [bone, rotation] : edits->rotations)
      if (bone >= 0 && bone < static_cast<int>(pose.size()))
        pose[bone].rotation = glm::normalize(pose[bone].rotation * rotation);
  driveHelperBones(character.helperBones, character.skeleton, pose);
  return pose;
}

std::vector<std::vector<float>> sampleMorphWeights(const Character& character, int clipIndex, float time) {
  std::vector<std::vector<float>> weights;
  for (const Mesh& m : character.meshes) weights.push_back(m.morphWeights);
  if (clipIndex >= 0 && clipIndex < static_cast<int>(character.clips.size()))
    character.clips[clipIndex].applyToMorphWeights(time, weights);
  return weights;
}

std::vector<std::vector<float>> boneWeights(const Character& character, int bone) {
  std::vector<std::vector<float>> out;
  for (const Mesh& mesh : character.meshes) out.push_back(mesh.skin.weightsOfBone(bone, mesh.vertexCount()));
  return out;
}

}  // namespace mq
