// The search's edge-edge candidates: the edge tree against itself, four
// pairs at once through a cheap bound (EdgeColumns), then the exact test at
// the start of the step. The exhaustive search (setExhaustive) is the
// tests' oracle.
#include <algorithm>
#include <array>

#include "sim/cloth/collision/proximity.h"
#include "sim/cloth/collision/segment_reach.h"
#include "sim/cloth/collision/self_collision/stages.h"

namespace mq::cloth {

using namespace self_collision;

// The edges' vertices and cheap bounds (see findCandidates) by place in the
// edge tree, as columns padded by three places: four places from any one
// are read at once.
void SelfCollision::EdgeColumns::resize(size_t places) {
  for (std::vector<uint32_t>* c : {&v0, &v1, &edge}) c->resize(places + 3, UINT32_MAX);
  for (std::vector<float>* c : {&midX, &midY, &midZ, &halfX, &halfY, &halfZ, &moveX, &moveY, &moveZ, &spread})
    c->resize(places + 3, 0.0f);
  for (int end = 0; end < 2; ++end)
    for (std::vector<float>* c : {&startX[end], &startY[end], &startZ[end], &stepX[end], &stepY[end], &stepZ[end]})
      c->resize(places + 3, 0.0f);
}

void SelfCollision::EdgeColumns::set(size_t k, uint32_t e, uint32_t a, uint32_t b, const glm::vec3& mid,
                                     const glm::vec3& halfEdge, const glm::vec3& meanMove, float moveSpread) {
  edge[k] = e, v0[k] = a, v1[k] = b;
  midX[k] = mid.x, midY[k] = mid.y, midZ[k] = mid.z;
  halfX[k] = halfEdge.x, halfY[k] = halfEdge.y, halfZ[k] = halfEdge.z;
  moveX[k] = meanMove.x, moveY[k] = meanMove.y, moveZ[k] = meanMove.z, spread[k] = moveSpread;
}

void SelfCollision::EdgeColumns::setVertices(size_t k, const glm::vec3 (&start)[2], const glm::vec3 (&move)[2]) {
  for (int end = 0; end < 2; ++end) {
    startX[end][k] = start[end].x, startY[end][k] = start[end].y, startZ[end][k] = start[end].z;
    stepX[end][k] = move[end].x, stepY[end][k] = move[end].y, stepZ[end][k] = move[end].z;
  }
}

inline unsigned SelfCollision::EdgeColumns::withinReach(uint32_t i, uint32_t first, float thickness) const {
#ifdef MQ_SEGMENT_REACH_SSE
  auto own = [&](const std::vector<float>& c) { return _mm_set1_ps(c[i]); };
  auto column = [&](const std::vector<float>& c) { return _mm_loadu_ps(&c[first]); };
  // The exact test takes the edge of lower index first: per lane, the own
  // edge or the other's.
  const __m128 ownFirst = _mm_castsi128_ps(
      _mm_cmplt_epi32(_mm_set1_epi32(int(edge[i])), _mm_loadu_si128(reinterpret_cast<const __m128i*>(&edge[first]))));
  auto pick = [&](const std::vector<float>& c, bool firstEdge) {
    const __m128 a = own(c), b = column(c);
    return firstEdge ? _mm_or_ps(_mm_and_ps(ownFirst, a), _mm_andnot_ps(ownFirst, b))
                     : _mm_or_ps(_mm_and_ps(ownFirst, b), _mm_andnot_ps(ownFirst, a));
  };
  auto point = [&](int end, bool firstEdge) {
    return Vec3x4{pick(startX[end], firstEdge), pick(startY[end], firstEdge), pick(startZ[end], firstEdge)};
  };
  // The largest difference of the two edges' vertices' moves (the same
  // either way round: a difference's negation is exact).
  __m128 worst = _mm_setzero_ps();
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const __m128 dx = _mm_sub_ps(own(stepX[a]), column(stepX[b])), dy = _mm_sub_ps(own(stepY[a]), column(stepY[b]));
      const __m128 dz = _mm_sub_ps(own(stepZ[a]), column(stepZ[b]));
      worst = _mm_max_ps(worst, _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz)));
    }
  const __m128 reach = _mm_add_ps(_mm_set1_ps(thickness), _mm_sqrt_ps(worst));
  return segmentsWithinReach(point(0, true), point(1, true), point(0, false), point(1, false), reach);
#else
  (void)i, (void)first, (void)thickness;
  return 0xFu;  // testEdgeEdge tests them one by one
#endif
}

inline unsigned SelfCollision::EdgeColumns::apartOrNeighbours(uint32_t i, uint32_t first, float thickness) const {
#ifdef __SSE2__
  auto column = [&](const std::vector<float>& c) { return _mm_loadu_ps(&c[first]); };
  auto own = [&](const std::vector<float>& c) { return _mm_set1_ps(c[i]); };
  auto offset = [&](const std::vector<float>& x, const std::vector<float>& y, const std::vector<float>& z) {
    return Vec3x4{_mm_sub_ps(own(x), column(x)), _mm_sub_ps(own(y), column(y)), _mm_sub_ps(own(z), column(z))};
  };
  auto length = [&](const Vec3x4& d) {
    return _mm_sqrt_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(d.x, d.x), _mm_mul_ps(d.y, d.y)), _mm_mul_ps(d.z, d.z)));
  };
  const __m128i a0 = _mm_set1_epi32(int(v0[i])), a1 = _mm_set1_epi32(int(v1[i]));
  const __m128i b0 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&v0[first]));
  const __m128i b1 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&v1[first]));
  const __m128i shared = _mm_or_si128(_mm_or_si128(_mm_cmpeq_epi32(a0, b0), _mm_cmpeq_epi32(a0, b1)),
                                      _mm_or_si128(_mm_cmpeq_epi32(a1, b0), _mm_cmpeq_epi32(a1, b1)));
  const __m128 bound = _mm_add_ps(_mm_add_ps(_mm_set1_ps(thickness), length(offset(moveX, moveY, moveZ))),
                                  _mm_add_ps(own(spread), column(spread)));
  const Vec3x4 ownHalf{own(halfX), own(halfY), own(halfZ)}, otherHalf{column(halfX), column(halfY), column(halfZ)};
  return unsigned(_mm_movemask_ps(_mm_castsi128_ps(shared))) |
         segmentsApart(offset(midX, midY, midZ), ownHalf, otherHalf, bound);
#else
  (void)i, (void)first, (void)thickness;
  return 0;  // testEdgeEdge tests them one by one (kScreened false)
#endif
}

void SelfCollision::findEdgeEdgeCandidates(const Step& step) {
  const std::vector<glm::vec3>& x0 = step.x0;
  const std::vector<glm::vec3>& move = step.move;
  const float thickness = step.thickness;
  const bool checkSwept = step.checkSwept, bounded = step.bounded;
  const std::vector<Box>& edgeBoxes = step.edgeBoxes;
  const std::vector<Box>& sweptEdgeBoxes = step.sweptEdgeBoxes;
  // Edge pairs from the edge tree against itself. A cheap bound first, from
  // each edge's midpoint, half length, mean move and move spread: any two of
  // their vertices' moves differ by at most |mean_e - mean_f| + spread_e +
  // spread_f, so a pair it rejects fails the exact test below too. The
  // four-lane screen (EdgeColumns::apartOrNeighbours) bounds their distance
  // along the line through their midpoints instead of by their half lengths
  // (tighter: most close pairs of a curved part are left out before the exact
  // test).
  struct EdgeBound {
    glm::vec3 mid;
    float halfLength;
    glm::vec3 meanMove;
    float spread;
  };
  std::vector<EdgeBound> bounds(edges_.size());  // by place
  EdgeColumns& columns = edgeColumns_;
  columns.resize(edges_.size());
  inChunks(edges_.size(), 4096, [&](size_t k0, size_t k1) {
    for (size_t k = k0; k < k1; ++k) {
      const auto [p0, p1] = edgeAtPlace_[k];
      const EdgeBound& b = bounds[k] = {0.5f * (x0[p0] + x0[p1]), 0.5f * glm::length(x0[p0] - x0[p1]),
                                        0.5f * (move[p0] + move[p1]), 0.5f * glm::length(move[p0] - move[p1])};
      columns.set(k, edgeTree_.primitive(uint32_t(k)), p0, p1, b.mid, 0.5f * (x0[p1] - x0[p0]), b.meanMove, b.spread);
      columns.setVertices(k, {x0[p0], x0[p1]}, {move[p0], move[p1]});
    }
  });
  // Two edges at places of the edge tree whose boxes overlap, not in one
  // flat patch (screened: not neighbours and within the four-lane screen's
  // bound, as EdgeColumns::apartOrNeighbours found).
  auto testEdgeEdge = [&](uint32_t placeI, uint32_t placeK, std::vector<EdgeEdge>& out, bool screened) {
    // Neighbours first, from the edges' vertices in the tree's order (read in sequence).
    const auto [a0, a1] = edgeAtPlace_[placeI];
    const auto [b0, b1] = edgeAtPlace_[placeK];
    if (!screened && sharesVertex(a0, a1, b0, b1)) return;
    if (bounded && !withinReach(edgeMotions_[placeI], edgeMotions_[placeK], thickness)) return;
    if (checkSwept && !sweptEdgeBoxes[placeI].overlaps(sweptEdgeBoxes[placeK])) return;
    if (!screened) {
      const EdgeBound &bi = bounds[placeI], &bk = bounds[placeK];
      const float bound = thickness + glm::length(bi.meanMove - bk.meanMove) + (bi.spread + bk.spread);
      if (glm::length(bi.mid - bk.mid) - (bi.halfLength + bk.halfLength) > 1.0001f * bound + 1e-6f) return;
    }
    // The exact test with the edges in their order (the lower index first).
    const uint32_t i = edgeTree_.primitive(placeI), k = edgeTree_.primitive(placeK);
    const bool ordered = i < k;
    const uint32_t e = ordered ? i : k, f = ordered ? k : i;
    const uint32_t p0 = ordered ? a0 : b0, p1 = ordered ? a1 : b1, q0 = ordered ? b0 : a0, q1 = ordered ? b1 : a1;
    if (!segmentsWithinReach(x0[p0], x0[p1], x0[q0], x0[q1], thickness + step.closing({p0, p1}, {q0, q1}))) return;
    const glm::vec2 st = closestSegmentParameters(x0[p0], x0[p1], x0[q0], x0[q1]);
    const glm::vec3 d = glm::mix(x0[p0], x0[p1], st.x) - glm::mix(x0[q0], x0[q1], st.y);
    out.push_back({e, f, st, d / glm::length(d)});
  };
  std::vector<std::vector<EdgeEdge>> found;
  if (exhaustive_) {
    const uint32_t places = uint32_t(edges_.size());
    found.resize(places);
    ThreadPool::shared().parallelBlocks(places, [&](size_t i) {
      const Box& box = edgeBoxes[edgeTree_.primitive(uint32_t(i))];
      const int32_t flat = topFlatEdgePlace_[i];
      for (uint32_t k = uint32_t(i) + 1; k < places; ++k) {
        if ((flat >= 0 && flat == topFlatEdgePlace_[k]) || !box.overlaps(edgeBoxes[edgeTree_.primitive(k)])) continue;
        testEdgeEdge(uint32_t(i), k, found[i], false);
      }
    });
  } else {
    auto flatEdgePatch = [&](int32_t node) { return flatEdgePatch_[node] != 0; };
    auto outOfReach = [&](int32_t a, int32_t b) {
      return bounded && !withinReach(edgeNodeMotions_[a], edgeNodeMotions_[b], thickness);
    };
    const std::vector<AabbTree::PairJob> jobs = edgeTree_.pairJobs(4 * kBlocks, flatEdgePatch);
    found.resize(jobs.size());
    ThreadPool::shared().parallelBlocks(jobs.size(), [&](size_t j) {
      // The neighbours and the cheap bound above for four pairs at once,
      // then the exact test's distance conditions (few pairs pass them).
      edgeTree_.runJobInQuads(
          jobs[j],
          [&](uint32_t placeI, uint32_t first, unsigned mask) {
            mask &= columns.apartOrNeighbours(placeI, first, thickness) ^ 0xFu;
            if (mask != 0) mask &= columns.withinReach(placeI, first, thickness);
            for (; mask != 0; mask &= mask - 1)
              testEdgeEdge(placeI, first + uint32_t(__builtin_ctz(mask)), found[j], kScreened);
          },
          flatEdgePatch, outOfReach);
    });
  }
  // In order of the first edge, then the other (the jobs' order depends on the tree).
  edgeEdge_.clear();
  for (const auto& f : found) edgeEdge_.insert(edgeEdge_.end(), f.begin(), f.end());
  std::sort(edgeEdge_.begin(), edgeEdge_.end(),
            [](const EdgeEdge& a, const EdgeEdge& b) { return a.e0 != b.e0 ? a.e0 < b.e0 : a.e1 < b.e1; });
}

}  // namespace mq::cloth
