#pragma once
// One force of the cloth model. Each term gives its force (the negative energy
// gradient plus damping), its potential energy, and for the implicit
// integrator the pieces of the linear system of Baraff and Witkin (1998):
//
//   (M - h df/dv - h^2 df/dx) dv = h (f0 + h df/dx v0)
//
// prepareImplicit() linearises the term at the current state (adding
// h^2 (df/dx) v0 to `hKv` and the term's diagonal blocks of
// -(h df/dv + h^2 df/dx) to `diagonal`), then addProduct() adds
// -(h df/dv + h^2 df/dx) p to y, matrix-free.

#include <vector>

#include <glm/glm.hpp>

#include "sim/cloth/cloth_state.h"

namespace mq::cloth {

class ForceTerm {
 public:
  virtual ~ForceTerm() = default;
  virtual void addForces(const ClothState& s, std::vector<glm::vec3>& f) const = 0;
  virtual double potentialEnergy(const ClothState& s) const = 0;
  virtual void prepareImplicit(const ClothState& s, float h, std::vector<glm::vec3>& hKv,
                               std::vector<glm::mat3>& diagonal) = 0;
  virtual void addProduct(const std::vector<glm::vec3>& p, std::vector<glm::vec3>& y) const = 0;
};

}  // namespace mq::cloth
