#include "core/math/perlin_noise.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace mq {

namespace {

inline float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }
inline float lerp(float t, float a, float b) { return a + t * (b - a); }

// Dot product of the offset with one of 12 edge-midpoint gradients (16
// entries, four repeated, as in Perlin's reference): a table lookup, since
// branches on a random hash mispredict.
constexpr float kGradients[16][3] = {{1, 1, 0},  {-1, 1, 0},  {1, -1, 0}, {-1, -1, 0}, {1, 0, 1},  {-1, 0, 1},
                                     {1, 0, -1}, {-1, 0, -1}, {0, 1, 1},  {0, -1, 1},  {0, 1, -1}, {0, -1, -1},
                                     {1, 1, 0},  {0, -1, 1},  {-1, 1, 0}, {0, -1, -1}};
inline float grad(int hash, float x, float y, float z) {
  const float* g = kGradients[hash & 15];
  return g[0] * x + g[1] * y + g[2] * z;
}

}  // namespace

PerlinNoise::PerlinNoise(uint32_t seed) {
  std::array<uint8_t, 256> p;
  std::iota(p.begin(), p.end(), 0);
  std::mt19937 rng(seed);
  for (int i = 255; i > 0; --i) std::swap(p[i], p[rng() % (i + 1)]);
  for (int i = 0; i < 512; ++i) perm_[i] = p[i & 255];
}

float PerlinNoise::noise(float x, float y, float z) const {
  const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const int X = static_cast<int>(fx) & 255, Y = static_cast<int>(fy) & 255, Z = static_cast<int>(fz) & 255;
  x -= fx;
  y -= fy;
  z -= fz;
  const float u = fade(x), v = fade(y), w = fade(z);
  const int A = perm_[X] + Y, AA = perm_[A] + Z, AB = perm_[A + 1] + Z;
  const int B = perm_[X + 1] + Y, BA = perm_[B] + Z, BB = perm_[B + 1] + Z;
  return lerp(w,
              lerp(v, lerp(u, grad(perm_[AA], x, y, z), grad(perm_[BA], x - 1, y, z)),
                   lerp(u, grad(perm_[AB], x, y - 1, z), grad(perm_[BB], x - 1, y - 1, z))),
              lerp(v, lerp(u, grad(perm_[AA + 1], x, y, z - 1), grad(perm_[BA + 1], x - 1, y, z - 1)),
                   lerp(u, grad(perm_[AB + 1], x, y - 1, z - 1), grad(perm_[BB + 1], x - 1, y - 1, z - 1))));
}

glm::vec3 PerlinNoise::noise3(const glm::vec3& p) const {
  return {noise(p), noise(p + glm::vec3(31.416f, 47.853f, 12.679f)), noise(p + glm::vec3(-23.112f, 19.871f, -55.309f))};
}

}  // namespace mq
