#pragma once
// The scalp: the triangles hair grows from, in world space (rest pose).
// For the default mannequin it is the faces whose vertices are tagged
// TagScalp; for an imported character, a ScalpRegion: the faces driven by a
// head bone within an angle of an axis, or an explicit face list.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/character/character.h"

namespace mq {

struct ScalpSurface {
  std::vector<float> positions;     // 3 per vertex, world space
  std::vector<float> normals;       // 3 per vertex, outward
  std::vector<uint32_t> triangles;  // 3 per triangle

  size_t triangleCount() const { return triangles.size() / 3; }
  glm::vec3 position(size_t v) const { return {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]}; }
  glm::vec3 normal(size_t v) const { return {normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]}; }
  float area() const;  // m^2
  bool empty() const { return triangles.empty(); }
};

// Where the hair grows on a character.
struct ScalpRegion {
  enum class Kind { Tagged, BoneCone, Faces };
  Kind kind = Kind::Tagged;
  // BoneCone: faces whose vertices `bone` (or its descendants) drives and
  // whose centre lies within `angleDegrees` of `axis` (world, rest pose) seen
  // from the bone's origin.
  std::string bone = "head";
  glm::vec3 axis{0.0f, 1.0f, 0.0f};
  float angleDegrees = 70.0f;
  // Faces: triangle indices of mesh `mesh`.
  int mesh = 0;
  std::vector<uint32_t> faces;
};

// The bone that drives vertex v of `mesh` most (its attach bone when
// unskinned; -1 when none).
int dominantBone(const Mesh& mesh, size_t v);

// The scalp of `character` for `region`; throws mq::Error when it is empty
// (no tagged faces, unknown bone, faces out of range).
ScalpSurface extractScalp(const Character& character, const ScalpRegion& region);

}  // namespace mq
