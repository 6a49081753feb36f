#include "core/skeleton/skeleton.h"

#include <stdexcept>

namespace mq {

int Skeleton::addBone(Bone bone) {
  const int index = boneCount();
  if (bone.parent >= index) throw std::invalid_argument("bone '" + bone.name + "' added before its parent");
  bones_.push_back(std::move(bone));
  return index;
}

int Skeleton::findBone(const std::string& name) const {
  for (int i = 0; i < boneCount(); ++i)
    if (bones_[i].name == name) return i;
  return -1;
}

std::vector<int> Skeleton::children(int index) const {
  std::vector<int> result;
  for (int i = 0; i < boneCount(); ++i)
    if (bones_[i].parent == index) result.push_back(i);
  return result;
}

Pose Skeleton::restPose() const {
  Pose pose(bones_.size());
  for (size_t i = 0; i < bones_.size(); ++i) pose[i] = bones_[i].rest;
  return pose;
}

void Skeleton::worldTransforms(const Pose& pose, std::vector<glm::mat4>& out) const {
  out.resize(bones_.size());
  for (size_t i = 0; i < bones_.size(); ++i) {
    const Bone& b = bones_[i];
    const glm::mat4 local = b.parentFromOffset * pose[i].matrix();
    out[i] = b.parent < 0 ? local : out[b.parent] * local;
  }
}

std::vector<glm::mat4> Skeleton::worldTransforms(const Pose& pose) const {
  std::vector<glm::mat4> out;
  worldTransforms(pose, out);
  return out;
}

std::vector<glm::mat4> Skeleton::inverseBindMatrices() const {
  std::vector<glm::mat4> world = worldTransforms(restPose());
  for (glm::mat4& m : world) m = glm::inverse(m);
  return world;
}

}  // namespace mq
