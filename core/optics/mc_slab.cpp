#include "core/optics/mc_slab.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <thread>

#include <glm/glm.hpp>

#include "core/optics/fresnel.h"
#include "core/optics/phase.h"

namespace mq::optics {

namespace {

constexpr std::int64_t kPathsPerBlock = 2048;

std::uint64_t splitMix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }  // [0, 1)

 private:
  std::mt19937_64 engine_;
};

// dir turned by the scattering angle psi (cos given) about itself, at a
// uniform azimuth.
glm::dvec3 scatterDirection(const glm::dvec3& dir, double cosPsi, double azimuth) {
  const double sinPsi = std::sqrt(std::max(0.0, 1.0 - cosPsi * cosPsi));
  const double cosPhi = std::cos(azimuth), sinPhi = std::sin(azimuth);
  if (std::abs(dir.z) > 0.99999) return {sinPsi * cosPhi, sinPsi * sinPhi, dir.z > 0.0 ? cosPsi : -cosPsi};
  const double lateral = std::sqrt(1.0 - dir.z * dir.z);
  const glm::dvec3 turned(sinPsi * (dir.x * dir.z * cosPhi - dir.y * sinPhi) / lateral + dir.x * cosPsi,
                          sinPsi * (dir.y * dir.z * cosPhi + dir.x * sinPhi) / lateral + dir.y * cosPsi,
                          -sinPsi * cosPhi * lateral + dir.z * cosPsi);
  return glm::normalize(turned);
}

// Crossing a boundary parallel to the surface from index n1 into n2:
// returns false (and mirrors dir) when the photon is reflected.
bool crossBoundary(glm::dvec3& dir, double n1, double n2, Random& random) {
  if (n1 == n2) return true;
  const double eta = n2 / n1;
  const double cosIncident = std::abs(dir.z);
  if (random.uniform() < fresnelDielectric(cosIncident, eta)) {
    dir.z = -dir.z;
    return false;
  }
  const double cosRefracted = refractedCos(cosIncident, eta);
  dir = {dir.x / eta, dir.y / eta, std::copysign(cosRefracted, dir.z)};
  return true;
}

struct Slab {
  std::vector<SlabLayer> layers;
  std::vector<double> tops, bottoms;
};

Slab stackLayers(const std::vector<SlabLayer>& layers) {
  Slab slab{layers, {}, {}};
  double depth = 0.0;
  for (const SlabLayer& layer : layers) {
    slab.tops.push_back(depth);
    depth += layer.thickness;
    slab.bottoms.push_back(depth);
  }
  return slab;
}

glm::dvec3 incidentDirection(const SlabSettings& settings, Random& random) {
  if (settings.diffuseIncidence) {
    const double cosTheta = std::sqrt(random.uniform());
    const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
    const double azimuth = 2.0 * std::numbers::pi * random.uniform();
    return {sinTheta * std::cos(azimuth), sinTheta * std::sin(azimuth), cosTheta};
  }
  const double c = settings.cosIncidence;
  return {std::sqrt(std::max(0.0, 1.0 - c * c)), 0.0, c};
}

void recordReflection(SlabResult& result, const SlabSettings& settings, const glm::dvec3& position,
                      const glm::dvec3& dir, std::int64_t events) {
  ++result.reflected;
  const double radius = std::hypot(position.x, position.y);
  const auto annulus = std::int64_t(radius / settings.annulusWidth);
  if (annulus < settings.annulusCount) ++result.annuli[annulus];
  ++result.orders[std::min<std::int64_t>(events, settings.maxOrder - 1)];
  if (events == 1) {
    const int bin = std::min(int(std::abs(dir.z) * settings.angularBins), settings.angularBins - 1);
    ++result.singleScatterBins[bin];
  }
}

void tracePath(const Slab& slab, const SlabSettings& settings, Random& random, SlabResult& result) {
  glm::dvec3 dir = incidentDirection(settings, random);
  glm::dvec3 position(0.0);
  if (!crossBoundary(dir, settings.indexAbove, slab.layers[0].index, random)) {
    ++result.specular;
    return;
  }
  const int layerCount = int(slab.layers.size());
  int layer = 0;
  std::int64_t events = 0;
  for (;;) {
    const SlabLayer& medium = slab.layers[layer];
    const double sigmaT = medium.sigmaA + medium.sigmaS;
    const double freePath =
        sigmaT > 0.0 ? -std::log1p(-random.uniform()) / sigmaT : std::numeric_limits<double>::infinity();
    double toBoundary = std::numeric_limits<double>::infinity();
    if (dir.z > 0.0) toBoundary = (slab.bottoms[layer] - position.z) / dir.z;
    if (dir.z < 0.0) toBoundary = (slab.tops[layer] - position.z) / dir.z;

    if (freePath < toBoundary) {
      position += freePath * dir;
      if (random.uniform() * sigmaT >= medium.sigmaS) {
        ++result.absorbed;
        return;
      }
      if (++events > settings.maxEventsPerPath) {
        ++result.abandoned;
        return;
      }
      const double cosPsi = sampleHenyeyGreenstein(medium.g, random.uniform());
      dir = scatterDirection(dir, cosPsi, 2.0 * std::numbers::pi * random.uniform());
      continue;
    }

    position += toBoundary * dir;
    const bool goingUp = dir.z < 0.0;
    position.z = goingUp ? slab.tops[layer] : slab.bottoms[layer];
    const int next = goingUp ? layer - 1 : layer + 1;
    const double nextIndex = next < 0             ? settings.indexAbove
                             : next >= layerCount ? settings.indexBelow
                                                  : slab.layers[next].index;
    if (!crossBoundary(dir, medium.index, nextIndex, random)) continue;
    if (next < 0) {
      recordReflection(result, settings, position, dir, events);
      return;
    }
    if (next >= layerCount) {
      ++result.transmitted;
      return;
    }
    layer = next;
  }
}

SlabResult emptyResult(const SlabSettings& settings) {
  SlabResult result;
  result.annuli.assign(settings.annulusCount, 0);
  result.singleScatterBins.assign(settings.angularBins, 0);
  result.orders.assign(settings.maxOrder, 0);
  return result;
}

void addCounts(SlabResult& total, const SlabResult& part) {
  total.paths += part.paths;
  total.specular += part.specular;
  total.reflected += part.reflected;
  total.transmitted += part.transmitted;
  total.absorbed += part.absorbed;
  total.abandoned += part.abandoned;
  for (size_t i = 0; i < total.annuli.size(); ++i) total.annuli[i] += part.annuli[i];
  for (size_t i = 0; i < total.singleScatterBins.size(); ++i) total.singleScatterBins[i] += part.singleScatterBins[i];
  for (size_t i = 0; i < total.orders.size(); ++i) total.orders[i] += part.orders[i];
}

}  // namespace

SlabResult simulateSlab(const std::vector<SlabLayer>& layers, const SlabSettings& settings) {
  const Slab slab = stackLayers(layers);
  const std::int64_t blocks = (settings.paths + kPathsPerBlock - 1) / kPathsPerBlock;
  const int threads = std::max(1, std::min<int>(settings.threads, int(blocks)));

  // Thread t traces blocks t, t + threads, ...; counts are integers, so the
  // sum does not depend on which thread traced which block.
  std::vector<SlabResult> perThread(threads, emptyResult(settings));
  auto work = [&](int thread) {
    SlabResult& result = perThread[thread];
    for (std::int64_t block = thread; block < blocks; block += threads) {
      Random random(splitMix64(settings.seed ^ splitMix64(std::uint64_t(block))));
      const std::int64_t begin = block * kPathsPerBlock;
      const std::int64_t end = std::min(settings.paths, begin + kPathsPerBlock);
      for (std::int64_t path = begin; path < end; ++path) tracePath(slab, settings, random, result);
      result.paths += end - begin;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& t : pool) t.join();

  SlabResult total = emptyResult(settings);
  for (const SlabResult& part : perThread) addCounts(total, part);
  return total;
}

}  // namespace mq::optics
