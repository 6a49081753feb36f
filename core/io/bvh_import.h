#pragma once
// BVH motion capture: as a character of its own (skeleton + one clip, no
// meshes), or applied to another character's skeleton.
//
// Name-map file (optional), one pair per line, '#' starts a comment:
//     # bvh_joint_name   target_bone_name
//     Hips               pelvis
//     LeftUpLeg          thigh_l
// Without a map, BVH joints drive the target bones of the same name (exact
// match first, then case-insensitive).
//
// Retargeting: each driven bone gets the BVH joint's world rotation change
// from the BVH rest pose, applied on top of the bone's own rest world
// orientation, so skeletons whose local axes differ still move alike. Where
// both the bone and the joint have exactly one child, the bone's rest
// direction is first turned onto the joint's (a T-pose motion on an A-pose
// skeleton). The root's displacement from the first frame is scaled by the
// ratio of the two skeletons' heights (over the matched joints).

#include <string>

#include "core/character/character.h"

namespace mq {

// The BVH skeleton (joints in file order, End Sites dropped) with one clip
// named after the file; times are frame * frame time. Throws FileError with
// the line and the problem for malformed files.
Character loadBvhCharacter(const std::string& bvhPath);

// A clip that drives `target`'s skeleton with the BVH motion. Throws
// FileError when the BVH or map is malformed or no joint matches a bone.
Clip importBvhMotion(const std::string& bvhPath, const Character& target, const std::string& nameMapPath = "");

}  // namespace mq
