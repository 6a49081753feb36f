// Humanoid bone roles: by name on the default mannequin, by structure on
// CesiumMan (no alias matches its bone names) and on the default mannequin's
// skeleton with every bone renamed; a clear error for a non-humanoid.
#include <gtest/gtest.h>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/garment/body_measurements.h"
#include "core/garment/parametric_garments.h"
#include "core/io/character_import.h"
#include "core/skeleton/humanoid_roles.h"
#include "core/util/error.h"

namespace mq {
namespace {

const std::string kCharacters = std::string(MANNEQUIN_SHARED_DIR) + "/assets/characters/";

std::vector<glm::mat4> restWorld(const Character& c) {
  PosedCharacter rest;
  rest.evaluate(c, -1, 0.0f, nullptr, nullptr);
  return rest.worldFromBone();
}

// Role -> bone name, in a fixed order, for comparisons and messages.
std::vector<std::pair<std::string, std::string>> roleNames(const Skeleton& s, const HumanoidBones& r) {
  auto name = [&](int b) { return b < 0 ? std::string("-") : s.bone(b).name; };
  std::vector<std::pair<std::string, std::string>> out = {{"pelvis", name(r.pelvis)},
                                                          {"spine", name(r.spine)},
                                                          {"chest", name(r.chest)},
                                                          {"neck", name(r.neck)},
                                                          {"head", name(r.head)}};
  for (int side = 0; side < 2; ++side) {
    const std::string tag = side == 0 ? "_l" : "_r";
    out.push_back({"clavicle" + tag, name(r.clavicle[side])});
    out.push_back({"upperarm" + tag, name(r.upperArm[side])});
    out.push_back({"forearm" + tag, name(r.forearm[side])});
    out.push_back({"hand" + tag, name(r.hand[side])});
    out.push_back({"thigh" + tag, name(r.thigh[side])});
    out.push_back({"shin" + tag, name(r.shin[side])});
    out.push_back({"foot" + tag, name(r.foot[side])});
  }
  return out;
}

std::vector<std::pair<std::string, std::string>> expectedMannequinRoles() {
  std::vector<std::pair<std::string, std::string>> out = {
      {"pelvis", "pelvis"}, {"spine", "spine"}, {"chest", "chest"}, {"neck", "neck"}, {"head", "head"}};
  for (const std::string tag : {"_l", "_r"})
    for (const std::string role : {"clavicle", "upperarm", "forearm", "hand", "thigh", "shin", "foot"})
      out.push_back({role + tag, role + tag});
  return out;
}

TEST(HumanoidRoles, DefaultMannequinByName) {
  const Character c = makeDefaultMannequin();
  const HumanoidBones r = findHumanoidBones(c.skeleton, restWorld(c));
  EXPECT_EQ(roleNames(c.skeleton, r), expectedMannequinRoles());
  EXPECT_NEAR(r.facing.z, 1.0f, 0.05f);
}

// Every bone renamed "b0", "b1", ...: no alias matches, the structure alone
// must give the same bones as the names.
TEST(HumanoidRoles, RenamedMannequinByStructureMatchesTheNames) {
  const Character named = makeDefaultMannequin();
  Character renamed = named;
  for (int b = 0; b < renamed.skeleton.boneCount(); ++b) renamed.skeleton.bone(b).name = "b" + std::to_string(b);
  ASSERT_EQ(findBoneByRoleName(renamed.skeleton, "pelvis", 0), -1);
  const HumanoidBones byName = findHumanoidBones(named.skeleton, restWorld(named));
  const HumanoidBones byStructure = findHumanoidBones(renamed.skeleton, restWorld(renamed));
  const auto expected = roleNames(named.skeleton, byName);
  auto actual = roleNames(renamed.skeleton, byStructure);
  for (auto& [role, bone] : actual)
    if (bone != "-") bone = named.skeleton.bone(std::stoi(bone.substr(1))).name;
  EXPECT_EQ(actual, expected);
  // And the measurements (joints, girths) are the same.
  const BodyMeasurements a = measureBody(named), b = measureBody(renamed);
  EXPECT_EQ(a.chest, b.chest);
  EXPECT_EQ(a.shoulder[0], b.shoulder[0]);
  EXPECT_EQ(a.ankle[1], b.ankle[1]);
  EXPECT_FLOAT_EQ(a.chestGirth, b.chestGirth);
  EXPECT_FLOAT_EQ(a.thighGirth, b.thighGirth);
}

TEST(HumanoidRoles, CesiumManByStructure) {
  const Character c = importCharacter(kCharacters + "CesiumMan/glTF/CesiumMan.gltf");
  const HumanoidBones r = findHumanoidBones(c.skeleton, restWorld(c));
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"pelvis", "Skeleton_torso_joint_1"},
      {"spine", "Skeleton_torso_joint_2"},
      {"chest", "torso_joint_3"},
      {"neck", "Skeleton_neck_joint_1"},
      {"head", "Skeleton_neck_joint_2"},
      {"clavicle_l", "-"},
      {"upperarm_l", "Skeleton_arm_joint_L__4_"},
      {"forearm_l", "Skeleton_arm_joint_L__3_"},
      {"hand_l", "Skeleton_arm_joint_L__2_"},
      {"thigh_l", "leg_joint_L_1"},
      {"shin_l", "leg_joint_L_2"},
      {"foot_l", "leg_joint_L_3"},
      {"clavicle_r", "-"},
      {"upperarm_r", "Skeleton_arm_joint_R"},
      {"forearm_r", "Skeleton_arm_joint_R__2_"},
      {"hand_r", "Skeleton_arm_joint_R__3_"},
      {"thigh_r", "leg_joint_R_1"},
      {"shin_r", "leg_joint_R_2"},
      {"foot_r", "leg_joint_R_3"},
  };
  EXPECT_EQ(roleNames(c.skeleton, r), expected);
  EXPECT_GT(r.facing.z, 0.7f);
}

// The built-in garments build on CesiumMan (1.5 units tall): lengths scale
// with the body, circumferences come from its skin; the default mannequin's
// keep the declared defaults.
TEST(HumanoidRoles, BuiltInGarmentsFitCesiumMan) {
  const Character c = importCharacter(kCharacters + "CesiumMan/glTF/CesiumMan.gltf");
  const BodyMeasurements m = measureBody(c);
  for (const std::string type : {"tshirt", "skirt", "trousers"}) {
    SCOPED_TRACE(type);
    const Garment g = makeParametricGarment(type, c);
    EXPECT_FALSE(g.panels.empty());
    const float declaredLength = garmentParameters(type)[0].value;
    EXPECT_LT(g.recipe.parameters.at("length"), 0.9f * declaredLength);
    EXPECT_GT(g.recipe.parameters.at("length"), 0.6f * declaredLength);
    // The front panels follow CesiumMan's bones, not the default's names.
    EXPECT_EQ(g.panels[0].placement.bone, "Skeleton_torso_joint_2");
    EXPECT_EQ(makeParametricGarment(type, makeDefaultMannequin()).recipe.parameters.at("length"), declaredLength);
  }
  EXPECT_GT(m.chestGirth, 0.4f);
  EXPECT_LT(m.chestGirth, 1.0f);
  EXPECT_GE(m.hipGirth, m.waistGirth);
}

// CesiumMan's left upper arm also drives skin of its shoulder (its capsule
// is 3.4 times as thick as the arm's girth, the right one's 2 times): the
// sleeves follow the arm's girth instead, so both sit alike around their arm.
TEST(HumanoidRoles, TShirtSleevesOfCesiumManAreAlike) {
  const Character c = importCharacter(kCharacters + "CesiumMan/glTF/CesiumMan.gltf");
  const Garment shirt = makeParametricGarment("tshirt", c);
  const PanelPlacement& left = shirt.panels[2].placement;
  const PanelPlacement& right = shirt.panels[3].placement;
  ASSERT_EQ(shirt.panels[2].name, "sleeve_l");
  EXPECT_NEAR(left.radius, right.radius, 0.005f);
  EXPECT_NEAR(left.center.x, -right.center.x, 0.02f);
  EXPECT_NEAR(left.center.y, right.center.y, 0.01f);
}

TEST(HumanoidRoles, NonHumanoidGivesAClearError) {
  const Character c = importCharacter(kCharacters + "RiggedSimple/RiggedSimple.gltf");
  try {
    measureBody(c);
    FAIL() << "RiggedSimple measured as a humanoid";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("character '" + c.name + "'"), std::string::npos) << message;
    EXPECT_NE(message.find("no bone for the pelvis"), std::string::npos) << message;
  }
  EXPECT_THROW(makeParametricGarment("tshirt", c), Error);
}

}  // namespace
}  // namespace mq
