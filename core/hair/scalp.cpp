#include "core/hair/scalp.h"

#include <cmath>
#include <unordered_map>

#include "core/character/posed_character.h"
#include "core/util/error.h"

namespace mq {

float ScalpSurface::area() const {
  double sum = 0.0;
  for (size_t t = 0; t < triangleCount(); ++t) {
    const glm::vec3 a = position(triangles[3 * t]), b = position(triangles[3 * t + 1]),
                    c = position(triangles[3 * t + 2]);
    sum += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  return float(sum);
}

int dominantBone(const Mesh& mesh, size_t v) {
  const SkinBinding& skin = mesh.skin;
  if (skin.empty()) return mesh.attachBone;
  const int k = skin.influencesPerVertex;
  int bone = -1;
  float best = 0.0f;
  for (int i = 0; i < k; ++i)
    if (skin.weights[k * v + i] > best) {
      best = skin.weights[k * v + i];
      bone = skin.jointBones[skin.joints[k * v + i]];
    }
  return bone;
}

namespace {

bool drivenBy(const Skeleton& skeleton, int bone, int ancestor) {
  for (int b = bone; b >= 0; b = skeleton.bone(b).parent)
    if (b == ancestor) return true;
  return false;
}

// Appends the chosen faces of one posed mesh, sharing vertices between them.
void appendFaces(const Mesh& mesh, const PosedMesh& posed, const std::vector<uint32_t>& faces, ScalpSurface& out) {
  std::unordered_map<uint32_t, uint32_t> remap;
  for (uint32_t f : faces)
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.triangles[3 * f + k];
      auto [it, inserted] = remap.try_emplace(v, uint32_t(out.positions.size() / 3));
      if (inserted) {
        for (int d = 0; d < 3; ++d) out.positions.push_back(posed.positions[3 * v + d]);
        for (int d = 0; d < 3; ++d) out.normals.push_back(posed.normals.empty() ? 0.0f : posed.normals[3 * v + d]);
      }
      out.triangles.push_back(it->second);
    }
}

std::vector<uint32_t> taggedFaces(const Mesh& mesh) {
  std::vector<uint32_t> faces;
  if (mesh.vertexTags.size() != mesh.vertexCount()) return faces;
  for (uint32_t f = 0; f < mesh.triangleCount(); ++f) {
    bool all = true;
    for (int k = 0; k < 3; ++k) all &= mesh.vertexTags[mesh.triangles[3 * f + k]] == TagScalp;
    if (all) faces.push_back(f);
  }
  return faces;
}

std::vector<uint32_t> coneFaces(const Character& character, const Mesh& mesh, const PosedMesh& posed,
                                const ScalpRegion& region, int bone, const glm::vec3& apex) {
  std::vector<uint32_t> faces;
  const glm::vec3 axis = glm::normalize(region.axis);
  const float cosLimit = std::cos(glm::radians(region.angleDegrees));
  for (uint32_t f = 0; f < mesh.triangleCount(); ++f) {
    glm::vec3 centre(0.0f);
    bool driven = true;
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.triangles[3 * f + k];
      driven &= drivenBy(character.skeleton, dominantBone(mesh, v), bone);
      centre += glm::vec3(posed.positions[3 * v], posed.positions[3 * v + 1], posed.positions[3 * v + 2]) / 3.0f;
    }
    const glm::vec3 d = centre - apex;
    if (driven && glm::dot(d, axis) >= cosLimit * glm::length(d)) faces.push_back(f);
  }
  return faces;
}

}  // namespace

ScalpSurface extractScalp(const Character& character, const ScalpRegion& region) {
  PosedCharacter posed;
  posed.evaluate(character, -1, 0.0f, nullptr, nullptr);
  ScalpSurface out;
  switch (region.kind) {
    case ScalpRegion::Kind::Tagged:
      for (size_t m = 0; m < character.meshes.size(); ++m)
        appendFaces(character.meshes[m], posed.meshes()[m], taggedFaces(character.meshes[m]), out);
      if (out.empty())
        throw Error(
            "character '" + character.name +
            "' has no faces tagged as scalp: give the scene's hair section a scalp region, e.g. "
            "\"scalp\": {\"kind\": \"bone_cone\", \"bone\": \"<head bone>\", \"axis\": [0, 1, 0], \"angle\": 70}");
      break;
    case ScalpRegion::Kind::BoneCone: {
      const int bone = character.skeleton.findBone(region.bone);
      if (bone < 0) throw Error("character '" + character.name + "' has no bone named '" + region.bone + "'");
      const glm::vec3 apex(posed.worldFromBone()[bone][3]);
      for (size_t m = 0; m < character.meshes.size(); ++m)
        appendFaces(character.meshes[m], posed.meshes()[m],
                    coneFaces(character, character.meshes[m], posed.meshes()[m], region, bone, apex), out);
      if (out.empty())
        throw Error("no face of character '" + character.name + "' is driven by '" + region.bone + "' within " +
                    std::to_string(region.angleDegrees) + " degrees of the scalp axis");
      break;
    }
    case ScalpRegion::Kind::Faces: {
      if (region.mesh < 0 || size_t(region.mesh) >= character.meshes.size())
        throw Error("scalp mesh index " + std::to_string(region.mesh) + " is out of range");
      const Mesh& mesh = character.meshes[region.mesh];
      for (uint32_t f : region.faces)
        if (f >= mesh.triangleCount()) throw Error("scalp face " + std::to_string(f) + " is out of range");
      appendFaces(mesh, posed.meshes()[region.mesh], region.faces, out);
      if (out.empty()) throw Error("the scalp face list is empty");
      break;
    }
  }
  // Normals from the scalp's own triangles when the posed mesh had none.
  bool haveNormals = false;
  for (float n : out.normals) haveNormals |= n != 0.0f;
  if (!haveNormals) computeVertexNormals(out.positions, out.triangles, out.normals);
  return out;
}

}  // namespace mq
