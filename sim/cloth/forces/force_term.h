#pragma once
// One force of the cloth model. Each term gives its force (the negative energy
// gradient plus damping), its potential energy, and for the implicit
// integrator the pieces of the linear system of Baraff and Witkin (1998):
//
//   (M - h df/dv - h^2 df/dx) dv = h (f0 + h df/dx v0)
//
// prepareImplicit() linearises the term at the current state (adding
// h^2 (df/dx) v0 to `hKv` and the term's diagonal blocks of
// -(h df/dv + h^2 df/dx) to `diagonal`), then the product
// y = -(h df/dv + h^2 df/dx) p is formed matrix-free in two passes:
// productPass(p) over the term's elements, then productAt(v) per vertex (so
// the solver fuses the per-vertex part of all terms into one loop).

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
  virtual void productPass(const std::vector<glm::vec3>& p) const = 0;
  virtual glm::vec3 productAt(size_t vertex) const = 0;
  // True when productPass() only keeps a pointer to p (no pass over p): the
  // solver may then fill p after calling it, in the same parallel job as the product.
  virtual bool productPassOnlyKeepsP() const { return false; }
  // y[v] += productAt(v) for v in [begin, end) (after productPass); terms
  // with a faster bulk form override it.
  virtual void addProductRange(size_t begin, size_t end, glm::vec3* y) const {
    for (size_t v = begin; v < end; ++v) y[v] += productAt(v);
  }
  // Both passes: y += product (for tests and simple callers).
  void addProduct(const std::vector<glm::vec3>& p, std::vector<glm::vec3>& y) const {
    productPass(p);
    for (size_t v = 0; v < y.size(); ++v) y[v] += productAt(v);
  }
};

}  // namespace mq::cloth
