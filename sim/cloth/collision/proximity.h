#pragma once
// Closest points between primitives, the narrow phase of collisions.

#include <glm/glm.hpp>

namespace mq::cloth {

// Closest point of triangle (a, b, c) to p, as barycentric weights (wa, wb, wc)
// (Ericson, Real-Time Collision Detection, 5.1.5).
glm::vec3 closestTriangleWeights(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// Parameters (s, t) in [0,1]^2 of the closest points p0 + s (p1 - p0) and
// q0 + t (q1 - q0) of two segments (Ericson 5.1.9).
glm::vec2 closestSegmentParameters(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& q0, const glm::vec3& q1);

}  // namespace mq::cloth
