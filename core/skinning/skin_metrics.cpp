#include "core/skinning/skin_metrics.h"

#include <algorithm>
#include <cmath>

#include "core/character/implicit_body.h"
#include "core/mesh/mesh_checks.h"
#include "core/mesh/plane_section.h"

namespace mq {

namespace {

std::vector<float> concatenatedRestPositions(const Character& character) {
  std::vector<float> out;
  for (const Mesh& m : character.meshes) out.insert(out.end(), m.positions.begin(), m.positions.end());
  return out;
}

}  // namespace

MetricBody::MetricBody(const Character& character)
    : weld_(weldByPosition(concatenatedRestPositions(character), concatenatedTriangles(character))) {}

std::vector<float> MetricBody::weld(const std::vector<PosedMesh>& posed) const {
  return weld_.gather(concatenatedPositions(posed));
}

namespace {

struct SectionAt {
  PlaneChart chart;
  std::vector<Polygon2> loops;
  const Polygon2* around = nullptr;
};

SectionAt sectionThrough(const std::vector<float>& positions, const std::vector<uint32_t>& triangles,
                         const glm::dvec3& point, const glm::dvec3& normal) {
  SectionAt s{PlaneChart(point, normal), {}, nullptr};
  s.loops = sectionLoops(positions, triangles, s.chart);
  s.around = loopAround(s.loops, glm::dvec2(0.0));
  return s;
}

// Thickness and outer half area of a section along the in-plane direction.
std::pair<double, double> outerMeasures(const SectionAt& s, const glm::dvec3& outward) {
  if (!s.around) return {0.0, 0.0};
  glm::dvec2 o(glm::dot(outward, s.chart.u), glm::dot(outward, s.chart.v));
  o = glm::normalize(o);
  const double thickness = std::max(0.0, rayExitDistance(*s.around, glm::dvec2(0.0), o));
  const double half = polygonArea(clipToHalfPlane(*s.around, glm::dvec2(0.0), o));
  return {thickness, half};
}

}  // namespace

OuterSection outerSection(const std::vector<float>& rest, const std::vector<float>& posed,
                          const std::vector<uint32_t>& triangles, const BendFrame& bend) {
  const glm::dvec3 restNormal = bend.parentRest + bend.childRest;
  glm::dvec3 restOut = -bend.inward;
  restOut -= glm::dot(restOut, glm::normalize(restNormal)) * glm::normalize(restNormal);
  const glm::dvec3 posedOut = bend.parentPosed - bend.childPosed;
  const SectionAt restSection = sectionThrough(rest, triangles, bend.jointRest, restNormal);
  const SectionAt posedSection = sectionThrough(posed, triangles, bend.jointPosed, bend.parentPosed + bend.childPosed);
  const auto [restThickness, restHalf] = outerMeasures(restSection, restOut);
  const auto [posedThickness, posedHalf] = outerMeasures(posedSection, posedOut);
  OuterSection out;
  if (restThickness > 0.0) out.thickness = posedThickness / restThickness;
  if (restHalf > 0.0) out.halfArea = posedHalf / restHalf;
  return out;
}

double minimumSectionRatio(const std::vector<float>& rest, const std::vector<float>& posed,
                           const std::vector<uint32_t>& triangles, const glm::dvec3& joint, const glm::dvec3& axis,
                           double from, double to, double step) {
  double least = -1.0;
  const int count = int(std::floor((to - from) / step + 1e-9)) + 1;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 point = joint + (from + i * step) * axis;
    const SectionAt restSection = sectionThrough(rest, triangles, point, axis);
    if (!restSection.around) continue;
    const SectionAt posedSection = sectionThrough(posed, triangles, point, axis);
    const double ratio =
        posedSection.around ? polygonArea(*posedSection.around) / polygonArea(*restSection.around) : 0.0;
    if (least < 0.0 || ratio < least) least = ratio;
  }
  return least;
}

double localVolumeRatio(const std::vector<float>& rest, const std::vector<float>& posed,
                        const std::vector<uint32_t>& triangles, const glm::dvec3& jointRest,
                        const glm::dvec3& jointPosed, double radius) {
  auto at = [](const std::vector<float>& p, uint32_t i) {
    return glm::dvec3(p[3 * size_t(i)], p[3 * size_t(i) + 1], p[3 * size_t(i) + 2]);
  };
  double restVolume = 0.0, posedVolume = 0.0;
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const glm::dvec3 a = at(rest, triangles[t]), b = at(rest, triangles[t + 1]), c = at(rest, triangles[t + 2]);
    if (glm::length((a + b + c) / 3.0 - jointRest) > radius) continue;
    restVolume += glm::dot(a - jointRest, glm::cross(b - jointRest, c - jointRest)) / 6.0;
    const glm::dvec3 pa = at(posed, triangles[t]) - jointPosed, pb = at(posed, triangles[t + 1]) - jointPosed,
                     pc = at(posed, triangles[t + 2]) - jointPosed;
    posedVolume += glm::dot(pa, glm::cross(pb, pc)) / 6.0;
  }
  return restVolume != 0.0 ? posedVolume / restVolume : -1.0;
}

size_t intersectingPairs(const std::vector<float>& positions, const std::vector<uint32_t>& triangles) {
  return selfIntersections(positions, triangles).size();
}

BodyDeviation implicitBodyDeviation(const ImplicitBody& posedBody, const std::vector<float>& rest,
                                    const std::vector<float>& posed, const glm::dvec3& jointRest, double radius) {
  BodyDeviation out;
  double sum = 0.0, squares = 0.0;
  size_t beyond = 0;
  for (size_t v = 0; 3 * v + 2 < rest.size() && 3 * v + 2 < posed.size(); ++v) {
    const glm::dvec3 r(rest[3 * v], rest[3 * v + 1], rest[3 * v + 2]);
    if (glm::distance(r, jointRest) > radius) continue;
    const double d = posedBody.value({posed[3 * v], posed[3 * v + 1], posed[3 * v + 2]});
    ++out.vertices;
    sum += d;
    squares += d * d;
    out.largest = std::max(out.largest, std::abs(d));
    beyond += std::abs(d) > 0.002;
  }
  if (out.vertices == 0) return out;
  out.mean = sum / double(out.vertices);
  out.rms = std::sqrt(squares / double(out.vertices));
  out.beyond2mm = double(beyond) / double(out.vertices);
  return out;
}

}  // namespace mq
