#pragma once
// A character: meshes bound to a skeleton, and animation clips that move it.

#include <map>
#include <string>
#include <vector>

#include "core/animation/clip.h"
#include "core/material/material.h"
#include "core/mesh/mesh.h"
#include "core/skeleton/skeleton.h"
#include "core/skinning/helper_bones.h"
#include "core/skinning/skinning_method.h"

namespace mq {

struct Character {
  std::string name;
  std::string sourcePath;  // file it came from, or "default"
  Skeleton skeleton;
  std::vector<Mesh> meshes;
  std::vector<Clip> clips;
  // Materials the meshes refer to, and the images their textures sample.
  std::vector<Material> materials;
  std::vector<ImageSource> images;
  // Problems the loader worked around (a missing texture image), each naming
  // the file; the caller shows them.
  std::vector<std::string> loadWarnings;
  // For a static mesh whose height suggests other units than metres: what
  // the units may be and the scale that fixes them; empty otherwise.
  std::string unitNotice;
  // How skinned meshes follow the skeleton (PosedCharacter::evaluate).
  SkinningMethod skinning = SkinningMethod::Lbs;
  // Procedural bones at the joints (helper_bones.h), driven by the pose.
  std::vector<HelperBone> helperBones;
  std::vector<SkinBinding> skinsBeforeHelpers;  // per mesh, to take the helpers out again

  size_t vertexCount() const;
  size_t triangleCount() const;
  int maxInfluences() const;
  // Finds a clip by name, or by index when `nameOrIndex` is a number; -1 if absent.
  int findClip(const std::string& nameOrIndex) const;
  // Scales the whole character by `factor` about the origin (units: a file
  // in centimetres takes 0.01): positions, morph offsets, bone and clip
  // translations, bind matrices. Section cones are dropped; an implicit body
  // is scaled with the rest.
  void scaleUniformly(float factor);
  // Normal maps need tangents: a mesh drawn with one and without tangents
  // gets them from the uv set the map samples.
  void addMissingTangents();
  // Checks indices, sizes and finiteness; throws std::runtime_error saying what is wrong.
  void validate() const;
};

// User pose edits layered over the clip: a local rotation per bone applied
// after the clip's rotation (local = T * R_clip * R_edit * S).
struct PoseEdits {
  std::map<int, glm::quat> rotations;
  bool empty() const { return rotations.empty(); }
};

// The local pose of `character` at time t of clip `clipIndex` (-1: rest pose),
// with edits applied.
Pose samplePose(const Character& character, int clipIndex, float time, const PoseEdits* edits = nullptr);
// Each mesh's per-vertex skin weight of `bone` (zeros for a mesh without a
// skin): what a weight view colours.
std::vector<std::vector<float>> boneWeights(const Character& character, int bone);

// Morph weights per mesh at time t (defaults when the clip does not animate them).
std::vector<std::vector<float>> sampleMorphWeights(const Character& character, int clipIndex, float time);

}  // namespace mq
