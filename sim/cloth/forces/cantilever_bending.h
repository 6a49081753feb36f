#pragma once
// Bending as a cantilever (Villard and Borouchaki, "Adaptive meshing for cloth
// animation", Engineering with Computers 20, 2005): along every nearly
// straight line of edges i-k-j, the segment k-j is a cantilever clamped at k
// in the direction of i-k. A cantilever of length L and bending rigidity B w
// (B per unit width, w the width of cloth the line stands for) answers a
// deflection angle theta with the moment M = 2 B w theta / L (tip load).
// Along a chain of such hinges, one every L, that doubles the bending
// stiffness of the continuous beam (M = B w kappa, theta = kappa L gives
// k_c = B w / L), so we use k_c = B w / L and a fabric's measured B gives the
// droop of an elastic beam (tests/sim/cloth_bending_test.cpp). We write it as
// an energy so the implicit solver gets a consistent Jacobian:
//
//   E = 1/2 k_c |r|^2,  r = t_1 - t_0,  t_0 = (x_k - x_i)/|x_k - x_i|,  t_1 = (x_j - x_k)/|x_j - x_k|
//
// (|r| = 2 sin(theta/2) ~ theta). With P_e = (I - t t^T)/|e|: dr/dx_i = P_0,
// dr/dx_k = -(P_0 + P_1), dr/dx_j = P_1; force f = -k_c J^T r, and the
// implicit solver uses the Gauss-Newton Jacobian -k_c J^T J (exact when the
// line is straight, r = 0). Rest shape: straight lines (flat panels).

#include <array>
#include <cstdint>
#include <vector>

#include "sim/cloth/forces/force_term.h"

namespace mq::cloth {

struct CantileverLine {
  uint32_t i, k, j;
  float kc;  // N m: rotational stiffness B w / L
  float kd;  // N m s: damping of the rotation rate
};

class CantileverBending : public ForceTerm {
 public:
  CantileverBending(std::vector<CantileverLine> lines, size_t vertexCount);

  const std::vector<CantileverLine>& lines() const { return lines_; }

  void addForces(const ClothState& s, std::vector<glm::vec3>& f) const override;
  double potentialEnergy(const ClothState& s) const override;
  void prepareImplicit(const ClothState& s, float h, std::vector<glm::vec3>& hKv,
                       std::vector<glm::mat3>& diagonal) override;
  void productPass(const std::vector<glm::vec3>& p) const override;
  glm::vec3 productAt(size_t vertex) const override {
    glm::vec3 sum(0.0f);
    for (uint32_t k = incidenceStart_[vertex]; k < incidenceStart_[vertex + 1]; ++k) sum += perSlot_[incidence_[k]];
    return sum;
  }

  // The Gauss-Newton Jacobian block d f_a / d x_b (a, b in 0..2 for i, k, j) of one line.
  glm::mat3 jacobianBlock(size_t line, int a, int b, const std::vector<glm::vec3>& x) const;

 private:
  struct Linearisation {
    std::array<glm::mat3, 3> J;  // dr/dx_i, dr/dx_k, dr/dx_j
    glm::vec3 r;
  };
  Linearisation linearise(const CantileverLine& line, const std::vector<glm::vec3>& x) const;
  void gather(std::vector<glm::vec3>& y) const;

  std::vector<CantileverLine> lines_;
  std::vector<uint32_t> incidenceStart_;
  std::vector<uint32_t> incidence_;                  // 3 * line + slot
  std::vector<std::array<glm::mat3, 3>> jacobians_;  // implicit: J per line
  std::vector<float> weight_;                        // implicit: h^2 kc + h kd per line
  mutable std::vector<glm::vec3> perSlot_;           // 3 per line
};

}  // namespace mq::cloth
