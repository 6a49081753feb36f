#pragma once
// Section cones (survey 1.2.5, "Contrainte sur la taille des sections"):
// around each bone a cone with elliptic bases, fitted at bind time to the
// rest skin's sections at 15 % and 85 % of the bone and interpolated linearly
// between them. Each base keeps two ellipses: the memorised section (same
// area and second moments as the section) and the enclosing one (CGAL's
// Min_ellipse_2). A cone much wider than its bone (pelvis, chest, a clavicle
// cut across the torso) is not a limb and stays unused.
//
// The cones-corrected skinning runs dual quaternion skinning, which already
// keeps the sections the survey's cones memorise (M1 0.98-1.00 on the
// mannequin), and then adds what DQS lacks: contact. Each limb joint (the
// head of a bone with a cone) has a plane through the posed joint, normal to
// the child's rest axis turned half way between the parent's rotation and
// the child's. A vertex within a few limb radii of that joint keeps the side
// it had at rest, so where a bent limb meets its parent the skin makes a
// crease on that plane instead of crossing itself. Creases join two limbs
// (elbow, knee, wrist, ankle), not a limb and the torso.
//
// Tried and measured worse on the mannequin (skin-report: more crossings;
// docs/performance.md): clamping each blend vertex's radial distance in its
// bones' cones to a band around rest, and pushing vertices out of the
// neighbour bone's enclosing cone.

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/mesh.h"
#include "core/skinning/ellipse.h"

namespace mq {

class Skeleton;
class ThreadPool;

struct SectionCone {
  static constexpr float kBaseNear = 0.15f, kBaseFar = 0.85f;  // base positions along the bone

  bool valid = false;  // fitted: a section loop surrounds the axis at both bases
  bool limb = false;   // fitted and no wider than 0.6 of its bone (not the torso): gets creases
  // The cone's frame in the mesh's bind space: head, unit axis towards the
  // tail, and two unit directions across it (the ellipses' chart).
  glm::dvec3 head{0.0}, axis{0.0, 1.0, 0.0}, side{1.0, 0.0, 0.0}, front{0.0, 0.0, 1.0};
  double length = 0.0;
  Ellipse2 minimum[2], enclosing[2];  // at kBaseNear and kBaseFar

  struct Point {
    double s = 0.0;             // along the bone, 0 at the head, 1 at the tail
    glm::dvec3 radial{0.0};     // from the cone's centre line to the point, across the axis
    double rho = 0.0;           // |radial| / the minimum ellipse's radius that way
    double rhoEnclosing = 0.0;  // |radial| / the enclosing ellipse's radius that way
  };
  // A bind-space point in cone coordinates (for inspecting a fit).
  Point locate(const glm::dvec3& p) const;
};

struct SectionCones {
  std::vector<SectionCone> cones;    // per skin joint
  std::vector<int16_t> parentJoint;  // per skin joint, its nearest skin-joint ancestor (-1: none)
  // Per vertex: the child joint whose plane it keeps to (-1: none), which
  // side (-1 the parent's, +1 the child's), and the signed distance to the
  // plane it may not pass.
  std::vector<int16_t> creaseJoint;
  std::vector<int8_t> creaseSide;
  std::vector<float> creaseBound;
  std::vector<uint32_t> visited;  // vertices with a crease
  // Vertex -> triangles, to recompute the normals of moved vertices.
  std::vector<uint32_t> triangleStart, triangleList;
};

// Fits the cone of every skin joint to the mesh's rest skin and records each
// vertex's crease. `skeleton` gives the bone hierarchy.
std::shared_ptr<const SectionCones> bindSectionCones(const Mesh& mesh, const Skeleton& skeleton);
// The cones alone, one per skin joint (the torso's too, marked not limb).
std::vector<SectionCone> fitSectionCones(const Mesh& mesh, const Skeleton& skeleton);
// Each skin joint's nearest ancestor among the skin's joints (-1: none).
std::vector<int> skinJointParents(const SkinBinding& skin, const Skeleton& skeleton);

// Applies the creases to dual-quaternion-skinned positions (and recomputes
// the moved vertices' normals, if given) in place; the skinning matrices come from worldFromBone and the skin's
// inverse bind matrices. Threaded results equal single-threaded ones.
void correctWithSectionCones(const Mesh& mesh, const SectionCones& cones, const std::vector<glm::mat4>& worldFromBone,
                             float* positions, float* normals, ThreadPool* pool);

}  // namespace mq
