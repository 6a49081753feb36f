#pragma once
// All forces of one cloth: Provot's springs (structural first, then shear,
// bend and seam springs), the optional cantilever bending, gravity and air.
// Turns the fabric's moduli into spring constants from the area each spring
// stands for, so a finer mesh of the same fabric behaves the same.

#include <memory>
#include <vector>

#include "core/garment/fabric.h"
#include "sim/cloth/cloth_settings.h"
#include "sim/cloth/cloth_topology.h"
#include "sim/cloth/forces/cantilever_bending.h"
#include "sim/cloth/forces/external_forces.h"
#include "sim/cloth/forces/spring_force.h"

namespace mq::cloth {

class ClothForces {
 public:
  ClothForces(const ClothTopology& topology, const ClothMesh& mesh, const Fabric& fabric,
              const ClothSettings& settings);

  // f = total force at the state (overwrites f).
  void computeForces(const ClothState& s, std::vector<glm::vec3>& f) const;
  double potentialEnergy(const ClothState& s) const;
  const std::vector<ForceTerm*>& terms() const { return terms_; }

  const SpringForce& springs() const { return *springs_; }
  SpringForce& springs() { return *springs_; }
  size_t structuralCount() const { return structuralCount_; }
  const CantileverBending* cantilever() const { return cantilever_.get(); }
  ExternalForces& external() { return *external_; }

  // Largest sum of spring stiffness / mass and damping / mass over the vertices:
  // bounds for the stable step of explicit integrators.
  float maxStiffnessPerMass(const std::vector<float>& mass) const;
  float maxDampingPerMass(const std::vector<float>& mass) const;

 private:
  void sumStiffnessPerVertex(const ClothTopology& topology, size_t vertexCount);

  std::unique_ptr<SpringForce> springs_;
  std::unique_ptr<CantileverBending> cantilever_;
  std::unique_ptr<ExternalForces> external_;
  std::vector<ForceTerm*> terms_;
  size_t structuralCount_ = 0;
  std::vector<float> vertexStiffness_, vertexDamping_;  // sums over incident springs and lines
};

}  // namespace mq::cloth
