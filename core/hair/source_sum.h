#pragma once
// The hot loop of the hair flow field's panel method (flow_field.h): the
// velocity that n point sources with softened cores induce at a point,
//   v(x) = sum_j w_j (x - p_j) / (|x - p_j|^2 + c_j)^(3/2),
// one kernel per instruction set, the fastest this machine runs chosen at
// run time. The SIMD kernels take 1/r^3 from the processor's reciprocal
// square root (refined by a Newton step, except AVX-512's 14-bit one) and sum
// in lanes of their width, so grooms agree between instruction sets to about
// 1e-4 relative, not to the bit; on one instruction set they are the same
// bytes every run.

#include <cstddef>

#include <glm/glm.hpp>

namespace mq {

enum class SourceSumKernel {
  Portable,  // one source at a time, sqrt and divide
  Sse,       // four at a time (x86-64's baseline)
  Avx2,      // eight at a time, with FMA
  Avx512,    // sixteen at a time
};

bool sourceSumKernelRuns(SourceSumKernel kernel);  // on this machine
SourceSumKernel fastestSourceSumKernel();

// The arrays hold n sources, n a multiple of 16 (pad with zero weights and
// a core of 1).
glm::vec3 sumSources(SourceSumKernel kernel, const float* px, const float* py, const float* pz, const float* w,
                     const float* core2, size_t n, const glm::vec3& x);

}  // namespace mq
