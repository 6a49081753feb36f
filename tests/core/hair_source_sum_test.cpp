// The flow field's source-sum kernels (core/hair/source_sum.h): every kernel
// this machine runs against a double-precision sum, and each one the same
// bytes on every call.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/hair/source_sum.h"

namespace mq {
namespace {

struct Sources {
  std::vector<float> x, y, z, w, core2;
};

// 200 sources in a head-sized box (padded to 208 with zero weights), with
// strengths of both signs and cores as the flow field makes them.
Sources randomSources() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> place(-0.12f, 0.12f), strength(-1.0f, 1.0f), core(1e-6f, 4e-5f);
  Sources s;
  for (int j = 0; j < 208; ++j) {
    const bool used = j < 200;
    s.x.push_back(used ? place(rng) : 0.0f);
    s.y.push_back(used ? place(rng) : 0.0f);
    s.z.push_back(used ? place(rng) : 0.0f);
    s.w.push_back(used ? strength(rng) : 0.0f);
    s.core2.push_back(used ? core(rng) : 1.0f);
  }
  return s;
}

// The sum in doubles, and the sum of its terms' magnitudes (the scale its
// rounding errors are measured against: the terms cancel).
void referenceSum(const Sources& s, const glm::vec3& p, glm::dvec3& sum, double& scale) {
  sum = glm::dvec3(0.0);
  scale = 0.0;
  for (size_t j = 0; j < s.x.size(); ++j) {
    const glm::dvec3 d = glm::dvec3(p) - glm::dvec3(s.x[j], s.y[j], s.z[j]);
    const double r2 = glm::dot(d, d) + s.core2[j];
    const glm::dvec3 term = d * (double(s.w[j]) / (r2 * std::sqrt(r2)));
    sum += term;
    scale += glm::length(term);
  }
}

TEST(SourceSum, EveryKernelThisMachineRunsMatchesTheDoubleSum) {
  const Sources s = randomSources();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> around(-0.2f, 0.2f);
  int kernelsRun = 0;
  for (SourceSumKernel kernel :
       {SourceSumKernel::Portable, SourceSumKernel::Sse, SourceSumKernel::Avx2, SourceSumKernel::Avx512}) {
    if (!sourceSumKernelRuns(kernel)) continue;
    ++kernelsRun;
    double worst = 0.0;
    for (int q = 0; q < 200; ++q) {
      const glm::vec3 p(around(rng), around(rng), around(rng));
      glm::dvec3 expected;
      double scale = 0.0;
      referenceSum(s, p, expected, scale);
      const glm::vec3 got =
          sumSources(kernel, s.x.data(), s.y.data(), s.z.data(), s.w.data(), s.core2.data(), s.x.size(), p);
      worst = std::max(worst, glm::length(glm::dvec3(got) - expected) / scale);
      // Deterministic: the same input, the same bytes.
      const glm::vec3 again =
          sumSources(kernel, s.x.data(), s.y.data(), s.z.data(), s.w.data(), s.core2.data(), s.x.size(), p);
      ASSERT_EQ(got.x, again.x);
      ASSERT_EQ(got.y, again.y);
      ASSERT_EQ(got.z, again.z);
    }
    // rsqrt14 (AVX-512) is good to 2^-14 relative per term; the others to float rounding.
    EXPECT_LT(worst, kernel == SourceSumKernel::Avx512 ? 3e-4 : 2e-5) << "kernel " << int(kernel);
  }
  EXPECT_GE(kernelsRun, 1);
  EXPECT_TRUE(sourceSumKernelRuns(fastestSourceSumKernel()));
}

}  // namespace
}  // namespace mq
