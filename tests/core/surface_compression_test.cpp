// Per-vertex compression l/L and its direction, the input of Volino's
// wrinkle height (survey §1.3.2).
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/mesh/surface_compression.h"
#include "icosphere_util.h"

namespace mq {
namespace {

// A flat n x n grid of unit-spaced vertices in the xy plane.
test::FlatMesh makeGrid(int n) {
  test::FlatMesh m;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) m.positions.insert(m.positions.end(), {float(x), float(y), 0.0f});
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const uint32_t a = y * n + x, b = a + 1, c = a + n, d = c + 1;
      m.triangles.insert(m.triangles.end(), {a, b, d, a, d, c});
    }
  return m;
}

std::vector<float> transformed(const std::vector<float>& p, const glm::mat4& m) {
  std::vector<float> out(p.size());
  for (size_t v = 0; v < p.size() / 3; ++v) {
    const glm::vec3 q = glm::vec3(m * glm::vec4(p[3 * v], p[3 * v + 1], p[3 * v + 2], 1.0f));
    out[3 * v] = q.x, out[3 * v + 1] = q.y, out[3 * v + 2] = q.z;
  }
  return out;
}

TEST(SurfaceCompression, RigidMotionIsNotCompressed) {
  const test::FlatMesh sphere = test::makeIcosphere(0.1f, 3);
  const SurfaceCompression compression(sphere.positions, sphere.triangles);
  const glm::mat4 rigid =
      glm::rotate(glm::translate(glm::mat4(1.0f), {0.3f, -1.0f, 2.0f}), 1.1f, glm::normalize(glm::vec3(1, 2, 3)));
  std::vector<float> out;
  compression.evaluate(transformed(sphere.positions, rigid), out);
  ASSERT_EQ(out.size(), 4 * compression.vertexCount());
  for (size_t v = 0; v < compression.vertexCount(); ++v) {
    EXPECT_NEAR(out[4 * v + 3], 1.0f, 1e-4f);
    EXPECT_LT(glm::length(glm::vec3(out[4 * v], out[4 * v + 1], out[4 * v + 2])) * (1.0f - out[4 * v + 3]), 1e-4f);
  }
}

TEST(SurfaceCompression, SquashedSheetGivesRatioAndDirection) {
  const test::FlatMesh grid = makeGrid(8);
  const SurfaceCompression compression(grid.positions, grid.triangles);
  std::vector<float> out;
  // Stretched along x, squashed along y: compression 0.8 across y.
  compression.evaluate(transformed(grid.positions, glm::scale(glm::mat4(1.0f), {1.2f, 0.8f, 1.0f})), out);
  // Two corners have edges in only two directions: undetermined (1, no direction).
  size_t undetermined = 0;
  for (size_t v = 0; v < compression.vertexCount(); ++v) {
    if (out[4 * v + 3] == 1.0f && out[4 * v + 1] == 0.0f) {
      ++undetermined;
      continue;
    }
    EXPECT_NEAR(out[4 * v + 3], 0.8f, 1e-4f);
    EXPECT_NEAR(std::abs(out[4 * v + 1]), 1.0f, 1e-4f);
  }
  EXPECT_EQ(undetermined, 2u);
  // The phase runs along the compression (y), the same way everywhere: the
  // folds it draws are straight lines across it.
  std::vector<float> phase;
  compression.evaluate(transformed(grid.positions, glm::scale(glm::mat4(1.0f), {1.2f, 0.8f, 1.0f})), out, &phase);
  const size_t first = 1;  // vertex (1, 0): determined
  const float sign = phase[first + 8] > phase[first] ? 1.0f : -1.0f;
  for (size_t v = 0; v < compression.vertexCount(); ++v) {
    if (out[4 * v + 1] == 0.0f) continue;
    EXPECT_NEAR(phase[v] - phase[first], sign * (grid.positions[3 * v + 1] - grid.positions[3 * first + 1]), 1e-4f);
    EXPECT_NEAR(out[4 * v + 1], sign, 1e-4f);  // directions oriented along the phase
  }
  // Folded along a line: a sheet bent in a right angle keeps its lengths.
  std::vector<float> folded = grid.positions;
  for (size_t v = 0; v < folded.size() / 3; ++v)
    if (folded[3 * v] > 3.0f) folded[3 * v + 2] = folded[3 * v] - 3.0f, folded[3 * v] = 3.0f;
  compression.evaluate(folded, out);
  for (size_t v = 0; v < compression.vertexCount(); ++v) EXPECT_NEAR(out[4 * v + 3], 1.0f, 0.15f);
}

}  // namespace
}  // namespace mq
