#pragma once
// The implicit solver's CG update loop over a range of vertices,
//
//   dv += alpha c,  r -= alpha q,  z = P r,  returns the sum of r . z,
//
// with P the block-Jacobi preconditioner. The vectors are glm::vec3 arrays
// (the force terms read and write them), z is kept split in x, y and z arrays
// and P eight vertices side by side, so an AVX2 path (chosen at run time)
// handles eight vertices per step. The AVX2 path does the scalar path's
// operations in the same order (no fused multiply-add, the dot summed in
// double vertex by vertex): both give bit-identical results.

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace mq::cloth {

// 3x3 blocks stored eight vertices side by side: entry m[col][row] of vertex
// 8 g + l at [72 g + 8 (3 col + row) + l].
class LaneBlocks {
 public:
  static constexpr size_t kLanes = 8;
  void resize(size_t vertices) { entries_.resize((vertices + kLanes - 1) / kLanes * 9 * kLanes); }
  void set(size_t v, const glm::mat3& m) {
    float* e = &entries_[v / kLanes * 9 * kLanes + v % kLanes];
    for (int col = 0; col < 3; ++col)
      for (int row = 0; row < 3; ++row) e[(3 * col + row) * kLanes] = m[col][row];
  }
  // m v, as glm computes it.
  glm::vec3 times(size_t v, const glm::vec3& x) const {
    const float* e = &entries_[v / kLanes * 9 * kLanes + v % kLanes];
    auto at = [&](int col, int row) { return e[(3 * col + row) * kLanes]; };
    return glm::vec3(at(0, 0) * x.x + at(1, 0) * x.y + at(2, 0) * x.z, at(0, 1) * x.x + at(1, 1) * x.y + at(2, 1) * x.z,
                     at(0, 2) * x.x + at(1, 2) * x.y + at(2, 2) * x.z);
  }
  const float* group(size_t g) const { return &entries_[g * 9 * kLanes]; }

 private:
  std::vector<float> entries_;
};

// A vec3 array split into x, y and z arrays.
struct SplitVec3 {
  std::vector<float> x, y, z;
  void resize(size_t n) { x.resize(n), y.resize(n), z.resize(n); }
  glm::vec3 at(size_t i) const { return glm::vec3(x[i], y[i], z[i]); }
};

struct CgUpdate {
  float alpha;
  const glm::vec3 *c, *q;
  glm::vec3 *dv, *r;
  const LaneBlocks* preconditioner;
  SplitVec3* z;
};

// The update over [begin, end) (begin a multiple of 8); the AVX2 path when
// `vectorised` and the CPU has it.
double cgUpdateRange(const CgUpdate& u, size_t begin, size_t end, bool vectorised = true);

}  // namespace mq::cloth
