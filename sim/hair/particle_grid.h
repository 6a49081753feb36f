#pragma once
// Particles counting-sorted into a dense grid of cells at least as wide as
// the search radius, x fastest: a cell's particles are contiguous, and so
// are those of the three cells x-1, x, x+1 of a row, so a radius search
// reads 9 ranges (the rows through the cell's 3 x 3 neighbourhood in y and
// z) instead of 27 scattered buckets. Consecutive particles share a cell,
// so they share the ranges. The grid spans the particles' box with at most
// kMaxCellsPerAxis cells an axis (cells widen beyond that, never narrow).

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace mq {

class ParticleGrid {
 public:
  using Range = std::pair<uint32_t, uint32_t>;  // [begin, end) in cell order
  static constexpr int kMaxCellsPerAxis = 160;

  // Cells at least `radius` wide on every axis.
  void build(const std::vector<glm::vec3>& positions, float radius);

  // order()[e] is the particle at place e of the cell order.
  const std::vector<uint32_t>& order() const { return order_; }
  // The cell of the particle at place e (the same for all of a cell's).
  uint32_t cellAt(size_t e) const { return cellOfPlace_[e]; }
  // The particles of `cell` and of every cell around it, as at most 9
  // non-empty ranges; returns how many.
  int neighbourRanges(uint32_t cell, Range (&out)[9]) const;

 private:
  glm::ivec3 cellOf(const glm::vec3& p) const;

  glm::vec3 origin_{0.0f}, invCell_{1.0f};
  glm::ivec3 dims_{1};
  std::vector<uint32_t> order_, cellOfPlace_;
  std::vector<uint32_t> cellStart_;              // per cell (x fastest), plus the end: a prefix sum
  std::vector<uint32_t> cellOfParticle_, fill_;  // scratch of build()
};

}  // namespace mq
