#include "sim/hair/particle_grid.h"

#include <algorithm>
#include <cmath>

namespace mq {

glm::ivec3 ParticleGrid::cellOf(const glm::vec3& p) const {
  glm::ivec3 c;
  for (int k = 0; k < 3; ++k) {
    const float x = (p[k] - origin_[k]) * invCell_[k];
    // Not finite (a broken simulation): the first cell, not an overflow.
    c[k] = std::isfinite(x) ? std::clamp(int(x), 0, dims_[k] - 1) : 0;
  }
  return c;
}

void ParticleGrid::build(const std::vector<glm::vec3>& positions, float radius) {
  const size_t count = positions.size();
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& p : positions)
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  if (!(lo.x <= hi.x)) lo = hi = glm::vec3(0.0f);
  origin_ = lo;
  radius = std::max(radius, 1e-6f);
  for (int k = 0; k < 3; ++k) {
    const float extent = hi[k] - lo[k];
    dims_[k] = int(std::clamp(std::floor(extent / radius), 0.0f, float(kMaxCellsPerAxis - 1))) + 1;
    // Cells of at least the radius: the 3 x 3 x 3 block holds every neighbour.
    invCell_[k] = 1.0f / std::max(radius, extent / float(dims_[k]) * 1.0001f);
  }
  const size_t cells = size_t(dims_.x) * dims_.y * dims_.z;
  cellOfParticle_.resize(count);
  cellStart_.assign(cells + 1, 0);
  for (size_t i = 0; i < count; ++i) {
    const glm::ivec3 c = cellOf(positions[i]);
    cellOfParticle_[i] = uint32_t((size_t(c.z) * dims_.y + c.y) * dims_.x + c.x);
    ++cellStart_[cellOfParticle_[i] + 1];
  }
  for (size_t c = 0; c < cells; ++c) cellStart_[c + 1] += cellStart_[c];
  order_.resize(count);
  cellOfPlace_.resize(count);
  fill_.assign(cellStart_.begin(), cellStart_.end() - 1);
  for (size_t i = 0; i < count; ++i) {
    const uint32_t place = fill_[cellOfParticle_[i]]++;
    order_[place] = uint32_t(i);
    cellOfPlace_[place] = cellOfParticle_[i];
  }
}

int ParticleGrid::neighbourRanges(uint32_t cell, Range (&out)[9]) const {
  const int x = int(cell % uint32_t(dims_.x));
  const int y = int(cell / uint32_t(dims_.x) % uint32_t(dims_.y));
  const int z = int(cell / (uint32_t(dims_.x) * uint32_t(dims_.y)));
  const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, dims_.x - 1);
  int count = 0;
  for (int dz = std::max(z - 1, 0); dz <= std::min(z + 1, dims_.z - 1); ++dz)
    for (int dy = std::max(y - 1, 0); dy <= std::min(y + 1, dims_.y - 1); ++dy) {
      const size_t row = (size_t(dz) * dims_.y + dy) * dims_.x;
      const uint32_t begin = cellStart_[row + x0], end = cellStart_[row + x1 + 1];
      if (begin < end) out[count++] = {begin, end};
    }
  return count;
}

}  // namespace mq
