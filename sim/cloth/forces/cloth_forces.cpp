#include "sim/cloth/forces/cloth_forces.h"

#include <algorithm>

#include "sim/cloth/parallel.h"

namespace mq::cloth {

namespace {

// 0.8 makes the uniaxial stiffness of a regular grid of right triangles (edge
// springs k_edge = 0.8 S, diagonal springs 0.4 S, contributing 1/2 of theirs)
// equal to the fabric's stretch modulus S.
constexpr float kStructuralScale = 0.8f;

std::vector<Spring> makeSprings(const ClothTopology& topo, const ClothMesh& mesh, const Fabric& fabric,
                                const ClothSettings& settings) {
  std::vector<Spring> springs;
  auto add = [&](const SpringTopology& t, float k) {
    springs.push_back({t.a, t.b, t.restLength, k, fabric.damping * k});
  };
  for (const auto& t : topo.structural)
    add(t, kStructuralScale * fabric.stretchStiffness * t.area / (t.restLength * t.restLength));
  // Shear: a pure shear gamma stretches the quad diagonal by gamma/2, so
  // 1/2 k (L gamma/2)^2 = 1/2 G A gamma^2 gives k = 4 G A / L^2.
  for (const auto& t : topo.shear) add(t, 4.0f * fabric.shearStiffness * t.area / (t.restLength * t.restLength));
  if (settings.bending == BendingModel::Springs) {
    // A bend spring of length L = 2 d is as stiff along its length as the
    // cantilever hinge is across its segment d: k = (B w / d) / d^2 = 8 B w / L^3.
    // (Provot's bend springs resist bending only to second order, through
    // the compression of the spring, so they are weak at small angles.)
    for (size_t n = 0; n < topo.bend.size(); ++n) {
      const float L = topo.bend[n].restLength;
      add(topo.bend[n], 8.0f * fabric.bendStiffness * topo.bendLines[n].width / (L * L * L));
    }
  }
  // Seams: zero rest length, as stiff as the stiffest structural spring.
  float kSeam = 0.0f;
  for (size_t i = 0; i < topo.structural.size(); ++i) kSeam = std::max(kSeam, springs[i].k);
  for (const auto& [a, b] : mesh.seams) springs.push_back({a, b, 0.0f, kSeam, fabric.damping * kSeam});
  return springs;
}

std::vector<CantileverLine> makeCantilevers(const ClothTopology& topo, const Fabric& fabric) {
  std::vector<CantileverLine> lines;
  for (const BendLine& b : topo.bendLines) {
    const float kc = fabric.bendStiffness * b.width / (0.5f * (b.length0 + b.length1));
    lines.push_back({b.i, b.k, b.j, kc, fabric.damping * kc});
  }
  return lines;
}

}  // namespace

ClothForces::ClothForces(const ClothTopology& topology, const ClothMesh& mesh, const Fabric& fabric,
                         const ClothSettings& settings) {
  const size_t n = mesh.vertexCount();
  springs_ = std::make_unique<SpringForce>(makeSprings(topology, mesh, fabric, settings), n);
  structuralCount_ = topology.structural.size();
  terms_.push_back(springs_.get());
  if (settings.bending == BendingModel::Cantilever) {
    cantilever_ = std::make_unique<CantileverBending>(makeCantilevers(topology, fabric), n);
    terms_.push_back(cantilever_.get());
  }
  external_ =
      std::make_unique<ExternalForces>(settings.gravity, settings.wind, settings.airDamping, topology.vertexArea);
  terms_.push_back(external_.get());
  sumStiffnessPerVertex(topology, n);
}

void ClothForces::computeForces(const ClothState& s, std::vector<glm::vec3>& f) const {
  f.assign(s.size(), glm::vec3(0.0f));
  for (const ForceTerm* t : terms_) t->addForces(s, f);
}

double ClothForces::potentialEnergy(const ClothState& s) const {
  double e = 0.0;
  for (const ForceTerm* t : terms_) e += t->potentialEnergy(s);
  return e;
}

float ClothForces::maxStiffnessPerMass(const std::vector<float>& mass) const {
  float worst = 0.0f;
  for (size_t i = 0; i < mass.size(); ++i) worst = std::max(worst, 2.0f * vertexStiffness_[i] / mass[i]);
  return worst;
}

float ClothForces::maxDampingPerMass(const std::vector<float>& mass) const {
  float worst = 0.0f;
  for (size_t i = 0; i < mass.size(); ++i) worst = std::max(worst, 2.0f * vertexDamping_[i] / mass[i]);
  return worst;
}

void ClothForces::sumStiffnessPerVertex(const ClothTopology& topology, size_t vertexCount) {
  vertexStiffness_.assign(vertexCount, 0.0f);
  vertexDamping_.assign(vertexCount, 0.0f);
  for (const Spring& s : springs_->springs()) {
    for (uint32_t v : {s.a, s.b}) {
      vertexStiffness_[v] += s.k;
      vertexDamping_[v] += s.kd;
    }
  }
  if (!cantilever_) return;
  // Translational stiffness of a line: kc |dr/dx|^2 with |dr/dx_i| = 1/l0.
  for (size_t n = 0; n < cantilever_->lines().size(); ++n) {
    const CantileverLine& l = cantilever_->lines()[n];
    const BendLine& b = topology.bendLines[n];
    const float gi = 1.0f / b.length0, gj = 1.0f / b.length1, gk = gi + gj;
    vertexStiffness_[l.i] += l.kc * gi * gi;
    vertexStiffness_[l.j] += l.kc * gj * gj;
    vertexStiffness_[l.k] += l.kc * gk * gk;
    vertexDamping_[l.i] += l.kd * gi * gi;
    vertexDamping_[l.j] += l.kd * gj * gj;
    vertexDamping_[l.k] += l.kd * gk * gk;
  }
}

}  // namespace mq::cloth
