#include "core/geometry/cellular_relief.h"

#include <algorithm>
#include <cmath>

namespace mq {

uint32_t reliefHash(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

ReliefSample cellularRelief(const glm::vec3& p) {
  const glm::vec3 base = glm::floor(p);
  float f1 = 1e9f, f2 = 1e9f;
  glm::vec3 c1(0.0f), c2(0.0f);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const glm::vec3 cell = base + glm::vec3(dx, dy, dz);
        const uint32_t seed = reliefHash(uint32_t(int32_t(cell.x)) +
                                         reliefHash(uint32_t(int32_t(cell.y)) + reliefHash(uint32_t(int32_t(cell.z)))));
        const glm::vec3 jitter(float(reliefHash(seed)), float(reliefHash(seed + 1u)), float(reliefHash(seed + 2u)));
        const glm::vec3 feature = cell + jitter * (1.0f / 4294967296.0f);
        const float d = glm::length(p - feature);
        if (d < f1) {
          f2 = f1;
          c2 = c1;
          f1 = d;
          c1 = feature;
        } else if (d < f2) {
          f2 = d;
          c2 = feature;
        }
      }
  ReliefSample s;
  const float x = std::min((f2 - f1) / kReliefFurrowWidth, 1.0f);
  s.height = 1.0f - (1.0f - x) * (1.0f - x);
  if (x < 1.0f && f1 > 1e-6f && f2 > 1e-6f) {
    const glm::vec3 gradX = ((p - c2) / f2 - (p - c1) / f1) / kReliefFurrowWidth;
    s.gradient = 2.0f * (1.0f - x) * gradX;
  }
  return s;
}

float reliefFade(float pixelsPerCell) { return std::clamp((pixelsPerCell - 4.0f) / 8.0f, 0.0f, 1.0f); }

glm::vec3 bumpedNormal(const glm::vec3& normal, const glm::vec3& gradient, float strength) {
  const glm::vec3 tangential = gradient - glm::dot(gradient, normal) * normal;
  return glm::normalize(normal - strength * tangential);
}

}  // namespace mq
