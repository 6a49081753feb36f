#pragma once
// A triangle mesh as flat float arrays (structure of arrays), with optional
// morph targets and a skin binding. Positions and normals are the rest (bind)
// shape in the mesh's own space.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace mq {

struct SectionCones;
class ImplicitBody;

struct MorphTarget {
  std::string name;
  std::vector<float> positionDeltas;  // 3 per vertex
  std::vector<float> normalDeltas;    // 3 per vertex, may be empty
};

// Smooth skinning data: K influences per vertex (K = influencesPerVertex),
// unused slots have weight 0; weights of a vertex sum to 1.
struct SkinBinding {
  int influencesPerVertex = 0;
  std::vector<uint16_t> joints;        // vertices * K, indices into jointBones
  std::vector<float> weights;          // vertices * K
  std::vector<int> jointBones;         // skin joint -> skeleton bone
  std::vector<glm::mat4> inverseBind;  // skin joint -> boneFromMesh at bind time

  bool empty() const { return influencesPerVertex == 0; }
  // Largest number of non-zero weights on one vertex.
  int maxInfluences() const;
  // Divides each vertex's weights by their sum (vertices with sum 0 keep 0).
  void normalise();
  // Keeps the `k` largest influences per vertex, then renormalises.
  void limitInfluences(int k);
  // Rigid skinning: each vertex follows its heaviest joint alone.
  void makeRigid();
  // Each vertex's weight of skeleton bone `bone` (0 where it has none).
  std::vector<float> weightsOfBone(int bone, size_t vertices) const;
};

struct Submesh {
  uint32_t firstTriangle = 0;
  uint32_t triangleCount = 0;
  int material = -1;  // index into Character::materials; -1: none
};

struct Mesh {
  std::string name;
  std::vector<float> positions;  // 3 per vertex
  std::vector<float> normals;    // 3 per vertex
  // Texture coordinates as glTF has them: (0, 0) is the image's top left.
  std::vector<float> uvs;           // 2 per vertex, may be empty (texture coordinate set 0)
  std::vector<float> uvs1;          // 2 per vertex, may be empty (set 1)
  std::vector<float> tangents;      // 4 per vertex (xyz, handedness w), may be empty
  std::vector<uint32_t> triangles;  // 3 per triangle
  std::vector<MorphTarget> morphTargets;
  std::vector<float> morphWeights;  // default weight per target
  SkinBinding skin;
  // Bind-time data of the cone-corrected skinning (built on demand).
  std::shared_ptr<const SectionCones> sectionCones;
  // The implicit body the skin was polygonised from, in bind space (the
  // built-in mannequin's): the ground truth of the skin metric M6. Null for
  // other meshes.
  std::shared_ptr<const ImplicitBody> implicitBody;
  // Unskinned meshes: world = worldFromBone[attachBone] * boneFromMesh, or
  // boneFromMesh alone when attachBone is -1.
  int attachBone = -1;
  glm::mat4 boneFromMesh{1.0f};
  // Per-vertex region tags (e.g. the scalp for hair); may be empty.
  std::vector<uint8_t> vertexTags;
  glm::vec3 baseColor{0.8f, 0.8f, 0.8f};
  // Triangle ranges drawn with one material each (a glTF mesh's primitives);
  // empty: the whole mesh with `material`.
  std::vector<Submesh> submeshes;
  int material = -1;  // index into Character::materials; -1: none (baseColor)

  size_t vertexCount() const { return positions.size() / 3; }
  // Forgets what the skinning methods bound on the skin (after the weights,
  // the skeleton or the rest shape changed): prepareSkinning binds again.
  void dropSkinningBindings() { sectionCones.reset(); }
  size_t triangleCount() const { return triangles.size() / 3; }
  // The submeshes, or one covering the whole mesh with `material`.
  std::vector<Submesh> drawRanges() const;
  glm::vec3 position(size_t v) const { return {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]}; }
};

enum VertexTag : uint8_t { TagNone = 0, TagScalp = 1 };

// Area-weighted vertex normals of a triangle soup over flat arrays.
void computeVertexNormals(const std::vector<float>& positions, const std::vector<uint32_t>& triangles,
                          std::vector<float>& normals);

struct Aabb {
  glm::vec3 min{1e30f};
  glm::vec3 max{-1e30f};
  void extend(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  bool valid() const { return min.x <= max.x; }
  glm::vec3 center() const { return 0.5f * (min + max); }
  float diagonal() const { return valid() ? glm::length(max - min) : 0.0f; }
};
Aabb boundsOf(const std::vector<float>& positions);

}  // namespace mq
