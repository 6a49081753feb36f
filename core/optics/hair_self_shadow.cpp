#include "core/optics/hair_self_shadow.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/util/thread_pool.h"

namespace mq::optics {

namespace {

glm::vec3 load(const std::vector<float>& a, size_t i) { return {a[3 * i], a[3 * i + 1], a[3 * i + 2]}; }

// Light-aligned frame: w toward the light, (u, v) across its rays.
struct LightFrame {
  glm::vec3 u, v, w;
};
LightFrame lightFrame(const glm::vec3& towardLight) {
  const glm::vec3 w = glm::normalize(towardLight);
  const glm::vec3 helper = std::abs(w.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 u = glm::normalize(glm::cross(helper, w));
  return {u, glm::cross(w, u), w};
}

// The strand points in the light's frame: (u, v) across its rays and z the
// depth along it (`depthSign` +1: toward the light; -1: away from it), their
// bounds, and the strands' mean segment length.
struct LightView {
  std::vector<glm::vec3> projected;
  glm::vec3 lo{1e30f}, hi{-1e30f};
  float segment = 0.0f;
};
LightView viewFromLight(const Strands& strands, const glm::vec3& towardLight, float depthSign) {
  const size_t count = strands.points.size() / 3;
  const int n = strands.pointsPerStrand;
  const auto [u, v, w] = lightFrame(towardLight);
  LightView view;
  view.projected.resize(count);
  double segmentSum = 0.0;
  for (size_t k = 0; k < count; ++k) {
    const glm::vec3 p = load(strands.points, k);
    view.projected[k] = {glm::dot(p, u), glm::dot(p, v), depthSign * glm::dot(p, w)};
    view.lo = glm::min(view.lo, view.projected[k]);
    view.hi = glm::max(view.hi, view.projected[k]);
    if (k % n != 0) segmentSum += glm::length(p - load(strands.points, k - 1));
  }
  view.segment = float(segmentSum / double(count - count / n));
  return view;
}

}  // namespace

std::vector<float> hairSelfShadow(const Strands& strands, const glm::vec3& towardLight,
                                  const HairShadowSettings& settings) {
  return settings.method == HairShadowMethod::OpacityMaps ? hairShadowByOpacityMaps(strands, towardLight, settings)
                                                          : hairShadowByPointCount(strands, towardLight, settings);
}

std::vector<float> hairShadowByPointCount(const Strands& strands, const glm::vec3& towardLight,
                                          const HairShadowSettings& settings) {
  const size_t count = strands.points.size() / 3;
  std::vector<float> shadow(count, 1.0f);
  const int n = strands.pointsPerStrand;
  if (count == 0 || n < 2) return shadow;
  const LightView view = viewFromLight(strands, towardLight, 1.0f);  // z: depth toward the light
  const std::vector<glm::vec3>& projected = view.projected;
  const glm::vec2 lo(view.lo), hi(view.hi);
  const float segment = view.segment;
  float cell = std::max(settings.cellSize, 1e-4f);
  const glm::vec2 extent = hi - lo;
  cell = std::max(cell, std::max(extent.x, extent.y) / 1024.0f);  // at most 1024 x 1024 columns
  const int columns = int(extent.x / cell) + 2, rows = int(extent.y / cell) + 2;

  // Counting sort of the points into columns, then each column by depth.
  std::vector<uint32_t> start(size_t(columns) * rows + 1, 0);
  auto columnOf = [&](float a, float b) {
    return size_t(int((b - lo.y) / cell)) * columns + size_t(int((a - lo.x) / cell));
  };
  for (size_t k = 0; k < count; ++k) ++start[columnOf(projected[k].x, projected[k].y) + 1];
  for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<float> depths(count);
  {
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t k = 0; k < count; ++k) depths[fill[columnOf(projected[k].x, projected[k].y)]++] = projected[k].z;
  }
  ThreadPool::shared().parallelFor(0, start.size() - 1, 1024, [&](size_t begin, size_t end) {
    for (size_t c = begin; c < end; ++c) std::sort(depths.begin() + start[c], depths.begin() + start[c + 1]);
  });

  // Points nearer the light than depth d in column (i, j).
  auto aheadIn = [&](int i, int j, float d) -> float {
    if (i < 0 || j < 0 || i >= columns || j >= rows) return 0.0f;
    const size_t c = size_t(j) * columns + size_t(i);
    const auto first = depths.begin() + start[c], last = depths.begin() + start[c + 1];
    return float(last - std::upper_bound(first, last, d + 1e-6f));
  };
  // A strand crossing a column leaves about cell / segment points in it.
  const float crossingsPerPoint = segment / cell;
  ThreadPool::shared().parallelFor(0, count, 4096, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      // Bilinear over the four nearest column centres: no blocky edges.
      const float a = (projected[k].x - lo.x) / cell - 0.5f, b = (projected[k].y - lo.y) / cell - 0.5f;
      const int i = int(std::floor(a)), j = int(std::floor(b));
      const float fa = a - float(i), fb = b - float(j);
      const float d = projected[k].z;
      const float ahead = (1 - fa) * (1 - fb) * aheadIn(i, j, d) + fa * (1 - fb) * aheadIn(i + 1, j, d) +
                          (1 - fa) * fb * aheadIn(i, j + 1, d) + fa * fb * aheadIn(i + 1, j + 1, d);
      const float transmitted = std::exp(-settings.perStrand * crossingsPerPoint * ahead);
      shadow[k] = std::max(settings.minShadow, transmitted);
    }
  });
  return shadow;
}

// Opacity shadow maps (Kim and Neumann, "Opacity Shadow Maps", 2001): the
// hair's depth range along the light is cut by `slices` maps; each point's
// density is splatted (bilinearly across the light's rays) into the slab
// between the two maps around it, a prefix sum along the light turns slabs
// into the opacity in front of each map, and a vertex reads the opacity in
// front of it by interpolating its two maps in depth and across the rays.
std::vector<float> hairShadowByOpacityMaps(const Strands& strands, const glm::vec3& towardLight,
                                           const HairShadowSettings& settings) {
  const size_t count = strands.points.size() / 3;
  std::vector<float> shadow(count, 1.0f);
  const int n = strands.pointsPerStrand;
  if (count == 0 || n < 2) return shadow;
  const LightView view = viewFromLight(strands, towardLight, -1.0f);  // z: away from the light
  const std::vector<glm::vec3>& projected = view.projected;
  const glm::vec3 lo = view.lo, hi = view.hi;
  const float segment = view.segment;
  const glm::vec2 extent = glm::vec2(hi) - glm::vec2(lo);
  const float cell = std::max({settings.cellSize, 1e-4f, std::max(extent.x, extent.y) / 384.0f});
  const int columns = int(extent.x / cell) + 2, rows = int(extent.y / cell) + 2;
  const int slices = std::clamp(settings.opacityMapCount, 2, 256);
  const float depthRange = std::max(hi.z - lo.z, 1e-6f);
  const float slab = depthRange / float(slices - 1);
  const size_t pixels = size_t(columns) * rows;

  // Map coordinates: (a, b) in pixels from the first pixel centre, s in slabs.
  struct Sample {
    int i, j, slice;
    float fa, fb, fs;
  };
  auto sampleOf = [&](const glm::vec3& q) {
    const float a = (q.x - lo.x) / cell - 0.5f, b = (q.y - lo.y) / cell - 0.5f, s = (q.z - lo.z) / slab;
    Sample m{int(std::floor(a)), int(std::floor(b)), std::min(int(s), slices - 2), 0, 0, 0};
    m.fa = a - float(m.i);
    m.fb = b - float(m.j);
    m.fs = std::clamp(s - float(m.slice), 0.0f, 1.0f);
    return m;
  };
  auto pixelIndex = [&](int i, int j) -> long {
    return i < 0 || j < 0 || i >= columns || j >= rows ? -1 : long(j) * columns + i;
  };

  // Slab densities: maps[slice * pixels + pixel] holds the points between
  // map `slice` and map `slice + 1`; after the prefix sum, the points in
  // front of map `slice`.
  std::vector<float> maps(size_t(slices) * pixels, 0.0f);
  for (size_t k = 0; k < count; ++k) {
    const Sample m = sampleOf(projected[k]);
    const float weights[4] = {(1 - m.fa) * (1 - m.fb), m.fa * (1 - m.fb), (1 - m.fa) * m.fb, m.fa * m.fb};
    const long corners[4] = {pixelIndex(m.i, m.j), pixelIndex(m.i + 1, m.j), pixelIndex(m.i, m.j + 1),
                             pixelIndex(m.i + 1, m.j + 1)};
    for (int c = 0; c < 4; ++c)
      if (corners[c] >= 0) maps[size_t(m.slice) * pixels + size_t(corners[c])] += weights[c];
  }
  ThreadPool::shared().parallelFor(0, pixels, 4096, [&](size_t begin, size_t end) {
    for (size_t p = begin; p < end; ++p) {
      float ahead = 0.0f;
      for (int s = 0; s < slices; ++s) {
        const float inSlab = maps[size_t(s) * pixels + p];
        maps[size_t(s) * pixels + p] = ahead;
        ahead += inSlab;
      }
    }
  });

  const float crossingsPerPoint = segment / cell;
  ThreadPool::shared().parallelFor(0, count, 4096, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      const Sample m = sampleOf(projected[k]);
      auto opacity = [&](int i, int j) {
        const long p = pixelIndex(i, j);
        if (p < 0) return 0.0f;
        return (1 - m.fs) * maps[size_t(m.slice) * pixels + size_t(p)] +
               m.fs * maps[size_t(m.slice + 1) * pixels + size_t(p)];
      };
      const float ahead = (1 - m.fa) * (1 - m.fb) * opacity(m.i, m.j) + m.fa * (1 - m.fb) * opacity(m.i + 1, m.j) +
                          (1 - m.fa) * m.fb * opacity(m.i, m.j + 1) + m.fa * m.fb * opacity(m.i + 1, m.j + 1);
      // The interpolation counts part of the vertex's own slab, itself
      // included: take its own share out (the exact count excludes it).
      const float own =
          m.fs * ((1 - m.fa) * (1 - m.fa) * (1 - m.fb) * (1 - m.fb) + m.fa * m.fa * (1 - m.fb) * (1 - m.fb) +
                  (1 - m.fa) * (1 - m.fa) * m.fb * m.fb + m.fa * m.fa * m.fb * m.fb);
      const float transmitted = std::exp(-settings.perStrand * crossingsPerPoint * std::max(0.0f, ahead - own));
      shadow[k] = std::max(settings.minShadow, transmitted);
    }
  });
  return shadow;
}

}  // namespace mq::optics
