#pragma once
// The deformed (posed) meshes of a character: morph targets, then skinning,
// into world space. Buffers are kept between frames so evaluation allocates
// nothing after the first call.

#include <vector>

#include "core/character/character.h"
#include "core/skinning/dual_quaternion_skinning.h"

namespace mq {

class ThreadPool;

struct PosedMesh {
  std::vector<float> positions;  // world space, 3 per vertex
  std::vector<float> normals;
};

// The posed meshes as one body (what cloth and hair collide with): their
// positions one after the other, and the character's triangles indexing them.
std::vector<float> concatenatedPositions(const std::vector<PosedMesh>& meshes);
std::vector<uint32_t> concatenatedTriangles(const Character& character);

// Binds ahead of time what the character's skinning method needs (section
// cones), so that posing it does not.
void prepareSkinning(Character& character);

class PosedCharacter {
 public:
  // Poses `character` with local bone transforms `pose` and per-mesh morph
  // weights (empty: the meshes' defaults).
  void evaluate(const Character& character, const Pose& pose, const std::vector<std::vector<float>>& morphWeights,
                ThreadPool* pool);
  // Convenience: clip + time + edits.
  void evaluate(const Character& character, int clipIndex, float time, const PoseEdits* edits, ThreadPool* pool);

  const std::vector<PosedMesh>& meshes() const { return meshes_; }
  const std::vector<glm::mat4>& worldFromBone() const { return worldFromBone_; }

 private:
  void skinMesh(SkinningMethod method, const Mesh& mesh, const float* positions, const float* normals,
                float* outPositions, float* outNormals, ThreadPool* pool);
  // The mesh's section cones, bound here once when the character has none.
  const SectionCones& conesOf(size_t meshIndex, const Mesh& mesh, const Skeleton& skeleton);

  std::vector<PosedMesh> meshes_;
  std::vector<glm::mat4> worldFromBone_;
  std::vector<float> palette_;
  DualQuaternionPalette dualPalette_;
  std::vector<std::shared_ptr<const SectionCones>> ownCones_;  // per mesh, for characters bound without cones
  std::vector<const float*> ownConesKey_;                      // the rest positions they were bound on
  std::vector<float> morphedPositions_, morphedNormals_;
  Pose drivenPose_;  // the pose with its helper bones driven
};

}  // namespace mq
