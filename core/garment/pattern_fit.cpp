#include "core/garment/pattern_fit.h"

#include <algorithm>
#include <cmath>

namespace mq {
namespace {

constexpr float kBendAngle = 20.0f * float(M_PI) / 180.0f;
constexpr float kStraightTolerance = 0.00005f;  // metres: a run this close to its chord is a line
constexpr float kCurveTolerance = 0.0005f;      // metres: a fitted curve's largest distance to the run

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
  const glm::vec2 ab = b - a;
  const float length2 = glm::dot(ab, ab);
  const float t = length2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / length2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * ab));
}

glm::vec2 cubicPoint(glm::vec2 p0, glm::vec2 c0, glm::vec2 c1, glm::vec2 p1, float t) {
  const float s = 1.0f - t;
  return s * s * s * p0 + 3.0f * s * s * t * c0 + 3.0f * s * t * t * c1 + t * t * t * p1;
}

// Fits run[first..last] (both kept as corners) and appends the edges.
void fitPiece(const std::vector<glm::vec2>& run, size_t first, size_t last, std::vector<FittedEdge>& out) {
  const glm::vec2 p0 = run[first], p1 = run[last];
  float straightError = 0.0f;
  for (size_t i = first + 1; i < last; ++i) straightError = std::max(straightError, distanceToSegment(run[i], p0, p1));
  if (last - first < 3 || straightError <= kStraightTolerance) {
    if (last - first >= 2 && straightError > kStraightTolerance) {  // too few points for a curve: keep them as lines
      for (size_t i = first; i < last; ++i) out.push_back({EdgeShape::Line, run[i], {}});
      return;
    }
    out.push_back({EdgeShape::Line, p0, {}});
    return;
  }
  // Chord-length parameters, then least squares for the two inner control points.
  std::vector<float> t(last - first + 1, 0.0f);
  for (size_t i = first + 1; i <= last; ++i) t[i - first] = t[i - first - 1] + glm::length(run[i] - run[i - 1]);
  for (float& v : t) v /= t.back();
  double a11 = 0, a12 = 0, a22 = 0;
  glm::dvec2 r1(0.0), r2(0.0);
  for (size_t i = first; i <= last; ++i) {
    const double u = t[i - first], s = 1.0 - u;
    const double b0 = s * s * s, b1 = 3 * s * s * u, b2 = 3 * s * u * u, b3 = u * u * u;
    const glm::dvec2 rest = glm::dvec2(run[i]) - b0 * glm::dvec2(p0) - b3 * glm::dvec2(p1);
    a11 += b1 * b1, a12 += b1 * b2, a22 += b2 * b2;
    r1 += b1 * rest, r2 += b2 * rest;
  }
  const double det = a11 * a22 - a12 * a12;
  glm::vec2 c0 = p0 + (p1 - p0) / 3.0f, c1 = p0 + 2.0f * (p1 - p0) / 3.0f;
  if (std::abs(det) > 1e-12) {
    c0 = glm::vec2((a22 * r1 - a12 * r2) / det);
    c1 = glm::vec2((a11 * r2 - a12 * r1) / det);
  }
  float worst = 0.0f;
  for (size_t i = first + 1; i < last; ++i)
    worst = std::max(worst, glm::length(cubicPoint(p0, c0, c1, p1, t[i - first]) - run[i]));
  if (worst <= kCurveTolerance) {
    out.push_back({EdgeShape::Cubic, p0, {c0, c1}});
    return;
  }
  // Halves (not the worst point, which lies near an end and leaves a sliver): fewer curves.
  const size_t split = (first + last) / 2;
  fitPiece(run, first, split, out);
  fitPiece(run, split, last, out);
}

}  // namespace

std::vector<FittedEdge> fitOutlineRun(const std::vector<glm::vec2>& run, std::vector<bool> corner, bool findBends) {
  std::vector<FittedEdge> out;
  if (run.size() < 2) return out;
  corner.resize(run.size(), false);
  corner.front() = corner.back() = true;
  for (size_t i = 1; findBends && i + 1 < run.size(); ++i) {
    const glm::vec2 in = run[i] - run[i - 1], away = run[i + 1] - run[i];
    const float lengths = glm::length(in) * glm::length(away);
    if (lengths > 0.0f && std::acos(std::clamp(glm::dot(in, away) / lengths, -1.0f, 1.0f)) > kBendAngle)
      corner[i] = true;
  }
  size_t first = 0;
  for (size_t i = 1; i < run.size(); ++i)
    if (corner[i]) {
      if (glm::length(run[i] - run[first]) > 0.0f) fitPiece(run, first, i, out);
      first = i;
    }
  return out;
}

}  // namespace mq
