#pragma once
// Skin micro-relief: the plateaus and furrows of the skin's surface pattern
// as a cellular (Worley) height, with its gradient for bump mapping (survey
// §1.3.3, "Ridules et micro-structure": a bump map generated from Voronoi
// diagrams [IYT93] beats a photo texture). The skin shader in
// render/skin_shader.cpp evaluates the same function in GLSL on the rest
// position; this C++ twin is its specification and what the tests check
// (oracle O26).
//
// In cell units (p = rest position / cell size), with F1 <= F2 the distances
// to the two nearest jittered feature points of the integer lattice:
//   x = min((F2 - F1) / furrowWidth, 1),  h = 1 - (1 - x)^2
// 0 on the Voronoi edges (the furrows), 1 on the cells' plateaus, smooth
// where they meet. grad F_i = (p - c_i) / F_i.

#include <cstdint>

#include <glm/glm.hpp>

namespace mq {

inline constexpr float kReliefFurrowWidth = 0.35f;  // of a cell

struct ReliefSample {
  float height = 0.0f;       // in [0, 1]
  glm::vec3 gradient{0.0f};  // d height / d p, per cell unit
};

// p in cell units.
ReliefSample cellularRelief(const glm::vec3& p);

// Lattice hash shared with the shader: 32-bit integer mixing (Wellons'
// "lowbias32"), so CPU and GPU pick the same feature points.
uint32_t reliefHash(uint32_t x);

// How much of the relief to show when a cell covers `pixelsPerCell` pixels:
// 0 below 4 (the furrows would alias), 1 from 12 (oracle O26).
float reliefFade(float pixelsPerCell);

// The bumped unit normal for a relief of slope `strength` (height amplitude
// / cell size): n' = normalize(n - strength * (g - (g.n) n)).
glm::vec3 bumpedNormal(const glm::vec3& normal, const glm::vec3& gradient, float strength);

}  // namespace mq
