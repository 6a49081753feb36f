#pragma once
// The coarse level of the implicit solve's two-level preconditioner.
//
// Block Jacobi (the inverse of A's 3x3 diagonal blocks) damps a residual that
// varies from vertex to vertex within a few iterations but hardly touches a
// smooth one: on stiff cloth the stretch springs tie thousands of vertices
// into slow, nearly rigid motions, and CG spends its iterations on them. The
// coarse level solves for those motions directly: the cloth's vertices are
// grouped into patches of about kPatchSize vertices connected by springs
// (fixed with the topology), each patch moves as one rigid translation
// (piecewise-constant prolongation P), and the Galerkin matrix
// A_c = P^T S A S P (S the solver's filter) of 3 unknowns per patch is
// factorised once per step. Applied additively,
//
//   z = D^-1 r + S P A_c^-1 P^T r,
//
// the preconditioner stays symmetric positive definite (A_c takes the
// springs' blocks exactly and the other terms' diagonal blocks only, which
// keeps it positive definite), so CG stays valid whatever the patches.
// The factorisation exploits the patches' order (grown in breadth-first
// order, so A_c is banded): an envelope Cholesky in double.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "sim/cloth/cloth_state.h"
#include "sim/cloth/forces/spring_force.h"

namespace mq::cloth {

class CoarseCorrection {
 public:
  static constexpr size_t kPatchSize = 64;

  // Groups the vertices into patches along the springs (once per topology).
  void build(const SpringForce& springs, size_t vertexCount);
  bool built(size_t vertexCount) const { return patchOf_.size() == vertexCount && vertexCount > 0; }
  size_t patchCount() const { return patchCount_; }
  const std::vector<uint32_t>& patchOf() const { return patchOf_; }

  // A_c for this step's linearisation: `otherDiagonal` holds A's diagonal
  // blocks without the springs' part (mass and the other terms), the springs
  // their implicit blocks.
  void assemble(const ClothState& s, const std::vector<glm::mat3>& otherDiagonal, const SpringForce& springs);
  // The same in three steps, so the second can run in parallel: the
  // filters of this step's pins and contacts, A_c's rows of the patches
  // [begin, end) (the ranges of a partition, in any order), then the
  // factorisation of all of it.
  void prepareAssembly(const ClothState& s);
  void assemblePatches(const ClothState& s, const std::vector<glm::mat3>& otherDiagonal, const SpringForce& springs,
                       size_t begin, size_t end);
  void factorise();

  // Coarse solution of the (filtered) residual r: fills perPatch (one vec3 per
  // patch, to be added as S_i perPatch[patchOf(i)]) and returns r . S P perPatch.
  double solve(const std::vector<glm::vec3>& r, std::vector<glm::vec3>& perPatch);
  // The same in two steps, so the first can run in parallel (patch ranges):
  // P^T r for the patches [begin, end), then the solve of all patches.
  void restrictResidual(const std::vector<glm::vec3>& r, size_t begin, size_t end);
  double solveRestricted(std::vector<glm::vec3>& perPatch);

 private:
  double& at(size_t i, size_t j) { return matrix_[i * order_ + j]; }

  std::vector<uint32_t> patchOf_;
  std::vector<uint32_t> patchStart_, patchVertices_;  // CSR: each patch's vertices, in vertex order
  size_t patchCount_ = 0, order_ = 0;
  std::vector<double> matrix_;         // dense storage, lower triangle used
  std::vector<uint32_t> firstColumn_;  // envelope: first non-zero column per row
  std::vector<uint8_t> dead_;          // unknowns with no stiffness (a pinned patch)
  static constexpr uint32_t kFree = ~0u;
  std::vector<uint32_t> filterOf_;         // per vertex: kFree (S = I) or its index in filters_
  std::vector<glm::mat3> filters_;         // S of the pinned and contact vertices
  std::vector<glm::dmat3> patchDiagonal_;  // A_c's diagonal blocks while assembling
  std::vector<double> rhs_, x_;
};

}  // namespace mq::cloth
