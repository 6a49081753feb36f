#pragma once
// Bounding capsules of a character's body in its rest pose, one per bone:
// the segment along the bone (towards its main child) that, with the radius,
// encloses every skin vertex the bone dominates. Garments are placed outside
// them and tests check that no panel vertex starts inside the body.

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace mq {

struct Character;

struct BodyCapsule {
  int bone = -1;
  std::string boneName;
  glm::vec3 a{0.0f}, b{0.0f};  // world space, rest pose
  float radius = 0.0f;

  // Signed distance from p to the capsule surface, negative inside.
  float distance(const glm::vec3& p) const;
};

// Capsules for every bone that dominates at least `minVertices` skin vertices.
std::vector<BodyCapsule> fitBodyCapsules(const Character& character, int minVertices = 8);

// The capsule of a bone, or nullptr.
const BodyCapsule* findCapsule(const std::vector<BodyCapsule>& capsules, const std::string& boneName);

// Smallest signed distance from p to any capsule (negative: inside one).
float distanceToCapsules(const std::vector<BodyCapsule>& capsules, const glm::vec3& p);

}  // namespace mq
