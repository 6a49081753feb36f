#pragma once
// Forces on every vertex alone: gravity m g, and air drag against the wind
// f = -c A (v - w), with A the cloth area a vertex stands for (a third of its
// triangles), c the air damping in N s/m^3 and w the wind velocity.

#include <vector>

#include "sim/cloth/forces/force_term.h"

namespace mq::cloth {

class ExternalForces : public ForceTerm {
 public:
  ExternalForces(glm::vec3 gravity, glm::vec3 wind, float airDamping, std::vector<float> vertexArea);

  void addForces(const ClothState& s, std::vector<glm::vec3>& f) const override;
  double potentialEnergy(const ClothState& s) const override;  // gravity only
  void prepareImplicit(const ClothState& s, float h, std::vector<glm::vec3>& hKv,
                       std::vector<glm::mat3>& diagonal) override;
  void productPass(const std::vector<glm::vec3>& p) const override { p_ = &p; }
  bool productPassOnlyKeepsP() const override { return true; }
  glm::vec3 productAt(size_t vertex) const override { return (h_ * airDamping_ * vertexArea_[vertex]) * (*p_)[vertex]; }
  // Per vertex, for the implicit solver's fused pass: the force (as
  // addForces adds it) and the diagonal of the implicit matrix (a multiple
  // of I, as prepareImplicit adds it) for the step h.
  glm::vec3 forceAt(const ClothState& s, size_t i) const {
    return s.mass[i] * gravity_ - airDamping_ * vertexArea_[i] * (s.v[i] - wind_);
  }
  void setStep(float h) { h_ = h; }
  float implicitDiagonalAt(size_t i) const { return h_ * airDamping_ * vertexArea_[i]; }
  // The same, without a virtual call per vertex (the solver's hot loop).
  void addProductRange(size_t begin, size_t end, glm::vec3* y) const override {
    const glm::vec3* p = p_->data();
    for (size_t v = begin; v < end; ++v) y[v] += (h_ * airDamping_ * vertexArea_[v]) * p[v];
  }

 private:
  glm::vec3 gravity_, wind_;
  float airDamping_;
  std::vector<float> vertexArea_;
  float h_ = 0.0f;
  mutable const std::vector<glm::vec3>* p_ = nullptr;
};

}  // namespace mq::cloth
