#include "sim/cloth/forces/external_forces.h"

#include "sim/cloth/parallel.h"

namespace mq::cloth {

ExternalForces::ExternalForces(glm::vec3 gravity, glm::vec3 wind, float airDamping, std::vector<float> vertexArea)
    : gravity_(gravity), wind_(wind), airDamping_(airDamping), vertexArea_(std::move(vertexArea)) {}

void ExternalForces::addForces(const ClothState& s, std::vector<glm::vec3>& f) const {
  forRange(s.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) f[i] += forceAt(s, i);
  });
}

double ExternalForces::potentialEnergy(const ClothState& s) const {
  return deterministicSum(s.size(), [&](size_t i) { return -double(s.mass[i]) * glm::dot(gravity_, s.x[i]); });
}

void ExternalForces::prepareImplicit(const ClothState& s, float h, std::vector<glm::vec3>&,
                                     std::vector<glm::mat3>& diagonal) {
  setStep(h);
  forRange(s.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) diagonal[i] += glm::mat3(implicitDiagonalAt(i));
  });
}

}  // namespace mq::cloth
