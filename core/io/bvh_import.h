#pragma once
// BVH motion capture: as a character of its own (skeleton + one clip, no
// meshes), or applied to another character's skeleton.
//
// Name-map file (optional), one pair per line, '#' starts a comment:
//     # bvh_joint_name   target_bone_name
//     Hips               pelvis
//     LeftUpLeg          thigh_l
// Map entries win; the other joints are paired by name, then by humanoid
// role (core/io/bone_match.h says how, and reports what was left out).
//
// Retargeting: each driven bone gets the BVH joint's world rotation change
// from the BVH rest pose, applied on top of the bone's own rest world
// orientation, so skeletons whose local axes differ still move alike. Where
// both the bone and the joint have exactly one child, the bone's rest
// direction is first turned onto the joint's (a T-pose motion on an A-pose
// skeleton). The root's displacement from the first frame is scaled by the
// ratio of the two skeletons' heights (over the matched joints); "in place"
// keeps only its vertical part, so a walk walks on the spot.

#include <string>

#include "core/character/character.h"
#include "core/io/bone_match.h"

namespace mq {

// The BVH skeleton (joints in file order, End Sites dropped) with one clip
// named after the file; times are frame * frame time. Throws FileError with
// the line and the problem for malformed files.
Character loadBvhCharacter(const std::string& bvhPath);

struct MotionOptions {
  std::string nameMapPath;  // optional name-map file
  bool inPlace = false;     // drop the root's horizontal translation
};

struct RetargetedMotion {
  Clip clip;
  BoneMatchReport match;
};

// The joint-to-bone pairing alone, without retargeting (for a preview).
// Throws FileError when the BVH or map is malformed.
BoneMatchReport matchBvhMotion(const std::string& bvhPath, const Character& target,
                               const std::string& nameMapPath = "");

// A clip that drives `target`'s skeleton with the BVH motion, and how the
// joints were paired. Throws FileError when the BVH or map is malformed or
// no joint matches a bone.
RetargetedMotion retargetBvhMotion(const std::string& bvhPath, const Character& target,
                                   const MotionOptions& options = {});
Clip importBvhMotion(const std::string& bvhPath, const Character& target, const std::string& nameMapPath = "");

}  // namespace mq
