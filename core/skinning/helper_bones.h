#pragma once
// Helper bones at the joints (survey 1.2.5, "ajout d'os": small bones added
// at the joints split a large rotation between bones into smaller ones, which
// linear blend skinning interpolates without collapsing). On a humanoid:
//   - a half-angle bone at each shoulder, hip and knee: a sibling of the
//     upper arm (thigh, shin) at its joint that turns half as far as it, from
//     its rest; at each elbow two such bones, turning a third and two thirds
//     as far as the forearm (a forearm twisted half a turn then keeps 0.75 of
//     its section under linear blending, against 0.5 with one);
//   - two twist bones along each forearm, at a third and two thirds of it,
//     taking that share of the hand's twist about the forearm's axis
//     (swing-twist split).
// Skin weights move onto them: a vertex shared by a bone and its parent
// (the forearm and the upper arm) moves onto the two stages its blend falls
// between (a 50/50 vertex follows the half angle alone), and the
// forearm's weight spreads over its twist bones by the vertex's place along
// the forearm. A half-angle bone at the wrist is not added: measured, it
// rounds a bent wrist but adds crossings and thins the wrist twist
// (docs/performance.md). The helpers are
// ordinary bones driven by their drivers' local transforms, so any LBS
// engine plays them once their motion is baked.

#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/skeleton/skeleton.h"

namespace mq {

struct Character;

struct HelperBone {
  enum class Kind { HalfAngle, Twist };
  Kind kind = Kind::HalfAngle;
  int bone = -1;                       // the helper itself
  int driver = -1;                     // HalfAngle: the bent bone (forearm, shin); Twist: the hand
  float share = 0.5f;                  // of the driver's rotation (HalfAngle) or twist (Twist)
  glm::vec3 axis{0.0f};                // Twist: the forearm's axis in the forearm's frame
  glm::mat4 driverRestInParent{1.0f};  // Twist: the hand in the forearm's frame at rest
};

// Adds the helpers to a humanoid character and moves weights onto them.
// Returns the number added; a character that has helpers already, or is not
// a humanoid, is left as it is (0; `why` says why when given).
int addHelperBones(Character& character, std::string* why = nullptr);

// Why addHelperBones would add nothing to `character`; empty when it would
// add some.
std::string helperBonesRefusal(const Character& character);

// Takes the helpers out again and gives the skins back their weights as they
// were. The helpers must be the skeleton's last bones, as addHelperBones
// leaves them.
void removeHelperBones(Character& character);

// Sets each helper's local transform in `pose` from its driver's.
void driveHelperBones(const std::vector<HelperBone>& helpers, const Skeleton& skeleton, Pose& pose);

// The twist part of rotation q about the unit axis (swing-twist split:
// q = swing * twist); identity when q has no twist about it.
glm::quat twistAbout(const glm::quat& q, const glm::vec3& axis);

}  // namespace mq
