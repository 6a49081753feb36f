#pragma once
// Closest points between primitives, the narrow phase of collisions.

#include <glm/glm.hpp>

#include "core/mesh/closest_point.h"

namespace mq::cloth {

// closestTriangleWeights (core/mesh/closest_point.h), from mq, and:

// Parameters (s, t) in [0,1]^2 of the closest points p0 + s (p1 - p0) and
// q0 + t (q1 - q0) of two segments (Ericson 5.1.9).
glm::vec2 closestSegmentParameters(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& q0, const glm::vec3& q1);

}  // namespace mq::cloth
