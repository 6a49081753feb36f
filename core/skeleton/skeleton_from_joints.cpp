#include "core/skeleton/skeleton_from_joints.h"

#include <cmath>

namespace mq {
namespace {

glm::mat3 restFrame(const JointSpec& s) {
  const glm::vec3 y = glm::normalize(s.tail - s.head);
  const glm::vec3 forward = std::abs(y.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  const glm::vec3 x = glm::normalize(glm::cross(y, forward));
  return glm::mat3(x, y, glm::cross(x, y));
}

}  // namespace

Skeleton skeletonFromJoints(const std::vector<JointSpec>& specs) {
  Skeleton skeleton;
  std::vector<glm::mat3> frames;
  for (const JointSpec& s : specs) {
    Bone bone;
    bone.name = s.name;
    bone.parent = skeleton.findBone(s.parent);
    const glm::mat3 frame = restFrame(s);
    glm::mat3 parentFrame(1.0f);
    glm::vec3 parentHead(0.0f);
    if (bone.parent >= 0) parentFrame = frames[bone.parent], parentHead = specs[bone.parent].head;
    const glm::mat3 parentFromWorld = glm::transpose(parentFrame);
    bone.rest.translation = parentFromWorld * (s.head - parentHead);
    bone.rest.rotation = glm::normalize(glm::quat_cast(parentFromWorld * frame));
    skeleton.addBone(bone);
    frames.push_back(frame);
  }
  return skeleton;
}

}  // namespace mq
