#pragma once
// The dynamic state of a cloth as structure of arrays: one contiguous array of
// vec3 (3 floats) per quantity, so loops split into ranges for the thread pool.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace mq::cloth {

struct ClothState {
  std::vector<glm::vec3> x;    // positions, m
  std::vector<glm::vec3> v;    // velocities, m/s
  std::vector<float> mass;     // kg
  std::vector<float> invMass;  // 1/kg; 0 for vertices the solver must not move (pins)
  // Outward normal of a resting contact at the start of the step (zero: none);
  // the implicit solver keeps such a vertex's normal velocity at zero.
  std::vector<glm::vec3> contactNormal;
  std::vector<float> contactSpeed;  // the surface's velocity along contactNormal

  size_t size() const { return x.size(); }
};

// The input every garment feeds the solver: a triangle mesh with a mass per
// vertex (the rest shape is the given positions).
struct ClothMesh {
  std::vector<float> positions;     // 3 per vertex
  std::vector<uint32_t> triangles;  // 3 per triangle
  std::vector<float> masses;        // per vertex, kg; empty = from the fabric's mass per area
  // Pairs of vertices to sew (zero rest length springs), may be empty.
  std::vector<std::pair<uint32_t, uint32_t>> seams;

  size_t vertexCount() const { return positions.size() / 3; }
};

inline glm::vec3 vec3At(const std::vector<float>& flat, size_t i) {
  return {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
}

}  // namespace mq::cloth
