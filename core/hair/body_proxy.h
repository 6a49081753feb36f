#pragma once
// A coarse stand-in for the head and upper body that hair flows around and
// must never enter: an ellipsoid for the head and capsules for the neck,
// chest and shoulders. Cheap inside tests and push-out, and the surface the
// flow's source panels are spread over.

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/character/character.h"
#include "core/mesh/mesh_distance_field.h"

namespace mq {

struct Ellipsoid {
  glm::vec3 center{0.0f};
  glm::mat3 axes{1.0f};  // columns: the ellipsoid's orthonormal frame in world space
  glm::vec3 radii{0.1f};
};

struct Capsule {
  glm::vec3 a{0.0f}, b{0.0f};
  float radius = 0.05f;
};

// Source panels over a closed surface: centre, outward normal, area, and how
// deep below the centre the panel's source may sit (inside the shape).
struct SurfacePanels {
  std::vector<glm::vec3> centers, normals;
  std::vector<float> areas, depths;
  size_t size() const { return centers.size(); }
};

class BodyProxy {
 public:
  std::vector<Ellipsoid> ellipsoids;  // the first one is the head
  std::vector<Capsule> capsules;
  // The mesh itself where it is known and fixed (a static mesh's head and
  // shoulders): hair stays out of it as out of the shapes, while the flow
  // still goes around the shapes. Shared: proxies are copied around.
  std::shared_ptr<const MeshDistanceField> surface;

  // Builds a coarse grid over the shapes recording, per cell, which shapes
  // (grown by up to kMaxCachedMargin) may reach into it, so contains() and
  // pushOut() test only those. Call after editing the shapes; a stale grid is
  // ignored when the shape counts differ, not when shapes move.
  void updateBounds();
  static constexpr float kMaxCachedMargin = 0.01f;

  bool empty() const { return ellipsoids.empty() && capsules.empty(); }
  glm::vec3 headCenter() const { return ellipsoids.empty() ? glm::vec3(0.0f) : ellipsoids[0].center; }

  // True when p is inside some shape or the surface grown by `margin`
  // (negative: shrunk).
  bool contains(const glm::vec3& p, float margin = 0.0f) const;
  // Moves p out of every shape and the surface it is inside, to `margin`
  // beyond. Returns true when p moved.
  bool pushOut(glm::vec3& p, float margin) const;
  // About `targetCount` panels over the union's surface (panels inside
  // another shape are dropped: they are not on the boundary).
  SurfacePanels makePanels(int targetCount) const;

 private:
  bool insideShapes(const glm::vec3& p, float margin) const;
  bool insideSurface(const glm::vec3& p, float margin) const;
  // Bit i set: shape i (ellipsoids, then capsules) may hold p grown by margin.
  uint64_t candidates(const glm::vec3& p, float margin) const;
  // Per cell an index into the few distinct masks (a small grid stays in cache).
  std::vector<uint16_t> cellMask_;
  std::vector<uint64_t> maskPalette_;
  glm::vec3 gridOrigin_{0.0f};
  float cellSize_ = 1.0f;
  glm::ivec3 gridDims_{0};
  size_t gridShapeCount_ = 0;
};

// A sphere head (tests and characters without a head bone).
BodyProxy sphereProxy(const glm::vec3& center, float radius);

// Fits the proxy to a character in its rest pose: an ellipsoid in the head
// bone's frame fitted (least squares) to the vertices the head bone drives,
// shrunk so that the scalp vertices (`scalpPoints`, world space, may be
// empty) lie on or outside it; capsules around the neck, chest, clavicles
// and upper arms (bones found by walking from the head bone). A character
// without bones gets the head alone, fitted to the top of its mesh
// (static_head.h) and the mesh's own surface around it. Throws mq::Error when the head bone does not exist or
// drives no vertex.
BodyProxy fitBodyProxy(const Character& character, const std::string& headBone,
                       const std::vector<glm::vec3>& scalpPoints);

}  // namespace mq
