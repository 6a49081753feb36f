#include "sim/cloth/forces/spring_force.h"

#include <cmath>

#include "sim/cloth/parallel.h"

namespace mq::cloth {

namespace {

struct SpringFrame {
  glm::vec3 d;  // unit direction a - b
  float length;
};

SpringFrame frameOf(const glm::vec3& xa, const glm::vec3& xb) {
  const glm::vec3 delta = xa - xb;
  const float l = glm::length(delta);
  return {l > 1e-12f ? delta / l : glm::vec3(0.0f), l};
}

glm::mat3 stiffness(const Spring& s, const SpringFrame& fr, bool filtered) {
  const glm::mat3 ddT = glm::outerProduct(fr.d, fr.d);
  float lateral = fr.length > 1e-12f ? 1.0f - s.rest / fr.length : 0.0f;
  if (filtered) lateral = std::max(lateral, 0.0f);
  return -s.k * (ddT + lateral * (glm::mat3(1.0f) - ddT));
}

}  // namespace

SpringForce::SpringForce(std::vector<Spring> springs, size_t vertexCount) : springs_(std::move(springs)) {
  std::vector<uint32_t> count(vertexCount + 1, 0);
  for (const Spring& s : springs_) {
    ++count[s.a + 1];
    ++count[s.b + 1];
  }
  for (size_t v = 0; v < vertexCount; ++v) count[v + 1] += count[v];
  incidenceStart_ = count;
  incidence_.resize(2 * springs_.size());
  std::vector<uint32_t> fill(count.begin(), count.end() - 1);
  for (size_t i = 0; i < springs_.size(); ++i) {
    incidence_[fill[springs_[i].a]++] = int32_t(i + 1);
    incidence_[fill[springs_[i].b]++] = -int32_t(i + 1);
  }
  perSpring_.resize(springs_.size());
  blocks_.resize(springs_.size());
}

void SpringForce::gather(const std::vector<glm::vec3>& perSpring, std::vector<glm::vec3>& y) const {
  forRange(y.size(), [&](size_t b, size_t e) {
    for (size_t v = b; v < e; ++v) y[v] += gatherAt(v, perSpring);
  });
}

void SpringForce::addForces(const ClothState& st, std::vector<glm::vec3>& f) const {
  forRange(springs_.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const Spring& s = springs_[i];
      const SpringFrame fr = frameOf(st.x[s.a], st.x[s.b]);
      const float relSpeed = glm::dot(st.v[s.a] - st.v[s.b], fr.d);
      perSpring_[i] = -(s.k * (fr.length - s.rest) + s.kd * relSpeed) * fr.d;
    }
  });
  gather(perSpring_, f);
}

double SpringForce::potentialEnergy(const ClothState& st) const {
  return deterministicSum(springs_.size(), [&](size_t i) {
    const Spring& s = springs_[i];
    const double stretch = double(glm::length(st.x[s.a] - st.x[s.b])) - s.rest;
    return 0.5 * s.k * stretch * stretch;
  });
}

void SpringForce::prepareImplicit(const ClothState& st, float h, std::vector<glm::vec3>& hKv,
                                  std::vector<glm::mat3>& diagonal) {
  forRange(springs_.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const Spring& s = springs_[i];
      const SpringFrame fr = frameOf(st.x[s.a], st.x[s.b]);
      const glm::mat3 K = stiffness(s, fr, true);  // df_a/dx_a, negative semi-definite
      blocks_[i] = -(h * h) * K + (h * s.kd) * glm::outerProduct(fr.d, fr.d);
      perSpring_[i] = (h * h) * (K * (st.v[s.a] - st.v[s.b]));
    }
  });
  gather(perSpring_, hKv);
  forRange(diagonal.size(), [&](size_t b, size_t e) {
    for (size_t v = b; v < e; ++v)
      for (uint32_t k = incidenceStart_[v]; k < incidenceStart_[v + 1]; ++k)
        diagonal[v] += blocks_[std::abs(incidence_[k]) - 1];
  });
}

void SpringForce::productPass(const std::vector<glm::vec3>& p) const {
  forRange(springs_.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) perSpring_[i] = blocks_[i] * (p[springs_[i].a] - p[springs_[i].b]);
  });
}

glm::mat3 SpringForce::stiffnessBlock(size_t spring, const std::vector<glm::vec3>& x, bool filtered) const {
  const Spring& s = springs_[spring];
  return stiffness(s, frameOf(x[s.a], x[s.b]), filtered);
}

}  // namespace mq::cloth
