#pragma once
// Which bone of a humanoid skeleton plays which role (pelvis, spine, chest,
// neck, head; clavicle, upper arm, forearm, hand; thigh, shin, foot), so
// tools made for the default mannequin (built-in garments) work on imported
// characters. Bone names win when they match common aliases ("upperarm_l",
// "mixamorig:LeftArm", ...); the skeleton's structure in its rest pose fills
// in the rest: the legs are the two chains from the hips going down, the
// spine the chain going highest, the arms the two chains branching sideways
// from it. Y is up; index 0 of a pair is the character's left, +X for a
// character facing +Z (the default mannequin's convention).

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/skeleton/skeleton.h"

namespace mq {

struct HumanoidBones {
  int pelvis = -1, spine = -1, chest = -1, neck = -1;
  int head = -1;            // optional: -1 when the neck is the top of the spine
  int clavicle[2]{-1, -1};  // optional
  int upperArm[2]{-1, -1}, forearm[2]{-1, -1}, hand[2]{-1, -1};
  int thigh[2]{-1, -1}, shin[2]{-1, -1}, foot[2]{-1, -1};
  // Where the toes point (unit, horizontal) when the feet have a child
  // joint; zero otherwise.
  glm::vec3 facing{0.0f};
};

// Roles for the skeleton with the given rest world transforms (one per bone,
// e.g. Skeleton::worldTransforms(restPose())). Throws mq::Error naming the
// first role it cannot find and why ("no bone for the upper arm (left): ...").
HumanoidBones findHumanoidBones(const Skeleton& skeleton, const std::vector<glm::mat4>& restWorld);

// The bone a common alias names for `role` ("pelvis", "spine", "chest",
// "neck", "head", "clavicle", "upperarm", "forearm", "hand", "thigh", "shin",
// "foot"), on `side` (0 left, 1 right) for the paired ones; -1 if none.
int findBoneByRoleName(const Skeleton& skeleton, const std::string& role, int side);

}  // namespace mq
