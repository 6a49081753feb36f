// The implicit solver's building blocks: the CG update loop's AVX2 path must
// give the scalar path's results bit for bit (and both glm's arithmetic), the
// springs' fused step preparation must equal addForces() + prepareImplicit(),
// and a phased parallel job must run its phases in order whichever thread
// runs which block.
#include <gtest/gtest.h>

// GCC 12 reports a free of a non-heap pointer in the inlined destructor of a
// std::vector<glm::vec3> in this file (a known false positive of its -O2 flow analysis).
#pragma GCC diagnostic ignored "-Wfree-nonheap-object"

#include <cstring>
#include <random>

#include "sim/cloth/forces/spring_force.h"
#include "sim/cloth/integrators/cg_update.h"
#include "sim/cloth/parallel.h"
#include "tests/sim/cloth_test_scenes.h"

namespace mq::cloth {
namespace {

struct UpdateData {
  std::vector<glm::vec3> c, q, dv, r;
  std::vector<glm::mat3> blocks;
  LaneBlocks preconditioner;
  SplitVec3 z;

  explicit UpdateData(size_t n) {
    std::mt19937 rng(12111);
    std::uniform_real_distribution<float> value(-2.0f, 2.0f);
    auto vec = [&] { return glm::vec3(value(rng), value(rng), value(rng)); };
    for (size_t i = 0; i < n; ++i) {
      c.push_back(vec()), q.push_back(vec()), dv.push_back(vec()), r.push_back(vec());
      blocks.push_back(glm::mat3(vec(), vec(), vec()));
    }
    preconditioner.resize(n);
    for (size_t i = 0; i < n; ++i) preconditioner.set(i, blocks[i]);
    z.resize(n);
  }
  CgUpdate update(float alpha) { return {alpha, c.data(), q.data(), dv.data(), r.data(), &preconditioner, &z}; }
};

template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(ClothCgUpdate, VectorisedPathEqualsTheScalarOneBitForBit) {
  constexpr size_t n = 8 * 13 + 5;  // a tail the vector path leaves to the scalar one
  for (size_t begin : {size_t(0), size_t(16)}) {
    UpdateData scalar(n), vectorised(n);
    const double scalarDot = cgUpdateRange(scalar.update(0.37f), begin, n, false);
    const double vectorDot = cgUpdateRange(vectorised.update(0.37f), begin, n, true);
    EXPECT_EQ(scalarDot, vectorDot) << begin;
    EXPECT_TRUE(sameBits(scalar.dv, vectorised.dv)) << begin;
    EXPECT_TRUE(sameBits(scalar.r, vectorised.r)) << begin;
    EXPECT_TRUE(sameBits(scalar.z.x, vectorised.z.x) && sameBits(scalar.z.y, vectorised.z.y) &&
                sameBits(scalar.z.z, vectorised.z.z))
        << begin;
  }
}

TEST(ClothCgUpdate, ScalarPathIsGlmArithmetic) {
  constexpr size_t n = 21;
  UpdateData data(n);
  const std::vector<glm::vec3> dv0 = data.dv, r0 = data.r;
  const double dot = cgUpdateRange(data.update(-1.5f), 0, n, false);
  double expectedDot = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3 r = r0[i] - -1.5f * data.q[i], z = data.blocks[i] * r;
    EXPECT_EQ(data.dv[i], dv0[i] + -1.5f * data.c[i]);
    EXPECT_EQ(data.r[i], r);
    EXPECT_EQ(data.z.at(i), z);
    expectedDot += double(glm::dot(r, z));
  }
  EXPECT_EQ(dot, expectedDot);
}

// A jittered 12 x 12 grid with edge, diagonal and skip-one springs (stretched
// and compressed), moving at random velocities.
struct SpringGrid {
  static constexpr int kColumns = 12;
  ClothState state;
  std::vector<Spring> springs;
  SpringGrid() {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> jitter(-0.004f, 0.004f), speed(-0.5f, 0.5f);
    for (int r = 0; r < kColumns; ++r)
      for (int c = 0; c < kColumns; ++c) {
        state.x.push_back({0.02f * c + jitter(rng), jitter(rng), 0.02f * r + jitter(rng)});
        state.v.push_back({speed(rng), speed(rng), speed(rng)});
      }
    springs = test::gridSprings(state.x, kColumns, rng);
  }
};

TEST(ClothCgUpdate, FusedSpringPreparationEqualsForcesThenLinearisation) {
  const SpringGrid grid;
  const size_t n = grid.state.x.size();
  const float h = 1.0f / 30.0f;
  SpringForce separate(grid.springs, n), fused(grid.springs, n);
  std::vector<glm::vec3> f(n, glm::vec3(0.0f)), hKv(n, glm::vec3(0.0f));
  std::vector<glm::mat3> diagonal(n, glm::mat3(0.0f));
  separate.addForces(grid.state, f);
  separate.prepareImplicit(grid.state, h, hKv, diagonal);
  std::vector<glm::vec3> fusedF(n, glm::vec3(0.0f)), fusedHKv(n, glm::vec3(0.0f));
  std::vector<glm::mat3> fusedDiagonal(n, glm::mat3(0.0f));
  fused.prepareStepSprings(grid.state, h, 0, grid.springs.size() / 2);
  fused.prepareStepSprings(grid.state, h, grid.springs.size() / 2, grid.springs.size());
  for (size_t v = 0; v < n; ++v) fused.prepareStepVertex(v, fusedF[v], fusedHKv[v], fusedDiagonal[v]);
  EXPECT_TRUE(sameBits(f, fusedF));
  EXPECT_TRUE(sameBits(hKv, fusedHKv));
  EXPECT_TRUE(sameBits(diagonal, fusedDiagonal));
  // The same matrix rows: the same products.
  std::vector<glm::vec3> p(grid.state.v), y(n, glm::vec3(0.0f)), fusedY(n, glm::vec3(0.0f));
  separate.addProduct(p, y);
  fused.addProduct(p, fusedY);
  EXPECT_TRUE(sameBits(y, fusedY));
}

// Each phase reads what every block of the previous one wrote: a phase
// started early would see zeros.
TEST(ClothCgUpdate, PhasedJobRunsPhasesInOrder) {
  constexpr size_t kBlocks = 64, kPerBlock = 100;
  for (bool parallel : {false, true}) {
    for (int repeat = 0; repeat < 50; ++repeat) {
      std::vector<double> values(kBlocks * kPerBlock, 0.0), sums(kBlocks, 0.0), checks(kBlocks, 0.0);
      PhasedJob job;
      const int fill = job.add(kBlocks, -1, [&](size_t b) {
        for (size_t i = b * kPerBlock; i < (b + 1) * kPerBlock; ++i) values[i] = double(i + 1);
      });
      const int sum = job.add(kBlocks, fill, [&](size_t b) {
        double total = 0.0;
        for (double v : values) total += v;
        sums[b] = total;
      });
      job.add(kBlocks, sum, [&](size_t b) { checks[b] = sums[(b + 1) % kBlocks]; });
      job.run(parallel);
      const double expected = 0.5 * double(values.size()) * double(values.size() + 1);
      for (size_t b = 0; b < kBlocks; ++b) ASSERT_EQ(checks[b], expected) << parallel << " " << repeat;
    }
  }
}

}  // namespace
}  // namespace mq::cloth
