#pragma once
// Which joint of a motion's skeleton (a BVH) drives which bone of a
// character, and which are left out on either side. The CLI prints the
// summary and the editor's Apply Motion dialog shows the whole report, so a
// motion that moves only part of a character says so.
//
// Joints are paired in this order; each joint and each bone is used once:
//   1. the name-map file, when one is given (lines "bvh_joint target_bone";
//      see core/io/bvh_import.h);
//   2. the same name (exact, then ignoring case);
//   3. the same humanoid role (pelvis, spine, chest, neck, head, clavicle,
//      upper arm, forearm, hand, thigh, shin, foot) as found on each skeleton
//      by core/skeleton/humanoid_roles.h, from names and structure. Skipped
//      for a skeleton that is not a humanoid.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "core/skeleton/skeleton.h"

namespace mq {

enum class MatchSource { None, Map, Name, Role };

struct JointMatch {
  std::string joint;  // the motion's joint name
  int parent = -1;    // index of its parent joint in the report, -1 for a root
  int bone = -1;      // the character's bone it drives, -1 for none
  MatchSource source = MatchSource::None;
  std::string role;  // for MatchSource::Role: "upper arm (left)"
};

struct BoneMatchReport {
  std::vector<JointMatch> joints;            // the motion's skeleton, parents first
  std::vector<std::string> unmatchedJoints;  // joints that drive nothing, in file order
  std::vector<std::string> unmatchedBones;   // character bones no joint drives
  int characterBoneCount = 0;

  int matchedCount() const;
  // The character bone driven by each joint (-1: none), indexed like `joints`.
  std::vector<int> boneOfJoint() const;
  // "matched 19 of 31 bones; unmatched: LHipJoint, RHipJoint; not driven on
  // the character: toes_l, toes_r". Lists longer than `maxNames` end in
  // "and N more".
  std::string summary(size_t maxNames = std::numeric_limits<size_t>::max()) const;
};

// Pairs `motion`'s joints with `character`'s bones (rest poses of both are
// used for the roles). Throws FileError for an unreadable or malformed map,
// or one naming a bone the character lacks.
BoneMatchReport matchBones(const Skeleton& motion, const Skeleton& character, const std::string& mapPath = "");

// "name map", "same name", "humanoid role" (for the editor's list).
const char* matchSourceName(MatchSource source);

}  // namespace mq
