#include "core/hair/strand_tracer.h"

#include <cmath>

namespace mq {

namespace {

// Unit flow direction at x, or `fallback` where the flow stalls.
inline glm::vec3 direction(const FlowField& field, const glm::vec3& x, const glm::vec3& fallback) {
  const glm::vec3 v = field.velocity(x);
  const float len2 = glm::dot(v, v);
  return len2 > 1e-12f ? v / std::sqrt(len2) : fallback;
}

}  // namespace

void traceStreamline(const FlowField& field, const BodyProxy& proxy, const glm::vec3& root, const glm::vec3& rootNormal,
                     float length, int points, const TraceOptions& options, float* out) {
  if (points <= 0) return;
  glm::vec3 x = root;
  out[0] = x.x;
  out[1] = x.y;
  out[2] = x.z;
  const float h = points > 1 ? length / float(points - 1) : 0.0f;
  glm::vec3 previous = rootNormal;
  for (int k = 1; k < points; ++k) {
    const glm::vec3 k1 = direction(field, x, previous);
    const glm::vec3 k2 = direction(field, x + 0.5f * h * k1, k1);
    const glm::vec3 k3 = direction(field, x + 0.5f * h * k2, k2);
    const glm::vec3 k4 = direction(field, x + h * k3, k3);
    glm::vec3 step = k1 + 2.0f * k2 + 2.0f * k3 + k4;
    if (options.perturb && field.hasNoise()) step = glm::normalize(step) + field.noise(x);
    const float len = glm::length(step);
    step = len > 1e-12f ? step / len : previous;
    glm::vec3 next = x + h * step;
    if (options.pushOut && proxy.pushOut(next, options.margin)) {
      // Keep the segment length: slide along the surface instead of jumping.
      const glm::vec3 d = next - x;
      const float dl = glm::length(d);
      if (dl > 1e-9f) next = x + d * (h / dl);
      proxy.pushOut(next, options.margin);
    }
    previous = glm::normalize(next - x + 1e-12f * step);
    x = next;
    out[3 * k] = x.x;
    out[3 * k + 1] = x.y;
    out[3 * k + 2] = x.z;
  }
}

}  // namespace mq
