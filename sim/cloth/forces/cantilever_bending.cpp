#include "sim/cloth/forces/cantilever_bending.h"

#include "sim/cloth/parallel.h"

namespace mq::cloth {

namespace {

glm::mat3 tangentProjector(const glm::vec3& e, glm::vec3& t) {
  const float l = glm::length(e);
  t = l > 1e-12f ? e / l : glm::vec3(0.0f);
  return (glm::mat3(1.0f) - glm::outerProduct(t, t)) / std::max(l, 1e-12f);
}

}  // namespace

CantileverBending::CantileverBending(std::vector<CantileverLine> lines, size_t vertexCount) : lines_(std::move(lines)) {
  std::vector<uint32_t> count(vertexCount + 1, 0);
  for (const auto& l : lines_) {
    ++count[l.i + 1];
    ++count[l.k + 1];
    ++count[l.j + 1];
  }
  for (size_t v = 0; v < vertexCount; ++v) count[v + 1] += count[v];
  incidenceStart_ = count;
  incidence_.resize(3 * lines_.size());
  std::vector<uint32_t> fill(count.begin(), count.end() - 1);
  for (size_t n = 0; n < lines_.size(); ++n) {
    incidence_[fill[lines_[n].i]++] = uint32_t(3 * n);
    incidence_[fill[lines_[n].k]++] = uint32_t(3 * n + 1);
    incidence_[fill[lines_[n].j]++] = uint32_t(3 * n + 2);
  }
  perSlot_.resize(3 * lines_.size());
  jacobians_.resize(lines_.size());
  weight_.resize(lines_.size());
}

CantileverBending::Linearisation CantileverBending::linearise(const CantileverLine& line,
                                                              const std::vector<glm::vec3>& x) const {
  glm::vec3 t0, t1;
  const glm::mat3 P0 = tangentProjector(x[line.k] - x[line.i], t0);
  const glm::mat3 P1 = tangentProjector(x[line.j] - x[line.k], t1);
  return {{P0, -(P0 + P1), P1}, t1 - t0};
}

void CantileverBending::gather(std::vector<glm::vec3>& y) const {
  forRange(y.size(), [&](size_t b, size_t e) {
    for (size_t v = b; v < e; ++v)
      for (uint32_t k = incidenceStart_[v]; k < incidenceStart_[v + 1]; ++k) y[v] += perSlot_[incidence_[k]];
  });
}

void CantileverBending::addForces(const ClothState& s, std::vector<glm::vec3>& f) const {
  forRange(lines_.size(), [&](size_t b, size_t e) {
    for (size_t n = b; n < e; ++n) {
      const CantileverLine& line = lines_[n];
      const Linearisation lin = linearise(line, s.x);
      const glm::vec3 rate = lin.J[0] * s.v[line.i] + lin.J[1] * s.v[line.k] + lin.J[2] * s.v[line.j];
      const glm::vec3 g = line.kc * lin.r + line.kd * rate;
      for (int a = 0; a < 3; ++a) perSlot_[3 * n + a] = -(glm::transpose(lin.J[a]) * g);
    }
  });
  gather(f);
}

double CantileverBending::potentialEnergy(const ClothState& s) const {
  return deterministicSum(lines_.size(), [&](size_t n) {
    const glm::vec3 r = linearise(lines_[n], s.x).r;
    return 0.5 * lines_[n].kc * double(glm::dot(r, r));
  });
}

void CantileverBending::prepareImplicit(const ClothState& s, float h, std::vector<glm::vec3>& hKv,
                                        std::vector<glm::mat3>& diagonal) {
  forRange(lines_.size(), [&](size_t b, size_t e) {
    for (size_t n = b; n < e; ++n) {
      const CantileverLine& line = lines_[n];
      jacobians_[n] = linearise(line, s.x).J;
      weight_[n] = h * h * line.kc + h * line.kd;
      const auto& J = jacobians_[n];
      const glm::vec3 u = J[0] * s.v[line.i] + J[1] * s.v[line.k] + J[2] * s.v[line.j];
      for (int a = 0; a < 3; ++a) perSlot_[3 * n + a] = -(h * h * line.kc) * (glm::transpose(J[a]) * u);
    }
  });
  gather(hKv);
  forRange(diagonal.size(), [&](size_t b, size_t e) {
    for (size_t v = b; v < e; ++v)
      for (uint32_t k = incidenceStart_[v]; k < incidenceStart_[v + 1]; ++k) {
        const uint32_t n = incidence_[k] / 3, a = incidence_[k] % 3;
        diagonal[v] += weight_[n] * (glm::transpose(jacobians_[n][a]) * jacobians_[n][a]);
      }
  });
}

void CantileverBending::productPass(const std::vector<glm::vec3>& p) const {
  forRange(lines_.size(), [&](size_t b, size_t e) {
    for (size_t n = b; n < e; ++n) {
      const CantileverLine& line = lines_[n];
      const auto& J = jacobians_[n];
      const glm::vec3 u = weight_[n] * (J[0] * p[line.i] + J[1] * p[line.k] + J[2] * p[line.j]);
      for (int a = 0; a < 3; ++a) perSlot_[3 * n + a] = glm::transpose(J[a]) * u;
    }
  });
}

glm::mat3 CantileverBending::jacobianBlock(size_t line, int a, int b, const std::vector<glm::vec3>& x) const {
  const Linearisation lin = linearise(lines_[line], x);
  return -lines_[line].kc * (glm::transpose(lin.J[a]) * lin.J[b]);
}

}  // namespace mq::cloth
