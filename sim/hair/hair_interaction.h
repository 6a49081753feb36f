#pragma once
// Hair-hair interaction by loosely connected particles (survey 2.5.2; Hadap
// and Magnenat-Thalmann, "Modeling dynamic hair as a continuum", 2001): the
// guide particles are SPH particles of the hair's volume. Each substep:
//   density   rho_i = sum over particles j of other strands of W(|x_i - x_j|),
//             W(r) = (1 - r^2/R^2)^3 for r < R
//   pressure  P_i = clamp(rho_i / rho0_i - 1, 0, 1), rho0_i the density the
//             groom gave the particle (at least W(R/2): a lone strand resists
//             a strand crossing it)
//   push      p_i += volume R sum_j (P_i + P_j)/2 g_ij u_ij / max(1, sum_j g_ij),
//             g = (1 - r/R)^2, u_ij the unit vector from j to i, and the
//             approach speed along u_ij of a compressed pair is removed
//   friction  v_i += friction sum_j W_ij (v_j - v_i) / (1 + sum_j W_ij)
// on the substep's predicted positions p (velocity changes as h dv), before
// the strands restore their lengths and leave the body (position based, so
// the corrections become velocities there). Wisps pushed together spread
// back to the groom's density and sliding hair drags its neighbours
// (internal friction). Every particle reads the predicted state only
// (Jacobi): results do not depend on the thread count.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "sim/hair/particle_grid.h"

namespace mq {

struct HairInteractionParams {
  float volume = 0.0f;    // share of the excess density pushed back per 1/60 s (0 off .. 1)
  float friction = 0.0f;  // share of the neighbours' relative velocity taken per 1/60 s (0 .. 1)
  float radius = 0.0f;    // kernel radius R in metres; 0: from the guides' spacing and segment length
  bool enabled() const { return volume > 0.0f || friction > 0.0f; }
};

class HairInteraction {
 public:
  // The strands at rest (Strands::points layout, roots first): the rest
  // densities and, unless params.radius is set, the kernel radius.
  void setRest(const std::vector<float>& restPoints, size_t strandCount, int pointsPerStrand,
               const HairInteractionParams& params);
  void setParams(const HairInteractionParams& params);
  float radius() const { return radius_; }

  // Corrects the predicted positions of a substep of h (one per particle;
  // `positions` the positions before it, Strands::points layout): the push,
  // plus h times the velocity change (velocity = (predicted - position) / h).
  // Roots are not moved.
  void apply(std::vector<glm::vec3>& predicted, const std::vector<float>& positions, float h);

  // Particles whose density exceeded their rest density at the last apply().
  size_t compressedCount() const { return compressed_; }

 private:
  void buildGrid(const std::vector<glm::vec3>& positions);
  template <class Each, class Visit, class Done>
  void forNeighbourRange(size_t begin, size_t end, Each&& each, Visit&& visit, Done&& done) const;
  void computeDensities(const std::vector<glm::vec3>& positions);

  HairInteractionParams params_;
  size_t strandCount_ = 0;
  int pointsPerStrand_ = 0;
  float radius_ = 0.01f;
  std::vector<float> restDensity_;
  // The particles in cell order (grid_.order()[e] the particle at place e),
  // with their positions and strands in that order.
  ParticleGrid grid_;
  std::vector<uint32_t> sortedStrands_;
  std::vector<glm::vec3> sortedPositions_;
  // Each block of kBlock particles (cell order) lists their neighbours;
  // neighbourEnd_[e] ends particle e's run in its block's list.
  struct Neighbour {
    uint32_t particle;  // cell order
    float distance2;
  };
  static constexpr size_t kBlock = 1024;
  std::vector<std::vector<Neighbour>> blockNeighbours_;
  std::vector<uint32_t> neighbourEnd_;
  // Scratch of apply(), in cell order.
  std::vector<float> sortedDensity_, pressure_;
  std::vector<glm::vec3> sortedVelocities_, push_, dv_;
  size_t compressed_ = 0;
};

// Pairs of guide segments of different strands closer than `distance` (root
// segments excluded): how often hair passes through hair in a frame.
size_t closeSegmentPairs(const std::vector<float>& points, size_t strandCount, int pointsPerStrand, float distance);
// The mean distance from a strand's root to the nearest other root.
float meanRootSpacing(const std::vector<float>& points, size_t strandCount, int pointsPerStrand);

}  // namespace mq
