#pragma once
// Streamline tracing: a strand is the path of a particle through the flow,
// integrated with classic Runge-Kutta (RK4) on the unit direction field at a
// fixed arc-length step, so every segment has the same length and the strand
// stops exactly at its length. Points that would fall inside the body proxy
// are pushed out.

#include <glm/glm.hpp>

#include "core/hair/body_proxy.h"
#include "core/hair/flow_field.h"

namespace mq {

struct TraceOptions {
  bool perturb = true;    // add the field's Perlin noise to each step
  bool pushOut = true;    // keep every point outside the proxy
  float margin = 0.002f;  // distance kept from the proxy's surface, metres
};

// Writes `points` points (3 floats each) to `out`, root first, spaced
// length / (points - 1) apart.
void traceStreamline(const FlowField& field, const BodyProxy& proxy, const glm::vec3& root, const glm::vec3& rootNormal,
                     float length, int points, const TraceOptions& options, float* out);

}  // namespace mq
