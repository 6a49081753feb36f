#pragma once
// A skeleton from joint positions: each bone from its head (its joint) to
// its tail (its child's joint), in world space, with a rest frame whose +Y
// runs along the bone (+X = Y x forward, forward +Z, or +Y for bones that
// point forward). The built-in mannequin and the auto-rig build theirs so.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/skeleton/skeleton.h"

namespace mq {

struct JointSpec {
  std::string name;
  std::string parent;    // empty for a root; parents come first
  glm::vec3 head, tail;  // world space
};

Skeleton skeletonFromJoints(const std::vector<JointSpec>& specs);

}  // namespace mq
