#pragma once
// Improved Perlin noise (Perlin 2002, "Improving Noise"): a smooth,
// band-limited pseudo-random scalar field over R^3 with values in about
// [-1, 1], zero at the integer lattice. The permutation comes from a seed, so
// the same seed gives the same field.

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

namespace mq {

class PerlinNoise {
 public:
  explicit PerlinNoise(uint32_t seed = 0);

  float noise(float x, float y, float z) const;
  float noise(const glm::vec3& p) const { return noise(p.x, p.y, p.z); }
  // Three decorrelated noise values (the field sampled at offset points).
  glm::vec3 noise3(const glm::vec3& p) const;
  // Sum of `octaves` noises, each at twice the frequency and half the amplitude.

 private:
  std::array<uint8_t, 512> perm_;
};

}  // namespace mq
