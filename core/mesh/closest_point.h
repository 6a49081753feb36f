#pragma once
// Closest points between primitives: the narrow phase of collisions and of
// distance fields.

#include <glm/glm.hpp>

namespace mq {

// Closest point of triangle (a, b, c) to p, as barycentric weights (wa, wb, wc)
// (Ericson, Real-Time Collision Detection, 5.1.5).
glm::vec3 closestTriangleWeights(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

}  // namespace mq
