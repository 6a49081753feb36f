#pragma once
// A body as an implicit surface over a skeleton: primitives (tapered capsules
// and ellipsoids) attached to bones, each with a potential exp(-d_i / k_i) of
// its signed distance d_i and its own falloff k_i. Potentials are summed
// (Blinn's blobby model over distance primitives) and the skin is the level
// set sum = 1, i.e. the smooth union
//   value(p) = -kRef * ln( sum_i exp(-d_i(p) / k_i) )
// which is about a signed distance (negative inside) in metres. Grouped
// primitives contribute one potential for their union. An optional
// ground plane cuts the soles flat with a small rounded edge.

#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/marching_cubes.h"
#include "core/mesh/mesh.h"

namespace mq {

class ThreadPool;

struct ImplicitPrimitive {
  enum class Shape { RoundCone, Ellipsoid };

  Shape shape = Shape::Ellipsoid;
  int bone = -1;  // skeleton bone the primitive belongs to
  // Primitives of one group (>= 0) act as one: the union (a smooth min with
  // rounding 0.3 blend) of their distances gets one potential, so a chain of
  // segments does not bulge where two meet. Members share their blend.
  int group = -1;
  float blend = 0.01f;  // falloff k of the potential, metres
  // Local frame: q = localFromWorld * (p - origin), then divided by stretch.
  glm::vec3 origin{0.0f};
  glm::mat3 localFromWorld{1.0f};
  glm::vec3 stretch{1.0f};
  float length = 0.0f;  // round cone: along local +Y from the origin
  float radius0 = 0.0f, radius1 = 0.0f;
  glm::vec3 radii{0.0f};  // ellipsoid
  Aabb extent;            // the primitive itself
  Aabb support;           // where the potential is not negligible

  // A cone from a (radius r0) to b (radius r1) with round ends. The cross
  // section can be an ellipse: `wide` (world direction, made perpendicular to
  // the axis) is stretched by wideScale and the third axis by thickScale.
  static ImplicitPrimitive roundCone(const glm::vec3& a, const glm::vec3& b, float r0, float r1, int bone, float blend,
                                     const glm::vec3& wide = {0, 0, 0}, float wideScale = 1.0f,
                                     float thickScale = 1.0f);
  static ImplicitPrimitive ellipsoid(const glm::vec3& center, const glm::vec3& radii, int bone, float blend);

  // Signed distance (approximate for stretched shapes), negative inside.
  float distance(const glm::vec3& p) const;
};

class ImplicitBody {
 public:
  // Potentials beyond cutoff * k are dropped.
  static constexpr float kCutoff = 7.0f;
  static constexpr int kMaxGroups = 8;

  void add(const ImplicitPrimitive& primitive);
  void setGround(float height, float rounding) {
    groundHeight_ = height, groundRounding_ = rounding, hasGround_ = true;
  }
  void setReferenceBlend(float k) { referenceBlend_ = k; }

  const std::vector<ImplicitPrimitive>& primitives() const { return primitives_; }
  Aabb bounds() const;  // where the field is not "far away"

  // The field: about the signed distance to the skin, negative inside.
  float value(const glm::vec3& p) const;
  // The body posed by its skeleton: each primitive moved by the rotation and
  // translation of worldFromBind[primitive.bone] (bind space to posed world).
  // The ground plane is dropped: it does not move with the feet.
  ImplicitBody posed(const std::vector<glm::mat4>& worldFromBind) const;
  // Scales the body about the origin (a character scaled to other units).
  void scale(float factor);
  // Outward unit normal from the field gradient (central differences, step h).
  glm::vec3 normal(const glm::vec3& p, float h) const;
  // Each primitive's potential exp(-max(d_i, 0) / falloff) at p.
  void potentials(const glm::vec3& p, float falloff, std::vector<float>& out) const;

  // Samples value() on a grid covering the primitives' shapes with a margin
  // for the blending, skipping primitives far from each block of samples.
  ScalarGrid sample(float cellSize, ThreadPool* pool) const;

 private:
  // The primitives whose support contains p, and the field from those alone
  // (equal to value(p) there).
  void candidatesAt(const glm::vec3& p, std::vector<int>& out) const;
  float valueFrom(const glm::vec3& p, const int* candidates, size_t count) const;

  std::vector<ImplicitPrimitive> primitives_;
  float referenceBlend_ = 0.01f;
  bool hasGround_ = false;
  float groundHeight_ = 0.0f, groundRounding_ = 0.0f;
};

}  // namespace mq
