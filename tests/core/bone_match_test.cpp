// The match report of a BVH applied to a character: CMU motion capture on the
// default mannequin (names and humanoid roles) and on CesiumMan (roles by
// structure alone), the shipped name map, the lists of what is left out on
// both sides, "in place" root motion, and bad map files.
#include <gtest/gtest.h>

#include <fstream>

#include "core/character/default_mannequin.h"
#include "core/io/bvh_import.h"
#include "core/io/character_import.h"
#include "core/util/error.h"
#include "import_test_util.h"

namespace mq {
namespace {

const std::string kShared = MANNEQUIN_SHARED_DIR;
const std::string kCmu = kShared + "/assets/motion/cmu_01_01.bvh";
const std::string kCmuMap = std::string(MANNEQUIN_SOURCE_DIR) + "/resources/motion_maps/cmu_to_default.txt";

// Built once: the mannequin's body takes a while to mesh.
const Character& mannequin() {
  static const Character c = makeDefaultMannequin();
  return c;
}

const JointMatch& jointNamed(const BoneMatchReport& report, const std::string& name) {
  for (const JointMatch& j : report.joints)
    if (j.joint == name) return j;
  throw Error("no joint " + name);
}

// "bone (source, role)" for one joint, so a failure shows the whole pairing.
std::string pairing(const BoneMatchReport& report, const Skeleton& character, const std::string& joint) {
  const JointMatch& j = jointNamed(report, joint);
  if (j.bone < 0) return "-";
  return character.bone(j.bone).name + " (" + matchSourceName(j.source) + (j.role.empty() ? "" : ", " + j.role) + ")";
}

TEST(BoneMatch, CmuOnTheDefaultMannequinByNameThenRole) {
  const BoneMatchReport r = matchBvhMotion(kCmu, mannequin());
  ASSERT_EQ(r.joints.size(), 31u);
  EXPECT_EQ(r.matchedCount(), 19);
  EXPECT_EQ(r.characterBoneCount, mannequin().skeleton.boneCount());
  const Skeleton& s = mannequin().skeleton;
  EXPECT_EQ(pairing(r, s, "Spine"), "spine (same name)");
  EXPECT_EQ(pairing(r, s, "Head"), "head (same name)");
  EXPECT_EQ(pairing(r, s, "Hips"), "pelvis (humanoid role, pelvis)");
  EXPECT_EQ(pairing(r, s, "Spine1"), "chest (humanoid role, chest)");
  EXPECT_EQ(pairing(r, s, "LeftShoulder"), "clavicle_l (humanoid role, clavicle (left))");
  EXPECT_EQ(pairing(r, s, "LeftArm"), "upperarm_l (humanoid role, upper arm (left))");
  EXPECT_EQ(pairing(r, s, "RightForeArm"), "forearm_r (humanoid role, forearm (right))");
  EXPECT_EQ(pairing(r, s, "LeftUpLeg"), "thigh_l (humanoid role, thigh (left))");
  EXPECT_EQ(pairing(r, s, "RightLeg"), "shin_r (humanoid role, shin (right))");
  EXPECT_EQ(pairing(r, s, "RightFoot"), "foot_r (humanoid role, foot (right))");
  EXPECT_EQ(pairing(r, s, "LowerBack"), "-");
  EXPECT_EQ(r.unmatchedJoints, (std::vector<std::string>{"LHipJoint", "LeftToeBase", "RHipJoint", "RightToeBase",
                                                         "LowerBack", "Neck1", "LeftFingerBase", "LFingers", "LThumb",
                                                         "RightFingerBase", "RFingers", "RThumb"}));
  EXPECT_EQ(r.unmatchedBones, (std::vector<std::string>{"toes_l", "toes_r"}));
  EXPECT_EQ(r.summary(3),
            "matched 19 of 31 bones; unmatched: LHipJoint, LeftToeBase, RHipJoint and 9 more; "
            "not driven on the character: toes_l, toes_r");
}

TEST(BoneMatch, CmuOnCesiumManByStructure) {
  const Character cesium = importCharacter(kShared + "/assets/characters/CesiumMan/glTF/CesiumMan.gltf");
  const BoneMatchReport r = matchBvhMotion(kCmu, cesium);
  const Skeleton& s = cesium.skeleton;
  EXPECT_EQ(r.matchedCount(), 17);  // every role but the clavicles, which CesiumMan lacks
  EXPECT_EQ(pairing(r, s, "Hips"), "Skeleton_torso_joint_1 (humanoid role, pelvis)");
  EXPECT_EQ(pairing(r, s, "Spine1"), "torso_joint_3 (humanoid role, chest)");
  EXPECT_EQ(pairing(r, s, "Head"), "Skeleton_neck_joint_2 (humanoid role, head)");
  EXPECT_EQ(pairing(r, s, "LeftArm"), "Skeleton_arm_joint_L__4_ (humanoid role, upper arm (left))");
  EXPECT_EQ(pairing(r, s, "RightHand"), "Skeleton_arm_joint_R__3_ (humanoid role, hand (right))");
  EXPECT_EQ(pairing(r, s, "LeftFoot"), "leg_joint_L_3 (humanoid role, foot (left))");
  EXPECT_EQ(pairing(r, s, "LeftShoulder"), "-");
  EXPECT_EQ(r.unmatchedJoints.size(), 14u);
  EXPECT_EQ(r.unmatchedBones, (std::vector<std::string>{"leg_joint_L_5", "leg_joint_R_5"}));
}

TEST(BoneMatch, NameMapComesFirstAndNamesFillTheRest) {
  const BoneMatchReport r = matchBvhMotion(kCmu, mannequin(), kCmuMap);
  const Skeleton& s = mannequin().skeleton;
  EXPECT_EQ(r.matchedCount(), 21);
  EXPECT_EQ(pairing(r, s, "LowerBack"), "spine (name map)");
  EXPECT_EQ(pairing(r, s, "LeftToeBase"), "toes_l (name map)");
  // "Spine" would take "spine" by its name, but the map gave that bone away.
  EXPECT_EQ(pairing(r, s, "Spine"), "-");
  EXPECT_TRUE(r.unmatchedBones.empty());
  EXPECT_EQ(r.summary().rfind("matched 21 of 31 bones; unmatched: LHipJoint, RHipJoint, Spine, Neck1", 0), 0u)
      << r.summary();
}

TEST(BoneMatch, NonHumanoidGetsNamesOnly) {
  const Character simple = importCharacter(kShared + "/assets/characters/RiggedSimple/RiggedSimple.gltf");
  const BoneMatchReport r = matchBvhMotion(kCmu, simple);
  EXPECT_EQ(r.matchedCount(), 0);
  EXPECT_EQ(r.unmatchedJoints.size(), 31u);
  EXPECT_EQ(static_cast<int>(r.unmatchedBones.size()), simple.skeleton.boneCount());
  EXPECT_THROW(retargetBvhMotion(kCmu, simple), FileError);
}

// The pelvis's world position over the first seconds of the CMU walk.
std::vector<glm::vec3> pelvisPath(const Character& c, int clip) {
  const int pelvis = c.skeleton.findBone("pelvis");
  std::vector<glm::vec3> path;
  for (float t = 0.0f; t < 5.0f; t += 0.25f)
    path.push_back(glm::vec3(c.skeleton.worldTransforms(samplePose(c, clip, t))[pelvis][3]));
  return path;
}

TEST(BoneMatch, InPlaceKeepsTheRootOverItsStartButLetsItBob) {
  Character c = mannequin();
  const RetargetedMotion walking = retargetBvhMotion(kCmu, c);
  const RetargetedMotion inPlace = retargetBvhMotion(kCmu, c, {"", true});
  EXPECT_EQ(walking.match.summary(), inPlace.match.summary());
  c.clips = {walking.clip, inPlace.clip};
  const std::vector<glm::vec3> walked = pelvisPath(c, 0), stayed = pelvisPath(c, 1);
  float travel = 0.0f, drift = 0.0f, bob = 0.0f;
  for (size_t i = 0; i < walked.size(); ++i) {
    travel = std::max(travel, glm::length(glm::vec2(walked[i].x - walked[0].x, walked[i].z - walked[0].z)));
    drift = std::max(drift, glm::length(glm::vec2(stayed[i].x - stayed[0].x, stayed[i].z - stayed[0].z)));
    bob = std::max(bob, std::abs(stayed[i].y - stayed[0].y));
    EXPECT_NEAR(stayed[i].y, walked[i].y, 1e-4f) << "the vertical part is kept";
  }
  EXPECT_GT(travel, 0.5f);  // the CMU walk covers metres in five seconds
  EXPECT_LT(drift, 1e-4f);
  EXPECT_GT(bob, 0.005f);
}

std::string writeMap(const std::string& name, const std::string& text) {
  const std::string path = (test::scratchDir("mq_bone_match_test") / name).string();
  std::ofstream(path) << text;
  return path;
}

void expectMapError(const std::string& map, const std::string& fragment) {
  try {
    matchBvhMotion(kCmu, mannequin(), map);
    FAIL() << "expected FileError for " << map;
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), map);
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(BoneMatch, BadMapFilesNameTheFileAndLine) {
  expectMapError(writeMap("three_words.txt", "Hips pelvis\n# fine\nLeftArm upperarm_l extra\n"),
                 "line 3: expected 'bvh_joint_name target_bone_name', found 3 word(s)");
  expectMapError(writeMap("unknown_bone.txt", "Hips hips_bone\n"), "line 1: the character has no bone 'hips_bone'");
  expectMapError(kShared + "/no_such_map.txt", "no such file");
}

}  // namespace
}  // namespace mq
