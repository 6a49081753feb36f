#include "sim/hair/hair_interaction.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/util/thread_pool.h"
#include "sim/cloth/collision/proximity.h"

namespace mq {

namespace {

glm::vec3 load(const float* a, size_t i) { return {a[3 * i], a[3 * i + 1], a[3 * i + 2]}; }

// A share k taken once per 1/60 s, for a substep of h: the same share is
// left after 1/60 s whatever the substep (as the simulator's stiffnesses).
float sharePerSubstep(float k, float h) {
  k = glm::clamp(k, 0.0f, 1.0f);
  return 1.0f - std::pow(1.0f - k, h * 60.0f);
}

float kernel(float r2, float invR2) {
  const float t = 1.0f - r2 * invR2;
  return t > 0.0f ? t * t * t : 0.0f;
}

float meanSegmentLength(const std::vector<float>& points, size_t strandCount, int n) {
  double sum = 0.0;
  size_t count = 0;
  for (size_t s = 0; s < strandCount; ++s)
    for (int i = 0; i + 1 < n; ++i) {
      const size_t a = s * n + i;
      sum += glm::length(load(points.data(), a + 1) - load(points.data(), a));
      ++count;
    }
  return count ? float(sum / double(count)) : 0.0f;
}

// Squared distance between segments [p0, p1] and [q0, q1].
float segmentDistance2(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& q0, const glm::vec3& q1) {
  const glm::vec2 st = cloth::closestSegmentParameters(p0, p1, q0, q1);
  const glm::vec3 gap = (p0 + st.x * (p1 - p0)) - (q0 + st.y * (q1 - q0));
  return glm::dot(gap, gap);
}

}  // namespace

float meanRootSpacing(const std::vector<float>& points, size_t strandCount, int pointsPerStrand) {
  if (strandCount < 2) return 0.0f;
  std::vector<glm::vec3> roots(strandCount);
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (size_t s = 0; s < strandCount; ++s) {
    roots[s] = load(points.data(), s * pointsPerStrand);
    lo = glm::min(lo, roots[s]);
    hi = glm::max(hi, roots[s]);
  }
  // Cells of about two spacings of roots spread over a surface; a root whose
  // nearest neighbour is not within one cell is searched among all.
  const glm::vec3 extent = hi - lo;
  const float cell = std::max(2.0f * std::max({extent.x, extent.y, extent.z}) / std::sqrt(float(strandCount)), 1e-6f);
  ParticleGrid grid;
  grid.build(roots, cell);
  std::vector<float> nearest(strandCount);
  ThreadPool::shared().parallelFor(0, strandCount, 256, [&](size_t begin, size_t end) {
    ParticleGrid::Range ranges[9];
    for (size_t e = begin; e < end; ++e) {
      const uint32_t s = grid.order()[e];
      float best = INFINITY;
      const int count = grid.neighbourRanges(grid.cellAt(e), ranges);
      for (int r = 0; r < count; ++r)
        for (uint32_t f = ranges[r].first; f < ranges[r].second; ++f) {
          const uint32_t o = grid.order()[f];
          if (o != s) best = std::min(best, glm::length(roots[o] - roots[s]));
        }
      if (!(best <= cell))
        for (size_t o = 0; o < strandCount; ++o)
          if (o != s) best = std::min(best, glm::length(roots[o] - roots[s]));
      nearest[s] = best;
    }
  });
  double sum = 0.0;
  for (float d : nearest) sum += d;
  return float(sum / double(strandCount));
}

size_t closeSegmentPairs(const std::vector<float>& points, size_t strandCount, int n, float distance) {
  if (strandCount < 2 || n < 3) return 0;
  // Segments from the second one on: roots sit side by side on the scalp.
  const int perStrand = n - 2;
  std::vector<glm::vec3> mid(strandCount * perStrand);
  float longest = 0.0f;
  for (size_t s = 0; s < strandCount; ++s)
    for (int k = 0; k < perStrand; ++k) {
      const glm::vec3 a = load(points.data(), s * n + k + 1), b = load(points.data(), s * n + k + 2);
      mid[s * perStrand + k] = 0.5f * (a + b);
      longest = std::max(longest, glm::length(b - a));
    }
  const float reach = longest + distance;  // midpoints of segments closer than `distance`
  ParticleGrid grid;
  grid.build(mid, std::max(reach, 1e-6f));
  const float distance2 = distance * distance;
  std::vector<uint32_t> perSegment(mid.size(), 0);
  ThreadPool::shared().parallelFor(0, mid.size(), 256, [&](size_t begin, size_t end) {
    ParticleGrid::Range ranges[9];
    for (size_t e = begin; e < end; ++e) {
      const uint32_t i = grid.order()[e];
      const size_t s = i / perStrand;
      const int k = int(i % perStrand);
      const glm::vec3 a = load(points.data(), s * n + k + 1), b = load(points.data(), s * n + k + 2);
      const int count = grid.neighbourRanges(grid.cellAt(e), ranges);
      for (int r = 0; r < count; ++r)
        for (uint32_t f = ranges[r].first; f < ranges[r].second; ++f) {
          const uint32_t j = grid.order()[f];
          const size_t other = j / perStrand;
          if (other <= s) continue;  // each pair once, other strands only
          const glm::vec3 gap = mid[j] - mid[i];
          if (glm::dot(gap, gap) > reach * reach) continue;
          const int l = int(j % perStrand);
          const glm::vec3 c0 = load(points.data(), other * n + l + 1), c1 = load(points.data(), other * n + l + 2);
          if (segmentDistance2(a, b, c0, c1) < distance2) ++perSegment[i];
        }
    }
  });
  size_t total = 0;
  for (uint32_t c : perSegment) total += c;
  return total;
}

void HairInteraction::setRest(const std::vector<float>& restPoints, size_t strandCount, int pointsPerStrand,
                              const HairInteractionParams& params) {
  strandCount_ = strandCount;
  pointsPerStrand_ = pointsPerStrand;
  params_ = params;
  radius_ = params.radius;
  if (!(radius_ > 0.0f)) {
    const float spacing = meanRootSpacing(restPoints, strandCount, pointsPerStrand);
    const float segment = meanSegmentLength(restPoints, strandCount, pointsPerStrand);
    // Wide enough that strands crossing between particles still meet.
    radius_ = std::max({2.0f * spacing, 0.5f * segment, 1e-4f});
  }
  std::vector<glm::vec3> rest(restPoints.size() / 3);
  for (size_t i = 0; i < rest.size(); ++i) rest[i] = load(restPoints.data(), i);
  computeDensities(rest);
  restDensity_.resize(rest.size());
  for (size_t e = 0; e < rest.size(); ++e) restDensity_[grid_.order()[e]] = sortedDensity_[e];
  const float floor = kernel(0.25f, 1.0f);  // W(R/2)
  for (float& rho : restDensity_) rho = std::max(rho, floor);
}

void HairInteraction::setParams(const HairInteractionParams& params) {
  const float radius = radius_;
  params_ = params;
  params_.radius = radius;
}

void HairInteraction::buildGrid(const std::vector<glm::vec3>& at) {
  const size_t count = at.size();
  grid_.build(at, radius_);
  // The particles in cell order, so a cell's particles sit side by side.
  const std::vector<uint32_t>& order = grid_.order();
  sortedPositions_.resize(count);
  sortedStrands_.resize(count);
  for (size_t e = 0; e < count; ++e) {
    sortedPositions_[e] = at[order[e]];
    sortedStrands_[e] = uint32_t(order[e] / pointsPerStrand_);
  }
}

// Calls visit(e, d, r2) for every particle e (cell order) of another strand
// within the radius of each particle of cell order [begin, end), with
// each(e) before a particle's neighbours and done(e) after. The 9 rows'
// ranges are found once per cell.
template <class Each, class Visit, class Done>
void HairInteraction::forNeighbourRange(size_t begin, size_t end, Each&& each, Visit&& visit, Done&& done) const {
  const float radius2 = radius_ * radius_;
  ParticleGrid::Range ranges[9];
  int rangeCount = 0;
  uint32_t lastCell = std::numeric_limits<uint32_t>::max();
  for (size_t e = begin; e < end; ++e) {
    const glm::vec3 xi = sortedPositions_[e];
    const uint32_t strand = sortedStrands_[e];
    const uint32_t cell = grid_.cellAt(e);
    if (cell != lastCell) {
      rangeCount = grid_.neighbourRanges(cell, ranges);
      lastCell = cell;
    }
    each(e);
    for (int c = 0; c < rangeCount; ++c)
      for (uint32_t f = ranges[c].first; f < ranges[c].second; ++f) {
        if (sortedStrands_[f] == strand) continue;  // a strand's own particles hold by its constraints
        const glm::vec3 d = xi - sortedPositions_[f];
        const float r2 = glm::dot(d, d);
        if (r2 < radius2) visit(f, d, r2);
      }
    done(e);
  }
}

// Densities in cell order (sortedDensity_); each block of particles keeps
// its particles' neighbour lists for apply().
void HairInteraction::computeDensities(const std::vector<glm::vec3>& positions) {
  buildGrid(positions);
  const size_t count = positions.size();
  sortedDensity_.assign(count, 0.0f);
  neighbourEnd_.resize(count);
  const size_t blocks = (count + kBlock - 1) / kBlock;
  blockNeighbours_.resize(blocks);
  const float invR2 = 1.0f / (radius_ * radius_);
  ThreadPool::shared().parallelFor(0, blocks, 1, [&](size_t firstBlock, size_t lastBlock) {
    for (size_t b = firstBlock; b < lastBlock; ++b) {
      std::vector<Neighbour>& list = blockNeighbours_[b];
      list.clear();
      float rho = 0.0f;
      forNeighbourRange(
          b * kBlock, std::min(count, (b + 1) * kBlock), [&](size_t) { rho = 0.0f; },
          [&](uint32_t f, const glm::vec3&, float r2) {
            rho += kernel(r2, invR2);
            list.push_back({f, r2});
          },
          [&](size_t e) {
            sortedDensity_[e] = rho;
            neighbourEnd_[e] = uint32_t(list.size());
          });
    }
  });
}

void HairInteraction::apply(std::vector<glm::vec3>& predicted, const std::vector<float>& positions, float h) {
  if (!params_.enabled() || predicted.size() != restDensity_.size() || positions.size() != 3 * predicted.size() ||
      !(h > 0.0f))
    return;
  const size_t count = predicted.size();
  computeDensities(predicted);
  const float invH = 1.0f / h;
  // Pressure and velocity in cell order, beside the positions.
  pressure_.resize(count);
  sortedVelocities_.resize(count);
  compressed_ = 0;
  for (size_t e = 0; e < count; ++e) {
    const uint32_t i = grid_.order()[e];
    pressure_[e] = glm::clamp(sortedDensity_[e] / restDensity_[i] - 1.0f, 0.0f, 1.0f);
    if (pressure_[e] > 0.0f) ++compressed_;
    sortedVelocities_[e] = (predicted[i] - load(positions.data(), i)) * invH;
  }
  push_.resize(count);
  dv_.resize(count);
  const float invR = 1.0f / radius_, invR2 = invR * invR;
  const float volume = sharePerSubstep(params_.volume, h), friction = sharePerSubstep(params_.friction, h);
  ThreadPool::shared().parallelFor(0, blockNeighbours_.size(), 1, [&](size_t firstBlock, size_t lastBlock) {
    for (size_t b = firstBlock; b < lastBlock; ++b) {
      const std::vector<Neighbour>& list = blockNeighbours_[b];
      uint32_t k = 0;
      for (size_t e = b * kBlock, last = std::min(count, (b + 1) * kBlock); e < last; ++e) {
        const glm::vec3 xi = sortedPositions_[e], vi = sortedVelocities_[e];
        const float pi = pressure_[e];
        glm::vec3 push(0.0f), stop(0.0f), drag(0.0f);
        float sumG = 0.0f, sumW = 0.0f;
        for (; k < neighbourEnd_[e]; ++k) {
          const uint32_t f = list[k].particle;
          const float r2 = list[k].distance2, r = std::sqrt(r2);
          const float g = (1.0f - r * invR) * (1.0f - r * invR), w = kernel(r2, invR2);
          const glm::vec3 vj = sortedVelocities_[f];
          sumG += g;
          sumW += w;
          drag += w * (vj - vi);
          const float q = 0.5f * (pi + pressure_[f]);
          if (q <= 0.0f || r < 1e-9f) continue;
          const glm::vec3 u = (xi - sortedPositions_[f]) / r;
          push += q * g * u;
          const float approach = glm::dot(vi - vj, u);
          if (approach < 0.0f) stop -= q * g * approach * u;
        }
        const float norm = 1.0f / std::max(1.0f, sumG);
        push_[e] = volume * radius_ * norm * push;
        dv_[e] = volume * norm * stop + friction * drag / (1.0f + sumW);
      }
    }
  });
  for (size_t e = 0; e < count; ++e) {
    const uint32_t i = grid_.order()[e];
    if (i % pointsPerStrand_ == 0) continue;  // roots follow the scalp
    predicted[i] += push_[e] + h * dv_[e];
  }
}

}  // namespace mq
