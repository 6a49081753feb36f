#pragma once
// What hair collides with: an ellipsoid for the head and capsules for neck,
// torso and upper arms, each attached to a bone (HairColliders, bone space),
// posed every step into world space (PosedHairColliders), where strand
// particles are pushed out of them. Built from the hair module's rest-pose
// BodyProxy (core/hair/body_proxy.h), the same shapes the groom keeps the
// strands out of, so rest strands start outside the colliders.

#include <memory>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace mq {

class BodyProxy;
class MeshDistanceField;
class Skeleton;

// A capsule is the set of points within `radius` of segment [a, b]; a sphere
// is a capsule with a == b.
struct ColliderCapsule {
  int bone = -1;               // -1: fixed in world space
  glm::vec3 a{0.0f}, b{0.0f};  // bone space
  float radius = 0.0f;
};

// An ellipsoid: the unit sphere mapped by boneFromUnit (rotation * scale +
// translation, no shear).
struct ColliderEllipsoid {
  int bone = -1;
  glm::vec3 center{0.0f};
  glm::vec3 radii{1.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // bone from ellipsoid axes
};

// The proxies in world space for one pose, inflated by a margin (the hair's
// thickness), laid out for the per-particle hot loop.
class PosedHairColliders {
 public:
  struct Capsule {
    glm::vec3 a, ab;
    float radius, invLengthSquared;
  };
  struct Ellipsoid {
    glm::mat4 worldFromUnit, unitFromWorld;
    // A ball holding the ellipsoid: points outside it skip the transform.
    glm::vec3 boundCenter{0.0f};
    float boundRadiusSquared = 1e30f;
    float smallestRadius = 0.0f;  // the shortest semi-axis in world space
  };

  std::vector<Capsule> capsules;
  std::vector<Ellipsoid> ellipsoids;
  std::shared_ptr<const MeshDistanceField> surface;  // fixed in world space
  float surfaceMargin = 0.0f;

  bool empty() const { return capsules.empty() && ellipsoids.empty() && !surface; }
  // Moves p onto the nearest proxy surface when it is inside one; returns
  // true and the outward surface normal when it moved.
  bool pushOut(glm::vec3& p, glm::vec3& normal) const;
  // A lower bound of the distance from p to the nearest proxy (0 inside
  // one): anything closer to p than that is outside every proxy, so
  // pushOut would leave it where it is.
  float clearance(const glm::vec3& p) const;
  // True when p lies deeper than `tolerance` inside any proxy.
  bool contains(const glm::vec3& p, float tolerance = 0.0f) const;

 private:
  bool pushOutOnce(glm::vec3& p, glm::vec3& normal) const;
};

class HairColliders {
 public:
  std::vector<ColliderCapsule> capsules;
  std::vector<ColliderEllipsoid> ellipsoids;
  // A static character's own surface (BodyProxy::surface): it has no bones,
  // so it never moves.
  std::shared_ptr<const MeshDistanceField> surface;

  void addSphere(int bone, const glm::vec3& center, float radius) {
    capsules.push_back({bone, center, center, radius});
  }
  void addCapsule(int bone, const glm::vec3& a, const glm::vec3& b, float radius) {
    capsules.push_back({bone, a, b, radius});
  }
  void addEllipsoid(int bone, const glm::vec3& center, const glm::vec3& radii,
                    const glm::quat& rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
    ellipsoids.push_back({bone, center, radii, rotation});
  }
  bool empty() const { return capsules.empty() && ellipsoids.empty() && !surface; }

  // Attaches the rest-pose shapes of `restProxy` to bones of `skeleton`:
  // its first ellipsoid (the head) to headBone, every other shape to the
  // bone whose rest segment (origin to first child's origin) is nearest to
  // the shape's centre; its surface, when the skeleton has no bones.
  static HairColliders attachToSkeleton(const BodyProxy& restProxy, const Skeleton& skeleton, int headBone);

  // World-space proxies for `worldFromBone` (indexed like the skeleton;
  // may be empty when every proxy is fixed), each grown by `margin` metres.
  PosedHairColliders posed(const std::vector<glm::mat4>& worldFromBone, float margin = 0.0f) const;
};

}  // namespace mq
