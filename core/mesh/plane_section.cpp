#include "core/mesh/plane_section.h"

#include <cmath>
#include <unordered_map>

namespace mq {

PlaneChart::PlaneChart(const glm::dvec3& o, const glm::dvec3& n) : origin(o), normal(glm::normalize(n)) {
  const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  u = glm::normalize(glm::cross(helper, normal));
  v = glm::cross(normal, u);
}

glm::dvec2 PlaneChart::toPlane(const glm::dvec3& p) const {
  const glm::dvec3 d = p - origin;
  return {glm::dot(d, u), glm::dot(d, v)};
}

namespace {

uint64_t edgeKey(uint32_t a, uint32_t b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(a) << 32) | b;
}

}  // namespace

std::vector<Polygon2> sectionLoops(const std::vector<float>& positions, const std::vector<uint32_t>& triangles,
                                   const PlaneChart& chart) {
  auto point = [&](uint32_t i) { return glm::dvec3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]); };
  auto side = [&](uint32_t i) { return glm::dot(point(i) - chart.origin, chart.normal); };
  // Each crossing triangle links the two crossed edges it has.
  std::unordered_map<uint64_t, std::pair<uint64_t, uint64_t>> links;
  std::unordered_map<uint64_t, glm::dvec2> crossing;
  auto link = [&](uint64_t from, uint64_t to) {
    auto [it, inserted] = links.try_emplace(from, to, ~uint64_t(0));
    if (!inserted) it->second.second = to;
  };
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const uint32_t idx[3] = {triangles[t], triangles[t + 1], triangles[t + 2]};
    double s[3];
    bool above[3];
    for (int k = 0; k < 3; ++k) s[k] = side(idx[k]), above[k] = s[k] >= 0.0;
    uint64_t crossed[2];
    int n = 0;
    for (int k = 0; k < 3; ++k) {
      const int a = k, b = (k + 1) % 3;
      if (above[a] == above[b]) continue;
      const uint64_t key = edgeKey(idx[a], idx[b]);
      if (!crossing.count(key)) {
        const double f = s[a] / (s[a] - s[b]);
        crossing[key] = chart.toPlane(point(idx[a]) + f * (point(idx[b]) - point(idx[a])));
      }
      if (n < 2) crossed[n++] = key;
    }
    if (n != 2) continue;
    link(crossed[0], crossed[1]);
    link(crossed[1], crossed[0]);
  }
  std::vector<Polygon2> loops;
  std::unordered_map<uint64_t, bool> visited;
  for (const auto& [start, ends] : links) {
    if (visited[start]) continue;
    Polygon2 loop;
    uint64_t previous = ~uint64_t(0), current = start;
    bool closed = false;
    while (true) {
      visited[current] = true;
      loop.push_back(crossing[current]);
      const auto& [a, b] = links[current];
      const uint64_t next = a != previous ? a : b;
      if (next == ~uint64_t(0)) break;
      if (next == start) {
        closed = true;
        break;
      }
      if (visited[next]) break;
      previous = current;
      current = next;
    }
    if (closed && loop.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

double polygonArea(const Polygon2& polygon) {
  double twice = 0.0;
  for (size_t i = 0, n = polygon.size(); i < n; ++i) {
    const glm::dvec2& a = polygon[i];
    const glm::dvec2& b = polygon[(i + 1) % n];
    twice += a.x * b.y - a.y * b.x;
  }
  return std::abs(0.5 * twice);
}

bool polygonContains(const Polygon2& polygon, const glm::dvec2& p) {
  bool inside = false;
  for (size_t i = 0, n = polygon.size(), j = n - 1; i < n; j = i++) {
    const glm::dvec2& a = polygon[i];
    const glm::dvec2& b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

const Polygon2* loopAround(const std::vector<Polygon2>& loops, const glm::dvec2& point) {
  const Polygon2* best = nullptr;
  double bestArea = 0.0;
  for (const Polygon2& loop : loops) {
    if (!polygonContains(loop, point)) continue;
    const double area = polygonArea(loop);
    if (!best || area < bestArea) best = &loop, bestArea = area;
  }
  return best;
}

double rayExitDistance(const Polygon2& polygon, const glm::dvec2& from, const glm::dvec2& direction) {
  double nearest = -1.0;
  for (size_t i = 0, n = polygon.size(); i < n; ++i) {
    const glm::dvec2 a = polygon[i] - from;
    const glm::dvec2 e = polygon[(i + 1) % n] - polygon[i];
    // from + t direction = polygon[i] + s e
    const double det = direction.x * (-e.y) - direction.y * (-e.x);
    if (std::abs(det) < 1e-300) continue;
    const double t = (a.x * (-e.y) - a.y * (-e.x)) / det;
    const double s = (direction.x * a.y - direction.y * a.x) / det;
    if (t >= 0.0 && s >= 0.0 && s <= 1.0 && (nearest < 0.0 || t < nearest)) nearest = t;
  }
  return nearest;
}

Polygon2 clipToHalfPlane(const Polygon2& polygon, const glm::dvec2& point, const glm::dvec2& direction) {
  Polygon2 out;
  for (size_t i = 0, n = polygon.size(); i < n; ++i) {
    const glm::dvec2& a = polygon[i];
    const glm::dvec2& b = polygon[(i + 1) % n];
    const double sa = glm::dot(a - point, direction), sb = glm::dot(b - point, direction);
    if (sa >= 0.0) out.push_back(a);
    if ((sa >= 0.0) != (sb >= 0.0)) out.push_back(a + (sa / (sa - sb)) * (b - a));
  }
  return out;
}

}  // namespace mq
