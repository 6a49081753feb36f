#pragma once
// The styling flow (Hadap and Magnenat-Thalmann 2000): an ideal
// (irrotational outside vortex cores, incompressible) flow whose streamlines
// are the hair. It is the sum of the style's primitives (uniform streams,
// point sources, vortices) and of source panels over the body proxy whose
// fluxes are solved so that the boundary condition
//     v(c_i) . n_i = b_i     at every panel centre c_i (collocation points)
// holds (the panel method): b = 0 on the body, so the flow goes around it,
// and b = scalpOutflow on the scalp, so hair springs from the roots.
//
// Desingularised panels: panel j's source of flux q_j sits at s_j, a depth
// d_j (about the panel spacing) below its centre, inside the body:
//     v_j(x) = q_j / (4 pi) * (x - s_j) / |x - s_j|^3
// so the field is smooth everywhere outside the body and the condition holds
// between the collocation points too, up to the discretisation error. The
// dense system is factorised once (LU) and re-solved when primitives move. A
// volumetric Perlin field perturbs the directions.

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/hair/body_proxy.h"
#include "core/hair/hairstyle.h"
#include "core/math/perlin_noise.h"

namespace mq {

class FlowField {
 public:
  // The obstacle's panels; scalpPanel[i] marks panels whose boundary
  // condition is the scalp outflow. Factorises the panel matrix (O(n^3)),
  // done once per body.
  void setObstacle(const SurfacePanels& panels, const std::vector<uint8_t>& scalpPanel);
  // The primitives (head space, origin `headOrigin` in world) and the scalp
  // outflow; re-solves the panel strengths with the kept factorisation (O(n^2)).
  void setPrimitives(const FlowPrimitives& primitives, const glm::vec3& headOrigin, float scalpOutflow);
  void setNoise(uint32_t seed, float amplitude, float wavelength);

  // The smooth flow at x: primitives + panels.
  glm::vec3 velocity(const glm::vec3& x) const { return primitiveVelocity(x) + panelVelocity(x); }
  glm::vec3 primitiveVelocity(const glm::vec3& x) const;
  // Field of all panels at x, leaving out panel `skip` (-1: none).
  glm::vec3 panelVelocity(const glm::vec3& x, int skip = -1) const;
  // The Perlin perturbation at x (add it to a unit direction).
  glm::vec3 noise(const glm::vec3& x) const;
  bool hasNoise() const { return noiseAmplitude_ > 0.0f; }

  // v . n at panel i's centre.
  float panelNormalVelocity(int i) const { return glm::dot(velocity(panels_.centers[i]), panels_.normals[i]); }
  float boundaryTarget(int i) const { return target_[i]; }
  const SurfacePanels& panels() const { return panels_; }
  const std::vector<float>& fluxes() const { return flux_; }

 private:
  void solveStrengths();

  SurfacePanels panels_;
  std::vector<uint8_t> scalpPanel_;
  // The panel matrix's LU factors (Eigen, kept out of this header): shared
  // between copies, as it only changes with the obstacle.
  struct Factorisation;
  std::shared_ptr<const Factorisation> lu_;
  std::vector<float> flux_, target_;
  std::vector<glm::vec3> sourcePositions_;
  // Sources as padded structure of arrays for the vectorised sum: position,
  // weight q / 4 pi, squared core radius (a tiny smoothing for safety).
  std::vector<float> px_, py_, pz_, weight_, core2_;

  std::vector<UniformStream> streams_;  // world space, directions normalised
  std::vector<PointSource> sources_;
  std::vector<Vortex> vortices_;
  glm::vec3 uniform_{0.0f};  // sum of the streams
  float scalpOutflow_ = 0.0f;

  PerlinNoise perlin_{0};
  float noiseAmplitude_ = 0.0f, noiseFrequency_ = 1.0f;
};

}  // namespace mq
