#pragma once
// Provot's linear springs with damping along the spring:
//
//   E = 1/2 k (l - L)^2,  l = |x_a - x_b|,  d = (x_a - x_b) / l
//   f_a = -k (l - L) d - kd ((v_a - v_b) . d) d,   f_b = -f_a
//   df_a/dx_a = -k [ d d^T + (1 - L/l) (I - d d^T) ]
//
// For the implicit solve the factor (1 - L/l) is clamped at 0 so a compressed
// spring never makes the system indefinite (Choi and Ko 2002; Baraff-Witkin's
// "filtered" Jacobian). Forces are computed per spring, then gathered per
// vertex in a fixed order, so the result does not depend on the thread count.

#include <cstdint>
#include <vector>

#include "sim/cloth/forces/force_term.h"

namespace mq::cloth {

struct Spring {
  uint32_t a, b;
  float rest;  // m
  float k;     // N/m
  float kd;    // N s/m
};

class SpringForce : public ForceTerm {
 public:
  SpringForce(std::vector<Spring> springs, size_t vertexCount);

  const std::vector<Spring>& springs() const { return springs_; }

  void addForces(const ClothState& s, std::vector<glm::vec3>& f) const override;
  double potentialEnergy(const ClothState& s) const override;
  void prepareImplicit(const ClothState& s, float h, std::vector<glm::vec3>& hKv,
                       std::vector<glm::mat3>& diagonal) override;
  // productPass() only keeps p: the product is then a sum over each
  // vertex's row of the assembled matrix, kept as compact blocks in a
  // sliced-ELL layout (8 vertices side by side) that vectorises.
  void productPass(const std::vector<glm::vec3>& p) const override { product_ = &p; }
  bool productPassOnlyKeepsP() const override { return true; }
  glm::vec3 productAt(size_t vertex) const override;
  void addProductRange(size_t begin, size_t end, glm::vec3* y) const override;

  // One spring's block of the implicit matrix after prepareImplicit():
  // h^2 k S + h kd d d^T = alpha d d^T + beta I = e e^T + beta I with
  // e = sqrt(alpha) d (alpha >= 0), acting on p_a - p_b: four floats.
  struct ImplicitBlock {
    glm::vec3 e;
    float beta;
  };
  const ImplicitBlock& implicitBlock(size_t spring) const { return blocks_[spring]; }

  // df_a/dx_a of one spring (exact, or filtered as the solver uses it).
  glm::mat3 stiffnessBlock(size_t spring, const std::vector<glm::vec3>& x, bool filtered) const;

  // addForces() and prepareImplicit() fused for the implicit step, in two
  // passes the solver runs as phases of one parallel job: over springs
  // [begin, end) (each spring's frame computed once for both), then per
  // vertex v once every spring is done: f += its spring forces, and what
  // prepareImplicit() adds to hKv and diagonal. Same results as the two calls.
  void prepareStepSprings(const ClothState& s, float h, size_t begin, size_t end);
  void prepareStepVertex(size_t v, glm::vec3& f, glm::vec3& hKv, glm::mat3& diagonal);

  struct SpringFrame {
    glm::vec3 d;  // unit direction a - b
    float length;
  };

 private:
  static glm::vec3 forceOf(const Spring& s, const ClothState& st, const SpringFrame& fr);
  // Spring i's implicit block and its part of h^2 K v0 (in perSpring_).
  void linearise(size_t i, const ClothState& st, float h, const SpringFrame& fr);
  // Vertex v's sums of those, in incidence order, and its sliced-ELL slots.
  void collectImplicit(size_t v, glm::vec3& hKv, glm::mat3& diagonal);

  static constexpr size_t kLanes = 8;
  void buildRows(size_t vertexCount);

  // For every vertex, y[v] += sum over its springs of sign * perSpring[s].
  void gather(const std::vector<glm::vec3>& perSpring, std::vector<glm::vec3>& y) const;
  glm::vec3 gatherAt(size_t v, const std::vector<glm::vec3>& perSpring) const {
    glm::vec3 sum(0.0f);
    for (uint32_t k = incidenceStart_[v]; k < incidenceStart_[v + 1]; ++k) {
      const int32_t s = incidence_[k];
      sum += s > 0 ? perSpring[s - 1] : -perSpring[-s - 1];
    }
    return sum;
  }

  std::vector<Spring> springs_;
  std::vector<uint32_t> incidenceStart_;  // CSR over vertices
  std::vector<int32_t> incidence_;        // spring index + 1, negative when the vertex is b
  // Sliced ELL: the vertex at lane position j = 8 b + lane (laneVertex_[j];
  // positionOf_ is the inverse) has slots rowStart_[b] + 8 k + lane,
  // k < rowWidth_[b] (the block's largest degree; spare slots have zero
  // blocks and point at the vertex itself). Per slot: the implicit block
  // e e^T + beta I (ImplicitBlock) acting on p_v - p_other, and rowOther_
  // the other vertex's first float (3 other: no multiply in the product's
  // eight loads per slot).
  size_t slotOf(size_t v) const { return rowStart_[positionOf_[v] / kLanes] + positionOf_[v] % kLanes; }
  std::vector<int32_t> laneVertex_;
  std::vector<uint32_t> positionOf_;
  std::vector<uint32_t> rowStart_, rowWidth_;
  std::vector<int32_t> rowOther_;
  std::vector<float> rowEx_, rowEy_, rowEz_, rowBeta_;
  std::vector<ImplicitBlock> blocks_;  // per spring, filled by prepareImplicit
  mutable std::vector<glm::vec3> perSpring_;
  std::vector<glm::vec3> force_;  // per spring, for prepareStepVertex()
  mutable const std::vector<glm::vec3>* product_ = nullptr;
};

}  // namespace mq::cloth
