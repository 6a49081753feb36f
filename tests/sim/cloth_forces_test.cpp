// Analytic gradients and Jacobians of the cloth forces against central
// finite differences of the energy and of the forces.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/cloth/forces/cantilever_bending.h"
#include "sim/cloth/forces/spring_force.h"
#include "sim/cloth/parallel.h"
#include "tests/sim/cloth_test_scenes.h"

namespace mq::cloth {
namespace {

ClothState randomState(size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.3f, 0.3f);
  ClothState s;
  for (size_t i = 0; i < n; ++i) {
    s.x.push_back(glm::vec3(float(i) * 0.1f, 0.0f, 0.0f) + glm::vec3(u(rng), u(rng), u(rng)) * 0.2f);
    s.v.push_back(glm::vec3(0.0f));
    s.mass.push_back(1.0f);
    s.invMass.push_back(1.0f);
  }
  return s;
}

std::vector<glm::vec3> forcesOf(const ForceTerm& term, const ClothState& s) {
  std::vector<glm::vec3> f(s.size(), glm::vec3(0.0f));
  term.addForces(s, f);
  return f;
}

// f = -dE/dx, checked component by component with central differences (double energy).
void expectForceIsMinusGradient(const ForceTerm& term, ClothState s, double tolerance) {
  const std::vector<glm::vec3> f = forcesOf(term, s);
  const float h = 1e-3f;
  for (size_t i = 0; i < s.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const float keep = s.x[i][c];
      s.x[i][c] = keep + h;
      const double ep = term.potentialEnergy(s);
      s.x[i][c] = keep - h;
      const double em = term.potentialEnergy(s);
      s.x[i][c] = keep;
      const double numeric = -(ep - em) / (2.0 * h);
      EXPECT_NEAR(f[i][c], numeric, tolerance * (1.0 + std::abs(numeric))) << "vertex " << i << " axis " << c;
    }
}

TEST(ClothForces, SpringForceIsMinusEnergyGradient) {
  const ClothState s = randomState(4, 7);
  const SpringForce springs({{0, 1, 0.08f, 120.0f, 0.0f}, {1, 2, 0.12f, 80.0f, 0.0f}, {0, 3, 0.25f, 50.0f, 0.0f}}, 4);
  expectForceIsMinusGradient(springs, s, 2e-3);
}

TEST(ClothForces, SpringJacobianMatchesFiniteDifferences) {
  ClothState s = randomState(2, 11);
  const SpringForce springs({{0, 1, 0.05f, 300.0f, 0.0f}}, 2);
  for (bool stretched : {true, false}) {
    // Rest shorter than the current length (stretched) and longer (compressed).
    const float l = glm::length(s.x[0] - s.x[1]);
    const SpringForce spring({{0, 1, stretched ? 0.7f * l : 1.3f * l, 300.0f, 0.0f}}, 2);
    const glm::mat3 K = spring.stiffnessBlock(0, s.x, false);
    const float h = 1e-3f;
    for (int c = 0; c < 3; ++c) {
      const float keep = s.x[0][c];
      s.x[0][c] = keep + h;
      const glm::vec3 fp = forcesOf(spring, s)[0];
      s.x[0][c] = keep - h;
      const glm::vec3 fm = forcesOf(spring, s)[0];
      s.x[0][c] = keep;
      const glm::vec3 column = (fp - fm) / (2.0f * h);
      for (int r = 0; r < 3; ++r) EXPECT_NEAR(K[c][r], column[r], 1e-2f * (1.0f + std::abs(column[r])));
    }
    // The filtered block the solver uses is negative semi-definite.
    const glm::mat3 F = spring.stiffnessBlock(0, s.x, true);
    std::mt19937 rng(3);
    std::normal_distribution<float> g;
    for (int k = 0; k < 20; ++k) {
      const glm::vec3 p(g(rng), g(rng), g(rng));
      EXPECT_LE(glm::dot(p, F * p), 1e-3f);
    }
  }
}

TEST(ClothForces, SpringDampingOpposesRelativeVelocity) {
  ClothState s = randomState(2, 5);
  const float l = glm::length(s.x[0] - s.x[1]);
  const SpringForce spring({{0, 1, l, 0.0f, 2.0f}}, 2);
  s.v[0] = glm::normalize(s.x[0] - s.x[1]);  // separating
  const auto f = forcesOf(spring, s);
  EXPECT_LT(glm::dot(f[0], s.v[0]), 0.0f);
  EXPECT_NEAR(glm::length(f[0] + f[1]), 0.0f, 1e-6f);  // momentum conserved
}

TEST(ClothForces, SpringImplicitProductMatchesTheAssembledMatrix) {
  // The solver's product y = -(h df/dv + h^2 df/dx) p (compact blocks, the
  // vectorised bulk form and the per-vertex form) against the sum of
  // h^2 (-K) + h kd d d^T over the springs, with K from stiffnessBlock():
  // an irregular spring set on 37 vertices (not whole 8-vertex blocks), some
  // springs stretched and some compressed, so both paths and the padding run.
  const size_t n = 37;
  ClothState s = randomState(n, 21);
  std::mt19937 rng(5);
  std::uniform_int_distribution<uint32_t> pick(0, n - 1);
  std::uniform_real_distribution<float> scale(0.6f, 1.4f);
  std::vector<Spring> list;
  while (list.size() < 150) {
    const uint32_t a = pick(rng), b = pick(rng);
    if (a == b) continue;
    list.push_back({a, b, scale(rng) * glm::length(s.x[a] - s.x[b]), 50.0f + 10.0f * float(list.size() % 7), 0.3f});
  }
  for (uint32_t v = 0; v < 3; ++v) list.push_back({v, v + 1, 0.0f, 400.0f, 1.0f});  // seam-like: zero rest length
  SpringForce springs(list, n);
  const float h = 0.02f;
  std::vector<glm::vec3> hKv(n, glm::vec3(0.0f));
  std::vector<glm::mat3> diagonal(n, glm::mat3(0.0f));
  springs.prepareImplicit(s, h, hKv, diagonal);
  std::vector<glm::vec3> p(n);
  std::normal_distribution<float> g;
  for (glm::vec3& q : p) q = glm::vec3(g(rng), g(rng), g(rng));
  std::vector<glm::vec3> expected(n, glm::vec3(0.0f));
  std::vector<glm::mat3> expectedDiagonal(n, glm::mat3(0.0f));
  for (size_t k = 0; k < list.size(); ++k) {
    const Spring& sp = list[k];
    const glm::vec3 delta = s.x[sp.a] - s.x[sp.b];
    const glm::vec3 d = glm::length(delta) > 1e-12f ? glm::normalize(delta) : glm::vec3(0.0f);
    const glm::mat3 block = -(h * h) * springs.stiffnessBlock(k, s.x, true) + (h * sp.kd) * glm::outerProduct(d, d);
    // The compact form the coarse level reads: e e^T + beta I.
    const SpringForce::ImplicitBlock& compact = springs.implicitBlock(k);
    const glm::mat3 fromCompact = glm::outerProduct(compact.e, compact.e) + glm::mat3(compact.beta);
    for (int c = 0; c < 3; ++c)
      EXPECT_LT(glm::length(fromCompact[c] - block[c]), 1e-4f * (1.0f + glm::length(block[c]))) << "spring " << k;
    expected[sp.a] += block * (p[sp.a] - p[sp.b]);
    expected[sp.b] += block * (p[sp.b] - p[sp.a]);
    expectedDiagonal[sp.a] += block;
    expectedDiagonal[sp.b] += block;
  }
  springs.productPass(p);
  std::vector<glm::vec3> bulk(n, glm::vec3(0.0f));
  springs.addProductRange(0, n, bulk.data());
  std::vector<glm::vec3> split(n, glm::vec3(0.0f));  // ranges that start and end inside blocks
  springs.addProductRange(0, 5, split.data());
  springs.addProductRange(5, 29, split.data());
  springs.addProductRange(29, n, split.data());
  for (size_t v = 0; v < n; ++v) {
    const float tolerance = 1e-4f * (1.0f + glm::length(expected[v]));
    EXPECT_LT(glm::length(springs.productAt(v) - expected[v]), tolerance) << v;
    EXPECT_LT(glm::length(bulk[v] - expected[v]), tolerance) << v;
    EXPECT_LT(glm::length(split[v] - expected[v]), tolerance) << v;
    for (int c = 0; c < 3; ++c)
      EXPECT_LT(glm::length(diagonal[v][c] - expectedDiagonal[v][c]),
                1e-4f * (1.0f + glm::length(expectedDiagonal[v][c])));
  }
}

// The solver's spring product (eight vertices per AVX2 step, lanes in the
// order of decreasing degree within each of its ranges) against a scalar
// reference doing the same fused multiply-adds vertex by vertex, in
// incidence order: bit for bit, over the solver's ranges (ReduceBlocks);
// the last partial block takes the scalar path, pinned to productAt().
TEST(ClothForces, SpringProductMatchesItsFusedMultiplyAddReferenceBitForBit) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) GTEST_SKIP() << "no AVX2 + FMA";
#else
  GTEST_SKIP() << "no AVX2 path";
#endif
  constexpr int kColumns = 37;  // 1,369 vertices: ranges of 3 blocks, and a last partial block
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> jitter(-0.004f, 0.004f);
  ClothState s;
  for (int r = 0; r < kColumns; ++r)
    for (int c = 0; c < kColumns; ++c) s.x.push_back({0.02f * c + jitter(rng), jitter(rng), 0.02f * r + jitter(rng)});
  const size_t n = s.x.size();
  std::normal_distribution<float> g;
  for (size_t i = 0; i < n; ++i) s.v.push_back(0.1f * glm::vec3(g(rng), g(rng), g(rng)));
  std::vector<Spring> list = test::gridSprings(s.x, kColumns, rng);
  // Drop some springs so the degrees vary inside the grid too.
  std::vector<Spring> kept;
  for (size_t k = 0; k < list.size(); ++k)
    if (k % 5 != 2 || k % 3 == 0) kept.push_back(list[k]);
  SpringForce springs(kept, n);
  std::vector<glm::vec3> hKv(n, glm::vec3(0.0f));
  std::vector<glm::mat3> diagonal(n, glm::mat3(0.0f));
  springs.prepareImplicit(s, 1.0f / 30.0f, hKv, diagonal);
  std::vector<glm::vec3> p(n), start(n);
  for (size_t i = 0; i < n; ++i) p[i] = glm::vec3(g(rng), g(rng), g(rng)), start[i] = glm::vec3(g(rng), g(rng), g(rng));

  springs.productPass(p);
  std::vector<glm::vec3> y = start;
  const ReduceBlocks ranges(n);
  for (size_t r = 0; r < ReduceBlocks::kCount; ++r)
    if (ranges.begin(r) < ranges.end(r)) springs.addProductRange(ranges.begin(r), ranges.end(r), y.data());

  std::vector<glm::vec3> sum(n, glm::vec3(0.0f));
  for (size_t k = 0; k < kept.size(); ++k) {  // each vertex's springs in index order, as its incidences
    const SpringForce::ImplicitBlock& b = springs.implicitBlock(k);
    for (const auto& [v, other] : {std::pair(kept[k].a, kept[k].b), std::pair(kept[k].b, kept[k].a)}) {
      const glm::vec3 q = p[v] - p[other];
      const float t = std::fma(b.e.x, q.x, std::fma(b.e.y, q.y, b.e.z * q.z));
      for (int c = 0; c < 3; ++c) sum[v][c] = std::fma(t, b.e[c], std::fma(b.beta, q[c], sum[v][c]));
    }
  }
  const size_t vectorised = n / 8 * 8;
  for (size_t v = 0; v < n; ++v) {
    const glm::vec3 expected = start[v] + (v < vectorised ? sum[v] : springs.productAt(v));
    for (int c = 0; c < 3; ++c) ASSERT_EQ(y[v][c], expected[c]) << "vertex " << v << " component " << c;
  }
}

TEST(ClothForces, CantileverForceIsMinusEnergyGradient) {
  const ClothState s = randomState(5, 21);
  const CantileverBending bending({{0, 1, 2, 0.02f, 0.0f}, {1, 2, 3, 0.03f, 0.0f}, {2, 3, 4, 0.01f, 0.0f}}, 5);
  expectForceIsMinusGradient(bending, s, 2e-3);
}

TEST(ClothForces, CantileverJacobianMatchesFiniteDifferencesWhenStraight) {
  // Straight line: the Gauss-Newton Jacobian equals the exact one.
  ClothState s = randomState(3, 1);
  s.x = {{0, 0, 0}, {0.1f, 0.01f, 0}, {0.2f, 0.02f, 0}};
  const CantileverBending bending({{0, 1, 2, 0.05f, 0.0f}}, 3);
  const float h = 1e-3f;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const glm::mat3 J = bending.jacobianBlock(0, a, b, s.x);
      for (int c = 0; c < 3; ++c) {
        const float keep = s.x[b][c];
        s.x[b][c] = keep + h;
        const glm::vec3 fp = forcesOf(bending, s)[a];
        s.x[b][c] = keep - h;
        const glm::vec3 fm = forcesOf(bending, s)[a];
        s.x[b][c] = keep;
        const glm::vec3 column = (fp - fm) / (2.0f * h);
        for (int r = 0; r < 3; ++r)
          EXPECT_NEAR(J[c][r], column[r], 2e-2f * (1.0f + std::abs(column[r]))) << a << b << c << r;
      }
    }
}

TEST(ClothForces, CantileverResistsBendingOnly) {
  ClothState s = randomState(3, 1);
  s.x = {{0, 0, 0}, {0.1f, 0, 0}, {0.2f, 0, 0}};
  const CantileverBending bending({{0, 1, 2, 0.05f, 0.0f}}, 3);
  EXPECT_NEAR(bending.potentialEnergy(s), 0.0, 1e-9);
  s.x[2] = {0.2f, 0.02f, 0};  // bend up: the tip is pushed back down
  const auto f = forcesOf(bending, s);
  EXPECT_LT(f[2].y, 0.0f);
  EXPECT_NEAR(glm::length(f[0] + f[1] + f[2]), 0.0f, 1e-5f);
}

}  // namespace
}  // namespace mq::cloth
