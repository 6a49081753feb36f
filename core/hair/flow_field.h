#pragma once
// The styling flow (Hadap and Magnenat-Thalmann 2000): an ideal
// (irrotational outside vortex cores, incompressible) flow whose streamlines
// are the hair. It is the sum of the style's primitives (uniform streams,
// point sources, vortices) and of source panels over the body proxy whose
// strengths are solved so that the boundary condition
//     v(c_i) . n_i = b_i     at every panel centre c_i
// holds (the panel method): b = 0 on the body, so the flow goes around it,
// and b = scalpOutflow on the scalp, so hair springs from the roots.
//
// Panel j is a source of density sigma_j over area A_j; seen from a point x
// it acts as a point source with a smoothed core d_j:
//     v_j(x) = sigma_j A_j / (4 pi) * (x - c_j) / (|x - c_j|^2 + d_j^2)^(3/2)
// and on its own centre it contributes sigma_j / 2 along n_j (the flat-panel
// limit from outside). A volumetric Perlin field perturbs the directions.

#include <cstdint>
#include <vector>

#include <Eigen/Dense>
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

  // v . n at panel i's centre, its own contribution sigma_i / 2 included.
  float panelNormalVelocity(int i) const;
  float boundaryTarget(int i) const { return target_[i]; }
  const SurfacePanels& panels() const { return panels_; }
  const std::vector<float>& strengths() const { return sigma_; }

 private:
  void solveStrengths();

  SurfacePanels panels_;
  std::vector<uint8_t> scalpPanel_;
  Eigen::PartialPivLU<Eigen::MatrixXf> lu_;
  std::vector<float> sigma_, target_;
  // Panels as padded structure of arrays for the vectorised sum: centre,
  // weight sigma A / 4 pi, squared core radius.
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
