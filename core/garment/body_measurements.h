#pragma once
// What a tailor measures, read from a character in its rest pose: joint
// positions (skeleton rest world transforms, bones found by findHumanoidBones:
// names with common aliases, else the skeleton's structure), girths (ellipses fitted to thin slices of the skin) and
// the bounding capsules of the body. Index 0 of a pair is the character's left (+X).

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/garment/body_capsules.h"

namespace mq {

struct Character;

struct BodyMeasurements {
  glm::vec3 pelvis{0.0f}, waist{0.0f}, chest{0.0f}, neck{0.0f};
  glm::vec3 shoulder[2]{}, elbow[2]{}, wrist[2]{};
  glm::vec3 hip[2]{}, knee[2]{}, ankle[2]{};
  float chestGirth = 0.0f, waistGirth = 0.0f, hipGirth = 0.0f;
  float upperArmGirth = 0.0f, thighGirth = 0.0f;
  // Top of the shoulders: the highest skin point over the torso axis's
  // depth, between halfway to the shoulder joint and the joint (left, right).
  float shoulderTop[2]{};
  // Bottom of the crotch: the lowest skin point on the torso axis between the
  // hips and the knees (the hips' height minus 7 cm without skin there).
  float crotchY = 0.0f;
  std::vector<BodyCapsule> capsules;
  // Names of the bones garment panels follow: the spine, the upper arms.
  std::string spineBone, upperArmBone[2];

  // The vertical torso axis (through pelvis and chest), as a point at height y.
  glm::vec3 torsoAxisAt(float y) const;
};

// Throws mq::Error naming the character and the missing role when the
// skeleton lacks one of pelvis, spine, chest, neck, upper arms, forearms,
// hands, thighs, shins or feet, or when the character does not face +Z.
// A character without bones (a static mesh) is measured on its auto-rig
// (core/character/auto_rig.h); the bone names are then the auto-rig's.
BodyMeasurements measureBody(const Character& character);

}  // namespace mq
