#pragma once
// Section cones (survey 1.2.5, "Contrainte sur la taille des sections"):
// around each bone a cone with elliptic bases, fitted at bind time to the
// rest skin's sections at 15 % and 85 % of the bone, and interpolated
// linearly between them. Each base keeps two ellipses: the memorised minimum
// section (same area and second moments as the section) and the enclosing
// one (CGAL's Min_ellipse_2), used for contact.
//
// At run time, after dual quaternion skinning, every vertex of a blend zone
// is measured in the cone of each bone that moves it, in that bone's bind
// frame: its radial distance rho from the cone axis over the minimum
// ellipse's radius in that direction, against its rest value rho0. The
// correction keeps rho within [tau rho0, kappa rho0] (the section never
// shrinks below tau of its memorised size, and DQS's bulge stays below
// kappa), each bone's displacement weighted by the vertex's weight of it.
// Then each vertex that was outside a neighbour bone's enclosing cone at rest
// is pushed back onto that cone's surface if the pose drove it inside, so a
// fold makes a crease instead of crossing the neighbour's skin.

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh/mesh.h"
#include "core/skinning/ellipse.h"

namespace mq {

class Skeleton;
class ThreadPool;
struct Character;

struct SectionCone {
  static constexpr float kBaseNear = 0.15f, kBaseFar = 0.85f;  // base positions along the bone

  bool valid = false;
  // The cone's frame in the mesh's bind space: head, unit axis towards the
  // tail, and two unit directions across it (the ellipses' chart).
  glm::dvec3 head{0.0}, axis{0.0, 1.0, 0.0}, side{1.0, 0.0, 0.0}, front{0.0, 0.0, 1.0};
  double length = 0.0;
  Ellipse2 minimum[2], enclosing[2];  // at kBaseNear and kBaseFar

  struct Point {
    double s = 0.0;            // along the bone, 0 at the head, 1 at the tail
    glm::dvec3 radial{0.0};    // from the cone's centre line to the point, across the axis
    double rho = 0.0;          // |radial| / the minimum ellipse's radius that way
    double rhoEnclosing = 0.0; // |radial| / the enclosing ellipse's radius that way
  };
  // A bind-space point in cone coordinates.
  Point locate(const glm::dvec3& p) const;
};

struct SectionCones {
  // Tunables: the least and largest section kept, relative to the rest.
  static constexpr float kMinimumSection = 0.95f;  // tau
  static constexpr float kBulgeLimit = 1.05f;      // kappa
  static constexpr int kContacts = 4;              // neighbour cones checked per vertex

  std::vector<SectionCone> cones;  // per skin joint
  std::vector<float> restRho;      // per vertex and influence slot; < 0: no cone, or no weight
  std::vector<int16_t> contacts;   // kContacts per vertex: skin joints to stay out of; -1 unused
  std::vector<uint32_t> visited;   // vertices the correction looks at
  // Vertex -> triangles, to recompute the normals of moved vertices.
  std::vector<uint32_t> triangleStart, triangleList;
};

// Fits the cones of every skin joint to the mesh's rest skin and records each
// vertex's rest coordinates. `skeleton` gives the bone hierarchy.
std::shared_ptr<const SectionCones> bindSectionCones(const Mesh& mesh, const Skeleton& skeleton);

// Binds the cones of every skinned mesh of the character that has none yet.
void bindSectionCones(Character& character);

// Corrects dual-quaternion-skinned positions (and their normals, if given)
// in place; the skinning matrices come from worldFromBone and the skin's
// inverse bind matrices. Threaded results equal single-threaded ones.
void correctWithSectionCones(const Mesh& mesh, const SectionCones& cones, const std::vector<glm::mat4>& worldFromBone,
                             float* positions, float* normals, ThreadPool* pool);

}  // namespace mq
