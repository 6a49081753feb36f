#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/skin_test_util.h"
#include "core/skinning/helper_bones.h"
#include "core/skinning/skin_report.h"

namespace mq {
namespace {

const Character& mannequin() {
  static const Character c = makeDefaultMannequin();
  return c;
}

float angleDegrees(const glm::quat& a, const glm::quat& b) {
  return glm::degrees(2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(a, b)))));
}

TEST(HelperBones, TwistAboutRecoversTheTwistOfASwingTwist) {
  const glm::vec3 axis(0, 1, 0);
  const glm::quat twist = glm::angleAxis(glm::radians(70.0f), axis);
  const glm::quat swing = glm::angleAxis(glm::radians(40.0f), glm::normalize(glm::vec3(1, 0, 1)));
  EXPECT_NEAR(angleDegrees(twistAbout(swing * twist, axis), twist), 0.0f, 0.05f);
  EXPECT_NEAR(angleDegrees(twistAbout(swing, axis), glm::quat(1, 0, 0, 0)), 0.0f, 0.05f);
}

TEST(HelperBones, MannequinGetsShoulderElbowHipKneeAndTwistBones) {
  Character c = mannequin();
  const int before = c.skeleton.boneCount();
  EXPECT_EQ(addHelperBones(c), 14);
  EXPECT_EQ(c.skeleton.boneCount(), before + 14);
  for (const char* name : {"forearm_l_third1", "forearm_r_third2", "shin_r_half", "thigh_l_half", "upperarm_r_half",
                           "forearm_l_twist1", "forearm_r_twist2"})
    EXPECT_GE(c.skeleton.findBone(name), 0) << name;
  // Twice is once.
  std::string why;
  EXPECT_EQ(addHelperBones(c, &why), 0);
  EXPECT_NE(why.find("already"), std::string::npos);
  // Weights stay a partition of unity over at most 4 joints, and the helpers carry some.
  const SkinBinding& skin = c.meshes[0].skin;
  EXPECT_LE(skin.maxInfluences(), 4);
  double onHelpers = 0.0;
  for (size_t v = 0; v < c.meshes[0].vertexCount(); ++v) {
    float sum = 0.0f;
    for (int i = 0; i < skin.influencesPerVertex; ++i) {
      const float w = skin.weights[v * skin.influencesPerVertex + i];
      sum += w;
      if (skin.jointBones[skin.joints[v * skin.influencesPerVertex + i]] >= before) onHelpers += w;
    }
    ASSERT_NEAR(sum, 1.0f, 1e-5f) << v;
  }
  EXPECT_GT(onHelpers, 1000.0);
}

TEST(HelperBones, RestPoseStillGivesTheRestMesh) {
  Character c = mannequin();
  addHelperBones(c);
  PosedCharacter posed;
  posed.evaluate(c, c.skeleton.restPose(), {}, nullptr);
  const std::vector<float>& rest = c.meshes[0].positions;
  float worst = 0.0f;
  for (size_t i = 0; i < rest.size(); ++i) worst = std::max(worst, std::abs(posed.meshes()[0].positions[i] - rest[i]));
  EXPECT_LT(worst, 1e-5f * 2.0f);  // 1e-5 of the body's ~2 m diagonal
}

TEST(HelperBones, HalfAngleBoneTurnsHalfAsFarAndElbowThirdsAThird) {
  Character c = mannequin();
  addHelperBones(c);
  const int shin = c.skeleton.findBone("shin_l"), half = c.skeleton.findBone("shin_l_half");
  const int forearm = c.skeleton.findBone("forearm_l");
  const int third1 = c.skeleton.findBone("forearm_l_third1"), third2 = c.skeleton.findBone("forearm_l_third2");
  Pose pose = c.skeleton.restPose();
  pose[shin].rotation = pose[shin].rotation * glm::angleAxis(glm::radians(120.0f), glm::vec3(1, 0, 0));
  pose[forearm].rotation = pose[forearm].rotation * glm::angleAxis(glm::radians(120.0f), glm::vec3(1, 0, 0));
  driveHelperBones(c.helperBones, c.skeleton, pose);
  EXPECT_NEAR(angleDegrees(pose[half].rotation, c.skeleton.bone(shin).rest.rotation), 60.0f, 0.01f);
  EXPECT_NEAR(glm::distance(pose[half].translation, pose[shin].translation), 0.0f, 1e-6f);
  EXPECT_NEAR(angleDegrees(pose[third1].rotation, c.skeleton.bone(forearm).rest.rotation), 40.0f, 0.01f);
  EXPECT_NEAR(angleDegrees(pose[third2].rotation, c.skeleton.bone(forearm).rest.rotation), 80.0f, 0.01f);
}

TEST(HelperBones, ElbowVerticesSplitTheirWeightBetweenNeighbouringStages) {
  // A vertex with upper arm u and forearm f sits at t = f / (u + f) along the
  // stages upper arm (0), third1 (1/3), third2 (2/3), forearm (1).
  Character c = mannequin();
  const Character file = c;
  addHelperBones(c);
  const SkinBinding& before = file.meshes[0].skin;
  const SkinBinding& after = c.meshes[0].skin;
  const int upper = c.skeleton.findBone("upperarm_l"), forearm = c.skeleton.findBone("forearm_l");
  const int third1 = c.skeleton.findBone("forearm_l_third1"), third2 = c.skeleton.findBone("forearm_l_third2");
  const int twist1 = c.skeleton.findBone("forearm_l_twist1"), twist2 = c.skeleton.findBone("forearm_l_twist2");
  auto weightOfBone = [](const SkinBinding& skin, size_t v, int bone) {
    float w = 0.0f;
    for (int i = 0; i < skin.influencesPerVertex; ++i)
      if (skin.jointBones[skin.joints[v * skin.influencesPerVertex + i]] == bone)
        w += skin.weights[v * skin.influencesPerVertex + i];
    return w;
  };
  int checked = 0;
  for (size_t v = 0; v < c.meshes[0].vertexCount(); ++v) {
    const float u = weightOfBone(before, v, upper), f = weightOfBone(before, v, forearm);
    if (u < 0.05f || f < 0.05f || u + f < 0.999f) continue;  // only the elbow's two bones
    const float x = 3.0f * f / (u + f);
    const float expected[4] = {std::max(0.0f, 1.0f - x), std::max(0.0f, 1.0f - std::abs(x - 1.0f)),
                               std::max(0.0f, 1.0f - std::abs(x - 2.0f)), std::max(0.0f, x - 2.0f)};
    const int bones[3] = {upper, third1, third2};
    // The forearm's stage spreads further over the forearm's twist bones.
    const float forearmStage =
        weightOfBone(after, v, forearm) + weightOfBone(after, v, twist1) + weightOfBone(after, v, twist2);
    for (int s = 0; s < 3; ++s) ASSERT_NEAR(weightOfBone(after, v, bones[s]), expected[s], 1e-4f) << v << " " << s;
    ASSERT_NEAR(forearmStage, expected[3], 1e-4f) << v;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(HelperBones, TwistBonesTakeAThirdAndTwoThirdsOfTheHandsTwist) {
  Character c = mannequin();
  addHelperBones(c);
  const int hand = c.skeleton.findBone("hand_l");
  const int t1 = c.skeleton.findBone("forearm_l_twist1"), t2 = c.skeleton.findBone("forearm_l_twist2");
  Pose pose = c.skeleton.restPose();
  // The hand turns 90 degrees about the forearm's axis (its own +Y).
  pose[hand].rotation = pose[hand].rotation * glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
  driveHelperBones(c.helperBones, c.skeleton, pose);
  const glm::quat identity(1, 0, 0, 0);
  EXPECT_NEAR(angleDegrees(pose[t1].rotation, identity), 30.0f, 0.5f);
  EXPECT_NEAR(angleDegrees(pose[t2].rotation, identity), 60.0f, 0.5f);
  // A bend alone (no twist) leaves them at rest.
  Pose bent = c.skeleton.restPose();
  bent[hand].rotation = bent[hand].rotation * glm::angleAxis(glm::radians(50.0f), glm::vec3(1, 0, 0));
  driveHelperBones(c.helperBones, c.skeleton, bent);
  EXPECT_NEAR(angleDegrees(bent[t2].rotation, identity), 0.0f, 0.5f);
}

TEST(HelperBones, RemovingThemGivesTheWeightsBack) {
  Character c = mannequin();
  addHelperBones(c);
  removeHelperBones(c);
  const Character& original = mannequin();
  EXPECT_EQ(c.skeleton.boneCount(), original.skeleton.boneCount());
  EXPECT_TRUE(c.helperBones.empty());
  EXPECT_EQ(c.meshes[0].skin.jointBones, original.meshes[0].skin.jointBones);
  EXPECT_EQ(c.meshes[0].skin.weights, original.meshes[0].skin.weights);
  // Same pose, same skin.
  Pose pose = original.skeleton.restPose();
  rotateBoneAboutWorldAxis(original.skeleton, pose, original.skeleton.findBone("forearm_l"), {1, 0, 0}, 100.0f);
  PosedCharacter a, b;
  a.evaluate(original, pose, {}, nullptr);
  b.evaluate(c, pose, {}, nullptr);
  float worst = 0.0f;
  for (size_t i = 0; i < a.meshes()[0].positions.size(); ++i)
    worst = std::max(worst, std::abs(a.meshes()[0].positions[i] - b.meshes()[0].positions[i]));
  EXPECT_EQ(worst, 0.0f);
}

TEST(HelperBones, NotAHumanoidIsLeftAsItIs) {
  Character tube = tubeCharacter(9, 12, false);
  std::string why;
  EXPECT_EQ(addHelperBones(tube, &why), 0);
  EXPECT_NE(why.find("humanoid"), std::string::npos) << why;
  EXPECT_EQ(tube.skeleton.boneCount(), 2);
}

// The survey's point: with helpers, plain LBS keeps a bent elbow's thickness.
TEST(HelperBones, LinearBlendKeepsTheElbowWithHelpers) {
  Character plain = mannequin();
  Character helped = mannequin();
  addHelperBones(helped);
  SkinReportOptions options;
  options.clips = false;
  options.intersections = false;
  auto elbow120 = [&](const Character& c) {
    for (const PoseMeasure& p : measureSkinning(c, options, nullptr).poses)
      if (p.name == "elbow 120") return p.thickness;
    return -1.0;
  };
  EXPECT_LT(elbow120(plain), 0.6);
  EXPECT_GT(elbow120(helped), 0.85);
}

}  // namespace
}  // namespace mq
