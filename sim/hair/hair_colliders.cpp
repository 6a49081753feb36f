#include "sim/hair/hair_colliders.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "core/hair/body_proxy.h"
#include "core/mesh/mesh_distance_field.h"
#include "core/skeleton/skeleton.h"

namespace mq {

// ---- PosedHairColliders: hot per-particle queries ----

bool PosedHairColliders::pushOutOnce(glm::vec3& p, glm::vec3& normal) const {
  bool moved = false;
  for (const Capsule& c : capsules) {
    const float t = glm::clamp(glm::dot(p - c.a, c.ab) * c.invLengthSquared, 0.0f, 1.0f);
    const glm::vec3 axisPoint = c.a + t * c.ab;
    const glm::vec3 d = p - axisPoint;
    const float d2 = glm::dot(d, d);
    if (d2 >= c.radius * c.radius) continue;
    const float len = std::sqrt(d2);
    // A particle exactly on the axis has no direction out: leave upward.
    normal = len > 1e-9f ? d / len : glm::vec3(0.0f, 1.0f, 0.0f);
    p = axisPoint + normal * c.radius;
    moved = true;
  }
  for (const Ellipsoid& e : ellipsoids) {
    const glm::vec3 fromCenter = p - e.boundCenter;
    if (glm::dot(fromCenter, fromCenter) >= e.boundRadiusSquared) continue;
    const glm::mat4& m = e.unitFromWorld;
    // unitFromWorld * (p, 1), in glm's order of operations.
    const glm::vec3 q = (glm::vec3(m[0]) * p.x + glm::vec3(m[1]) * p.y) + (glm::vec3(m[2]) * p.z + glm::vec3(m[3]));
    const float q2 = glm::dot(q, q);
    if (q2 >= 1.0f) continue;
    // Radial projection in the unit sphere's space: close to the nearest
    // surface point for the near-spherical ellipsoids of heads.
    const float len = std::sqrt(q2);
    const glm::vec3 onSphere = len > 1e-9f ? q / len : glm::vec3(0.0f, 1.0f, 0.0f);
    p = glm::vec3(e.worldFromUnit * glm::vec4(onSphere, 1.0f));
    // The gradient of |unitFromWorld p|^2 is the surface normal.
    normal = glm::normalize(glm::transpose(glm::mat3(e.unitFromWorld)) * onSphere);
    moved = true;
  }
  glm::vec3 surfaceNormal;
  if (surface && surface->pushOut(p, surfaceMargin, &surfaceNormal)) {
    normal = surfaceNormal;
    moved = true;
  }
  return moved;
}

// Where shapes overlap (head and neck, neck and shoulders) leaving one can
// enter the next: a few rounds settle the point outside all of them.
bool PosedHairColliders::pushOut(glm::vec3& p, glm::vec3& normal) const {
  bool moved = false;
  for (int round = 0; round < 4; ++round) {
    if (!pushOutOnce(p, normal)) break;
    moved = true;
  }
  return moved;
}

bool PosedHairColliders::contains(const glm::vec3& p, float tolerance) const {
  for (const Capsule& c : capsules) {
    const float t = glm::clamp(glm::dot(p - c.a, c.ab) * c.invLengthSquared, 0.0f, 1.0f);
    if (glm::length(p - (c.a + t * c.ab)) < c.radius - tolerance) return true;
  }
  for (const Ellipsoid& e : ellipsoids) {
    // Shrink by the tolerance along the smallest axis (conservative).
    const glm::vec3 q = glm::vec3(e.unitFromWorld * glm::vec4(p, 1.0f));
    const float limit = std::max(0.0f, 1.0f - tolerance / e.smallestRadius);
    if (glm::length(q) < limit) return true;
  }
  return surface && surface->distance(p) < surfaceMargin - tolerance - 1e-5f;
}

float PosedHairColliders::clearance(const glm::vec3& p) const {
  float nearest = std::numeric_limits<float>::max();
  for (const Capsule& c : capsules) {
    const float t = glm::clamp(glm::dot(p - c.a, c.ab) * c.invLengthSquared, 0.0f, 1.0f);
    nearest = std::min(nearest, glm::length(p - (c.a + t * c.ab)) - c.radius);
  }
  for (const Ellipsoid& e : ellipsoids) {
    const glm::vec3 fromCenter = p - e.boundCenter;
    const float boundGap = std::sqrt(glm::dot(fromCenter, fromCenter)) - std::sqrt(e.boundRadiusSquared);
    if (boundGap >= nearest) continue;
    // A unit-space gap |q| - 1 is at least smallestRadius times as long in
    // the world: the map from unit space stretches by no less than that.
    const glm::vec3 q = glm::vec3(e.unitFromWorld * glm::vec4(p, 1.0f));
    nearest = std::min(nearest, std::max(boundGap, (glm::length(q) - 1.0f) * e.smallestRadius));
  }
  // The field is interpolated between grid samples, so it may change up to
  // sqrt(3) times faster than the distance it samples.
  if (surface) nearest = std::min(nearest, (surface->distance(p) - surfaceMargin) / 1.75f);
  return std::max(nearest, 0.0f);
}

PosedHairColliders HairColliders::posed(const std::vector<glm::mat4>& worldFromBone, float margin) const {
  auto transformOf = [&](int bone) {
    return bone >= 0 && bone < int(worldFromBone.size()) ? worldFromBone[bone] : glm::mat4(1.0f);
  };
  PosedHairColliders out;
  out.capsules.reserve(capsules.size());
  for (const ColliderCapsule& c : capsules) {
    const glm::mat4 m = transformOf(c.bone);
    const glm::vec3 a = glm::vec3(m * glm::vec4(c.a, 1.0f));
    const glm::vec3 ab = glm::vec3(m * glm::vec4(c.b, 1.0f)) - a;
    const float len2 = glm::dot(ab, ab);
    out.capsules.push_back({a, ab, c.radius + margin, len2 > 1e-12f ? 1.0f / len2 : 0.0f});
  }
  out.ellipsoids.reserve(ellipsoids.size());
  for (const ColliderEllipsoid& e : ellipsoids) {
    const glm::mat4 boneFromUnit = glm::translate(glm::mat4(1.0f), e.center) * glm::mat4_cast(e.rotation) *
                                   glm::scale(glm::mat4(1.0f), e.radii + glm::vec3(margin));
    const glm::mat4 worldFromUnit = transformOf(e.bone) * boneFromUnit;
    // The Frobenius norm bounds how far a unit vector can be stretched.
    const glm::mat3 axes(worldFromUnit);
    const float reach2 =
        (glm::dot(axes[0], axes[0]) + glm::dot(axes[1], axes[1]) + glm::dot(axes[2], axes[2])) * 1.002f;
    const float smallest = std::min({glm::length(axes[0]), glm::length(axes[1]), glm::length(axes[2])});
    out.ellipsoids.push_back(
        {worldFromUnit, glm::inverse(worldFromUnit), glm::vec3(worldFromUnit[3]), reach2 + 1e-12f, smallest});
  }
  out.surface = surface;
  out.surfaceMargin = margin;
  return out;
}

// ---- Attaching the rest proxy to the skeleton ----

namespace {

glm::vec3 closestOnSegment(const glm::vec3& a, const glm::vec3& b, const glm::vec3& p) {
  const glm::vec3 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 1e-12f ? glm::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return a + t * ab;
}

int nearestBone(const Skeleton& skeleton, const std::vector<glm::mat4>& worldFromBone, const glm::vec3& p) {
  int best = -1;
  float bestDistance = 1e30f;
  for (int b = 0; b < skeleton.boneCount(); ++b) {
    const glm::vec3 start(worldFromBone[b][3]);
    const std::vector<int> children = skeleton.children(b);
    const glm::vec3 end = children.empty() ? start : glm::vec3(worldFromBone[children[0]][3]);
    const float d = glm::length(p - closestOnSegment(start, end, p));
    if (d < bestDistance) {
      bestDistance = d;
      best = b;
    }
  }
  return best;
}

}  // namespace

HairColliders HairColliders::attachToSkeleton(const BodyProxy& restProxy, const Skeleton& skeleton, int headBone) {
  const std::vector<glm::mat4> worldFromBone = skeleton.worldTransforms(skeleton.restPose());
  auto boneFromWorld = [&](int bone) { return bone >= 0 ? glm::inverse(worldFromBone[bone]) : glm::mat4(1.0f); };
  HairColliders colliders;
  for (size_t i = 0; i < restProxy.ellipsoids.size(); ++i) {
    const Ellipsoid& e = restProxy.ellipsoids[i];
    const int bone = i == 0 && headBone >= 0 ? headBone : nearestBone(skeleton, worldFromBone, e.center);
    const glm::mat4 m = boneFromWorld(bone);
    const glm::quat rotation = glm::normalize(glm::quat_cast(glm::mat3(m) * e.axes));
    colliders.ellipsoids.push_back({bone, glm::vec3(m * glm::vec4(e.center, 1.0f)), e.radii, rotation});
  }
  for (const Capsule& c : restProxy.capsules) {
    const int bone = nearestBone(skeleton, worldFromBone, 0.5f * (c.a + c.b));
    const glm::mat4 m = boneFromWorld(bone);
    colliders.capsules.push_back(
        {bone, glm::vec3(m * glm::vec4(c.a, 1.0f)), glm::vec3(m * glm::vec4(c.b, 1.0f)), c.radius});
  }
  if (skeleton.boneCount() == 0) colliders.surface = restProxy.surface;
  return colliders;
}

}  // namespace mq
