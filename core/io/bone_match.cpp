#include "core/io/bone_match.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>

#include "core/io/file_bytes.h"
#include "core/skeleton/humanoid_roles.h"
#include "core/util/error.h"

namespace mq {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

struct MapEntry {
  std::string bone;
  int line = 0;
};

// bvh joint name -> target bone name and the line that says so.
std::map<std::string, MapEntry> readNameMap(const std::string& path) {
  std::map<std::string, MapEntry> map;
  std::istringstream in(loadFileText(path));
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string s; words >> s;) w.push_back(s);
    if (w.empty()) continue;
    if (w.size() != 2)
      throw FileError(path, "line " + std::to_string(number) + ": expected 'bvh_joint_name target_bone_name', found " +
                                std::to_string(w.size()) + " word(s)");
    map.emplace(w[0], MapEntry{w[1], number});
  }
  return map;
}

// Builds the pairing one rule at a time; a joint or bone once paired stays so.
class Matcher {
 public:
  Matcher(const Skeleton& motion, const Skeleton& character) : motion_(motion), character_(character) {
    report_.characterBoneCount = character.boneCount();
    for (const Bone& joint : motion.bones()) {
      JointMatch match;
      match.joint = joint.name;
      match.parent = joint.parent;
      report_.joints.push_back(std::move(match));
    }
    taken_.assign(character.boneCount(), false);
  }

  void byMap(const std::string& path) {
    const auto map = readNameMap(path);
    for (const auto& [joint, entry] : map)
      if (character_.findBone(entry.bone) < 0)
        throw FileError(path,
                        "line " + std::to_string(entry.line) + ": the character has no bone '" + entry.bone + "'");
    for (JointMatch& j : report_.joints)
      if (auto it = map.find(j.joint); it != map.end()) pair(j, character_.findBone(it->second.bone), MatchSource::Map);
  }

  void byName() {
    for (JointMatch& j : report_.joints) pair(j, character_.findBone(j.joint), MatchSource::Name);
    for (JointMatch& j : report_.joints)
      for (int b = 0; b < character_.boneCount() && j.bone < 0; ++b)
        if (lower(character_.bone(b).name) == lower(j.joint)) pair(j, b, MatchSource::Name);
  }

  // Both skeletons must be humanoids; otherwise this rule adds nothing.
  void byRole() {
    HumanoidBones motionRoles, characterRoles;
    try {
      motionRoles = findHumanoidBones(motion_, motion_.worldTransforms(motion_.restPose()));
      characterRoles = findHumanoidBones(character_, character_.worldTransforms(character_.restPose()));
    } catch (const Error&) {
      return;
    }
    pairRole(motionRoles.pelvis, characterRoles.pelvis, "pelvis");
    pairRole(motionRoles.spine, characterRoles.spine, "spine");
    pairRole(motionRoles.chest, characterRoles.chest, "chest");
    pairRole(motionRoles.neck, characterRoles.neck, "neck");
    pairRole(motionRoles.head, characterRoles.head, "head");
    for (int s = 0; s < 2; ++s) {
      const std::string side = s == 0 ? " (left)" : " (right)";
      pairRole(motionRoles.clavicle[s], characterRoles.clavicle[s], "clavicle" + side);
      pairRole(motionRoles.upperArm[s], characterRoles.upperArm[s], "upper arm" + side);
      pairRole(motionRoles.forearm[s], characterRoles.forearm[s], "forearm" + side);
      pairRole(motionRoles.hand[s], characterRoles.hand[s], "hand" + side);
      pairRole(motionRoles.thigh[s], characterRoles.thigh[s], "thigh" + side);
      pairRole(motionRoles.shin[s], characterRoles.shin[s], "shin" + side);
      pairRole(motionRoles.foot[s], characterRoles.foot[s], "foot" + side);
    }
  }

  BoneMatchReport finish() {
    for (const JointMatch& j : report_.joints)
      if (j.bone < 0) report_.unmatchedJoints.push_back(j.joint);
    for (int b = 0; b < character_.boneCount(); ++b)
      if (!taken_[b]) report_.unmatchedBones.push_back(character_.bone(b).name);
    return std::move(report_);
  }

 private:
  void pair(JointMatch& joint, int bone, MatchSource source) {
    if (bone < 0 || taken_[bone] || joint.bone >= 0) return;
    joint.bone = bone;
    joint.source = source;
    taken_[bone] = true;
  }

  void pairRole(int joint, int bone, const std::string& role) {
    if (joint < 0 || bone < 0) return;
    JointMatch& match = report_.joints[joint];
    pair(match, bone, MatchSource::Role);
    if (match.bone == bone && match.source == MatchSource::Role) match.role = role;
  }

  const Skeleton& motion_;
  const Skeleton& character_;
  BoneMatchReport report_;
  std::vector<bool> taken_;
};

std::string nameList(const std::vector<std::string>& names, size_t maxNames) {
  std::string text;
  const size_t shown = std::min(names.size(), maxNames);
  for (size_t i = 0; i < shown; ++i) text += (i ? ", " : "") + names[i];
  if (shown < names.size()) text += " and " + std::to_string(names.size() - shown) + " more";
  return text;
}

}  // namespace

int BoneMatchReport::matchedCount() const {
  return static_cast<int>(std::count_if(joints.begin(), joints.end(), [](const JointMatch& j) { return j.bone >= 0; }));
}

std::vector<int> BoneMatchReport::boneOfJoint() const {
  std::vector<int> bones;
  for (const JointMatch& j : joints) bones.push_back(j.bone);
  return bones;
}

std::string BoneMatchReport::summary(size_t maxNames) const {
  std::string text = "matched " + std::to_string(matchedCount()) + " of " + std::to_string(joints.size()) + " bones";
  text += unmatchedJoints.empty() ? "; all matched" : "; unmatched: " + nameList(unmatchedJoints, maxNames);
  if (!unmatchedBones.empty()) text += "; not driven on the character: " + nameList(unmatchedBones, maxNames);
  return text;
}

BoneMatchReport matchBones(const Skeleton& motion, const Skeleton& character, const std::string& mapPath) {
  Matcher matcher(motion, character);
  if (!mapPath.empty()) matcher.byMap(mapPath);
  matcher.byName();
  matcher.byRole();
  return matcher.finish();
}

const char* matchSourceName(MatchSource source) {
  switch (source) {
    case MatchSource::Map:
      return "name map";
    case MatchSource::Name:
      return "same name";
    case MatchSource::Role:
      return "humanoid role";
    case MatchSource::None:
      break;
  }
  return "unmatched";
}

}  // namespace mq
