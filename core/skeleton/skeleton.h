#pragma once
// A skeleton: bones in a hierarchy, each with a rest (bind) local transform.
// World transforms propagate from the roots down:
//   worldFromBone[b] = worldFromBone[parent] * parentFromOffset[b] * local[b]
// where parentFromOffset holds fixed transforms of non-bone nodes that sit
// between a bone and its parent bone in a file's node graph (for a root bone:
// all its non-bone ancestors), identity otherwise.

#include <string>
#include <vector>

#include "core/math/transform.h"

namespace mq {

struct Bone {
  std::string name;
  int parent = -1;                   // index of the parent bone, -1 for a root
  Trs rest;                          // local transform in the rest pose
  glm::mat4 parentFromOffset{1.0f};  // fixed non-bone transforms above it
};

// Local transforms of every bone, indexed like Skeleton::bones.
using Pose = std::vector<Trs>;

class Skeleton {
 public:
  // Adds a bone; its parent must already exist (parents precede children).
  int addBone(Bone bone);

  int boneCount() const { return static_cast<int>(bones_.size()); }
  const Bone& bone(int index) const { return bones_[index]; }
  Bone& bone(int index) { return bones_[index]; }
  const std::vector<Bone>& bones() const { return bones_; }
  int findBone(const std::string& name) const;  // -1 if absent
  std::vector<int> children(int index) const;

  Pose restPose() const;
  // worldFromBone for every bone; bones are stored parents first.
  std::vector<glm::mat4> worldTransforms(const Pose& pose) const;
  void worldTransforms(const Pose& pose, std::vector<glm::mat4>& out) const;
  // boneFromWorld in the rest pose: the inverse bind matrices.
  std::vector<glm::mat4> inverseBindMatrices() const;

 private:
  std::vector<Bone> bones_;
};

}  // namespace mq
