// The two-level preconditioner's coarse level: A_c must be the Galerkin
// matrix P^T S A S P exactly (springs inside and across patches, pins,
// resting contacts), so solving A_c y = P^T r for r = S A S P e gives back e.
#include <gtest/gtest.h>

#include <random>

#include "sim/cloth/integrators/coarse_correction.h"
#include "tests/sim/cloth_test_scenes.h"

namespace mq::cloth {
namespace {

constexpr int kColumns = 20;  // 400 vertices: about 6 patches of 64

uint32_t at(int row, int column) { return uint32_t(row * kColumns + column); }

// A grid with edge, diagonal and skip-one springs, some stretched, some compressed.
std::vector<Spring> gridSprings(const ClothState& s) {
  std::mt19937 rng(3);
  return test::gridSprings(s.x, kColumns, rng);
}

ClothState jitteredGrid() {
  ClothState s;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> jitter(-0.003f, 0.003f);
  for (int r = 0; r < kColumns; ++r)
    for (int c = 0; c < kColumns; ++c) s.x.push_back({0.02f * c + jitter(rng), jitter(rng), 0.02f * r + jitter(rng)});
  const size_t n = s.x.size();
  s.v.assign(n, glm::vec3(0.0f));
  s.mass.assign(n, 2e-4f);
  s.invMass.assign(n, 1.0f / 2e-4f);
  s.contactNormal.assign(n, glm::vec3(0.0f));
  s.contactSpeed.assign(n, 0.0f);
  return s;
}

glm::vec3 filtered(const ClothState& s, size_t i, const glm::vec3& a) {
  if (s.invMass[i] == 0.0f) return glm::vec3(0.0f);
  const glm::vec3& n = s.contactNormal[i];
  return a - glm::dot(a, n) * n;
}

TEST(CoarseCorrection, SolvesTheGalerkinSystemOfTheFilteredMatrix) {
  ClothState s = jitteredGrid();
  const size_t n = s.size();
  // Pins along one edge, resting contacts (mixed normals) in a band across
  // patches: every patch keeps free directions.
  for (int c = 0; c < kColumns; c += 3) s.invMass[at(0, c)] = 0.0f;
  for (int c = 0; c < kColumns; ++c) s.contactNormal[at(9, c)] = glm::normalize(glm::vec3(0.2f * (c % 3), 1.0f, 0.1f));
  SpringForce springs(gridSprings(s), n);
  const float h = 1.0f / 60.0f;
  std::vector<glm::vec3> hKv(n, glm::vec3(0.0f));
  std::vector<glm::mat3> springDiagonal(n, glm::mat3(0.0f)), otherDiagonal(n);
  springs.prepareImplicit(s, h, hKv, springDiagonal);
  for (size_t i = 0; i < n; ++i) otherDiagonal[i] = glm::mat3(s.mass[i]);

  CoarseCorrection coarse;
  coarse.build(springs, n);
  ASSERT_GE(coarse.patchCount(), 4u);
  coarse.assemble(s, otherDiagonal, springs);

  // e: one translation per patch; w = S P e; r = S A w, A = M + the springs' product.
  std::mt19937 rng(11);
  std::normal_distribution<float> g;
  std::vector<glm::vec3> e(coarse.patchCount());
  for (glm::vec3& t : e) t = glm::vec3(g(rng), g(rng), g(rng));
  std::vector<glm::vec3> w(n), r(n, glm::vec3(0.0f));
  for (size_t i = 0; i < n; ++i) w[i] = filtered(s, i, e[coarse.patchOf()[i]]);
  springs.addProduct(w, r);
  for (size_t i = 0; i < n; ++i) r[i] = filtered(s, i, r[i] + s.mass[i] * w[i]);

  std::vector<glm::vec3> solved;
  const double rDotCorrection = coarse.solve(r, solved);
  ASSERT_EQ(solved.size(), e.size());
  float worst = 0.0f, largest = 0.0f;
  for (size_t p = 0; p < e.size(); ++p) {
    worst = std::max(worst, glm::length(solved[p] - e[p]));
    largest = std::max(largest, glm::length(e[p]));
  }
  EXPECT_LT(worst, 1e-3f * largest) << "patches " << e.size();
  // The returned r . S P y is w . A w > 0 (A positive definite).
  EXPECT_GT(rDotCorrection, 0.0);
}

// The solver assembles A_c in parts by patch range, in parallel: any
// partition, in any order, must give the whole assembly's solution bit for bit.
TEST(CoarseCorrection, AssemblyInPartsMatchesTheWholeBitForBit) {
  ClothState s = jitteredGrid();
  const size_t n = s.size();
  for (int c = 0; c < kColumns; c += 4) s.invMass[at(0, c)] = 0.0f;
  for (int c = 0; c < kColumns; ++c) s.contactNormal[at(11, c)] = glm::normalize(glm::vec3(0.3f, 1.0f, 0.1f * (c % 2)));
  SpringForce springs(gridSprings(s), n);
  std::vector<glm::vec3> hKv(n, glm::vec3(0.0f));
  std::vector<glm::mat3> springDiagonal(n, glm::mat3(0.0f)), otherDiagonal(n);
  springs.prepareImplicit(s, 1.0f / 60.0f, hKv, springDiagonal);
  for (size_t i = 0; i < n; ++i) otherDiagonal[i] = glm::mat3(s.mass[i] * (1.0f + 0.01f * float(i % 7)));

  CoarseCorrection whole, parts;
  whole.build(springs, n);
  parts.build(springs, n);
  whole.assemble(s, otherDiagonal, springs);
  parts.prepareAssembly(s);
  const size_t patches = parts.patchCount(), split = patches / 3;
  parts.assemblePatches(s, otherDiagonal, springs, split, patches);  // the later rows first
  parts.assemblePatches(s, otherDiagonal, springs, 0, split);
  parts.factorise();

  std::mt19937 rng(5);
  std::normal_distribution<float> g;
  std::vector<glm::vec3> r(n);
  for (glm::vec3& v : r) v = glm::vec3(g(rng), g(rng), g(rng));
  std::vector<glm::vec3> fromWhole, fromParts;
  EXPECT_EQ(whole.solve(r, fromWhole), parts.solve(r, fromParts));
  ASSERT_EQ(fromWhole.size(), fromParts.size());
  for (size_t p = 0; p < fromWhole.size(); ++p)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(fromWhole[p][c], fromParts[p][c]) << "patch " << p << " component " << c;
}

}  // namespace
}  // namespace mq::cloth
