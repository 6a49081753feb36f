#pragma once
// Hair strands as flat arrays: strand s has pointsPerStrand points starting at
// points[3 * s * pointsPerStrand], root first. Every strand has the same point
// count so loops over strands vectorise and split across threads.

#include <cstdint>
#include <utility>
#include <vector>

namespace mq {

struct Strands {
  int pointsPerStrand = 0;
  std::vector<float> points;       // strands * pointsPerStrand * 3, world or head space
  std::vector<float> rootNormals;  // 3 per strand: scalp normal at the root
  std::vector<float> rootUvs;      // 2 per strand: scalp parameterisation, may be empty
  std::vector<int32_t> guideOf;    // per strand: its nearest guide (-1 for guides), may be empty
  // 4 per strand, its painted pigments as shares of the style's (groom_stroke.h's
  // PaintedShare): eumelanin keep, add, pheomelanin keep, add. Empty: none painted.
  std::vector<float> pigmentPaint;

  size_t strandCount() const { return pointsPerStrand > 0 ? points.size() / (3 * size_t(pointsPerStrand)) : 0; }
  float* strand(size_t s) { return points.data() + 3 * s * pointsPerStrand; }
  const float* strand(size_t s) const { return points.data() + 3 * s * pointsPerStrand; }
  // Strand s's eumelanin and pheomelanin over the style's `melanin` and
  // `pheomelanin` (the style's own where nothing is painted).
  std::pair<float, float> pigments(size_t s, float melanin, float pheomelanin) const {
    if (pigmentPaint.size() < 4 * (s + 1)) return {melanin, pheomelanin};
    const float* p = &pigmentPaint[4 * s];
    return {p[0] * melanin + p[1], p[2] * pheomelanin + p[3]};
  }
};

}  // namespace mq
