// The search's first stage: how every vertex moved in the step, and each
// element's box for the trees.
#include <algorithm>
#include <array>

#include "sim/cloth/collision/self_collision/stages.h"

namespace mq::cloth {

using namespace self_collision;

namespace {

// The box of an element's vertices at the start of the step (and at its end
// when `end` is given) grown by `grow`: the box Box::extend makes, in registers.
template <size_t N>
Box grownBox(const std::array<uint32_t, N>& vertices, const std::vector<glm::vec3>& start,
             const std::vector<glm::vec3>* end, float grow) {
#ifdef __SSE2__
  __m128 lo = row(start[vertices[0]]), hi = lo;
  for (uint32_t v : vertices) {
    const __m128 p = row(start[v]);
    lo = _mm_min_ps(lo, p), hi = _mm_max_ps(hi, p);
    if (end) {
      const __m128 q = row((*end)[v]);
      lo = _mm_min_ps(lo, q), hi = _mm_max_ps(hi, q);
    }
  }
  const __m128 g = _mm_set1_ps(grow);
  alignas(16) float low[4], high[4];
  _mm_store_ps(low, _mm_sub_ps(lo, g)), _mm_store_ps(high, _mm_add_ps(hi, g));
  return Box{{low[0], low[1], low[2]}, {high[0], high[1], high[2]}};
#else
  Box b;
  for (uint32_t v : vertices) {
    b.extend(start[v]);
    if (end) b.extend((*end)[v]);
  }
  b.min -= glm::vec3(grow);
  b.max += glm::vec3(grow);
  return b;
#endif
}
}  // namespace

void SelfCollision::measureMoves(Step& step) const {
  const ClothState& s = step.s;
  const std::vector<glm::vec3>& x0 = step.x0;
  const size_t n = s.size();
  // How every vertex moved in the step. Two elements can close their gap by
  // at most the largest difference of their vertices' moves (a sheet falling
  // as a whole closes none).
  // The moves and their lengths in parallel, the sums in order (the same
  // float sums for any thread count).
  std::vector<glm::vec3>& move = step.move;
  std::vector<float>& offMean = step.offMean;  // its move's length, then its distance from the mean move
  move.resize(n), offMean.resize(n);
  inChunks(n, 2048, [&](size_t v0, size_t v1) {
    for (size_t v = v0; v < v1; ++v) move[v] = s.x[v] - x0[v], offMean[v] = glm::length(move[v]);
  });
  glm::vec3 meanMove(0.0f);
  float meanMotion = 0.0f;
  for (size_t v = 0; v < n; ++v) meanMove += move[v], meanMotion += offMean[v];
  meanMove /= float(std::max<size_t>(n, 1));
  meanMotion /= float(std::max<size_t>(n, 1));
  step.meanMotion = meanMotion;
  inChunks(n, 2048, [&](size_t v0, size_t v1) {
    for (size_t v = v0; v < v1; ++v) offMean[v] = glm::length(move[v] - meanMove);
  });
  float deviation = 0.0f;
  for (size_t v = 0; v < n; ++v) deviation = std::max(deviation, offMean[v]);
  step.deviation = deviation;
}

void SelfCollision::findElementBoxes(Step& step) const {
  const ClothState& s = step.s;
  const std::vector<glm::vec3>& x0 = step.x0;
  const float thickness = step.thickness;
  const std::vector<float>& offMean = step.offMean;
  const size_t triangleCount = triangles_.size() / 3;
  std::vector<Box>& boxes = step.boxes;
  std::vector<Box>& edgeBoxes = step.edgeBoxes;
  std::vector<Box>& sweptBoxes = step.sweptBoxes;
  std::vector<Box>& sweptEdgeBoxes = step.sweptEdgeBoxes;
  // Element boxes for the broad phase. Swept over the step (start and end,
  // grown by the thickness) when the cloth's moves differ much (a pair is a
  // candidate only when those overlap); otherwise no such condition: any two
  // elements closing by up to twice the deviation qualify ("relative" boxes:
  // at the start, grown by half the thickness plus their own vertices'
  // largest distance from the mean move). Either way a candidate passes the
  // exact test below, dist(x0) <= thickness + closing; the traversals check
  // it for whole nodes too (nodeMotions_), which keeps them out of the parts
  // that move rigidly, however far the cloth moves as a whole.
  const bool swept = step.swept = !(2.0f * step.deviation < step.meanMotion + thickness);
  auto extentSum = [](const std::vector<Box>& boxes) {
    double sum = 0.0;
    for (const Box& b : boxes) sum += double(b.max.x - b.min.x) + double(b.max.y - b.min.y) + double(b.max.z - b.min.z);
    return sum;
  };
  // The trees hold whichever kind is smaller in all; when they hold relative
  // boxes in swept mode, the swept boxes are checked on each pair.
  boxes.resize(triangleCount), edgeBoxes.resize(edges_.size());
  if (swept) sweptBoxes.resize(triangleCount), sweptEdgeBoxes.resize(edges_.size());
  // In parallel (each element on its own: the same boxes).
  // The same boxes as Step::relativeBox() and Step::sweptBox() for elements, in registers.
  auto relativeElementBox = [&](const auto& vertices) {
    float grow = 0.0f;
    for (uint32_t v : vertices) grow = std::max(grow, offMean[v]);
    return grownBox(vertices, x0, nullptr, grow + 0.5f * thickness);
  };
  auto sweptElementBox = [&](const auto& vertices) { return grownBox(vertices, x0, &s.x, thickness); };
  inChunks(triangleCount, 4096, [&](size_t t0, size_t t1) {
    for (size_t t = t0; t < t1; ++t) {
      const std::array<uint32_t, 3> corners{triangles_[3 * t], triangles_[3 * t + 1], triangles_[3 * t + 2]};
      boxes[t] = relativeElementBox(corners);
      if (swept) sweptBoxes[t] = sweptElementBox(corners);
    }
  });
  inChunks(edges_.size(), 4096, [&](size_t e0, size_t e1) {
    for (size_t e = e0; e < e1; ++e) {
      const std::array<uint32_t, 2> ends{edges_[e].first, edges_[e].second};
      edgeBoxes[e] = relativeElementBox(ends);
      if (swept) sweptEdgeBoxes[e] = sweptElementBox(ends);
    }
  });
  if (swept) {
    step.checkSwept = extentSum(boxes) + extentSum(edgeBoxes) < extentSum(sweptBoxes) + extentSum(sweptEdgeBoxes);
    if (!step.checkSwept) boxes.swap(sweptBoxes), edgeBoxes.swap(sweptEdgeBoxes);
  }
}

}  // namespace mq::cloth
