#include "core/hair/hair_groom.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include <nlohmann/json.hpp>

#include "core/hair/hairstyle_json.h"
#include "core/hair/strand_tracer.h"
#include "core/math/perlin_noise.h"
#include "core/util/memory_budget.h"
#include "core/util/thread_pool.h"

namespace mq {

namespace {

constexpr float kTwoPi = 6.28318530718f;
constexpr float kMargin = 0.002f;  // hair keeps this far from the proxy surface
constexpr float kScalpPanelDistance = 0.025f;
constexpr uint64_t kChildKey = uint64_t(1) << 32;
constexpr float kPartingSpread = 0.06f;  // guide tips this far apart start to part, metres

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Stateless per-strand random numbers: the same strand gets the same values
// whichever thread grows it.
uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
float random01(uint32_t seed, uint64_t key, uint32_t salt) {
  const uint64_t h = mix64(mix64(key + 0x9E3779B97F4A7C15ull * (seed + 1)) ^ (uint64_t(salt) * 0xD6E8FEB86659FD93ull));
  return float(h >> 40) * (1.0f / 16777216.0f);
}

// A smooth random 3D wander along a strand: a periodic table of random
// vectors, interpolated with a smoothstep. Cheap enough for every point of
// every child.
class Wander {
 public:
  explicit Wander(uint32_t seed) {
    for (size_t i = 0; i < table_.size(); ++i)
      table_[i] = glm::vec3(random01(seed, i, 11), random01(seed, i, 12), random01(seed, i, 13)) * 2.0f - 1.0f;
  }
  glm::vec3 at(float t) const {
    const float f = std::floor(t);
    const int i = int(f) & 255;
    float u = t - f;
    u = u * u * (3.0f - 2.0f * u);
    return glm::mix(table_[i], table_[(i + 1) & 255], u);
  }

 private:
  std::array<glm::vec3, 256> table_;
};

glm::vec3 load(const float* p, int k) { return {p[3 * k], p[3 * k + 1], p[3 * k + 2]}; }
void store(float* p, int k, const glm::vec3& v) {
  p[3 * k] = v.x;
  p[3 * k + 1] = v.y;
  p[3 * k + 2] = v.z;
}

// Hair length per unit of traced centreline: curls and waves make the fibre
// longer than the path it follows.
float fibreStretch(const HairStyle& style) {
  const float curl = style.curlLength > 0.0f ? kTwoPi * style.curlRadius / style.curlLength : 0.0f;
  const float wave = style.waveLength > 0.0f ? kTwoPi * style.waveAmplitude / style.waveLength : 0.0f;
  return std::sqrt(1.0f + curl * curl + 0.5f * wave * wave);
}

// Adds waves, curls and per-strand wander to a traced centreline, in a frame
// carried along it by parallel transport. Phases come from a smooth field
// over the scalp so neighbouring guides curl together and children, which
// blend guides, keep the curls.
struct StrandShaper {
  const HairStyle& style;
  const PerlinNoise& phaseField;
  const Wander& wander;
  const BodyProxy& proxy;

  void apply(float* pts, int points, float segment, const glm::vec3& rootNormal, float length, uint64_t key) const {
    const bool curls = style.curlRadius > 0.0f && style.curlLength > 0.0f;
    const bool waves = style.waveAmplitude > 0.0f && style.waveLength > 0.0f;
    const bool noise = style.strandNoise > 0.0f;
    if (points < 3 || !(curls || waves || noise)) return;
    const glm::vec3 root = load(pts, 0);
    const float phase = kTwoPi * phaseField.noise(root * 25.0f) * 2.0f;
    const float wanderStart = 256.0f * random01(style.seed, key, 3);
    const float fibreSegment = length / float(points - 1);
    glm::vec3 placed = root;
    glm::vec3 original = root, next = load(pts, 1);
    glm::vec3 tangent = glm::normalize(next - original + glm::vec3(1e-9f));
    glm::vec3 normal = rootNormal - glm::dot(rootNormal, tangent) * tangent;
    normal = glm::length(normal) > 1e-6f ? glm::normalize(normal)
                                         : glm::normalize(glm::cross(tangent, glm::vec3(1, 0, 0)) + glm::vec3(1e-6f));
    for (int k = 1; k < points; ++k) {
      const glm::vec3 previous = original;
      original = next;
      next = k + 1 < points ? load(pts, k + 1) : original + (original - previous);
      const glm::vec3 t = next - previous;
      if (glm::dot(t, t) > 1e-18f) tangent = glm::normalize(t);
      normal = normal - glm::dot(normal, tangent) * tangent;
      normal = glm::length(normal) > 1e-6f ? glm::normalize(normal) : normal;
      const glm::vec3 binormal = glm::cross(tangent, normal);
      const float s = float(k) * segment;
      const float ramp = std::min(1.0f, s / 0.03f);  // curls start a few cm from the scalp
      glm::vec3 offset(0.0f);
      if (waves) offset += style.waveAmplitude * ramp * std::sin(kTwoPi * s / style.waveLength + phase) * normal;
      if (curls) {
        const float a = kTwoPi * s / style.curlLength + phase;
        offset += style.curlRadius * ramp * (std::cos(a) * normal + std::sin(a) * binormal);
      }
      if (noise) {
        const float along = s / std::max(length, 1e-6f);
        offset += style.strandNoise * along * std::sqrt(along) * wander.at(wanderStart + 6.0f * along);
      }
      // Follow the leader towards the shaped point, so every segment keeps
      // the fibre's segment length (what the dynamics take as rest length).
      const glm::vec3 target = original + offset;
      const glm::vec3 d = target - placed;
      const float dl = glm::length(d);
      glm::vec3 p = dl > 1e-9f ? placed + d * (fibreSegment / dl) : target;
      if (proxy.pushOut(p, kMargin)) {
        const glm::vec3 slid = p - placed;
        const float sl = glm::length(slid);
        if (sl > 1e-9f) p = placed + slid * (fibreSegment / sl);
        proxy.pushOut(p, kMargin);
      }
      store(pts, k, p);
      placed = p;
    }
  }
};

}  // namespace

HairGroom::HairGroom(ScalpSurface scalp, BodyProxy proxy, int panelCount)
    : scalp_(std::move(scalp)), proxy_(std::move(proxy)) {
  proxy_.updateBounds();
  const SurfacePanels panels = proxy_.makePanels(panelCount);
  std::vector<uint8_t> onScalp(panels.size(), 0);
  const size_t vertices = scalp_.positions.size() / 3;
  for (size_t i = 0; i < panels.size(); ++i) {
    float best = 1e30f;
    glm::vec3 bestNormal(0.0f);
    for (size_t v = 0; v < vertices; ++v) {
      const glm::vec3 d = scalp_.position(v) - panels.centers[i];
      const float d2 = glm::dot(d, d);
      if (d2 < best) {
        best = d2;
        bestNormal = scalp_.normal(v);
      }
    }
    onScalp[i] = best < kScalpPanelDistance * kScalpPanelDistance && glm::dot(bestNormal, panels.normals[i]) > 0.3f;
  }
  flow_.setObstacle(panels, onScalp);
}

// Keeps each child root with the painted density's probability there (the
// same roots for the same paint and seed).
void HairGroom::thinRoots(HairRoots& roots, const std::vector<GroomStroke>& density, uint32_t seed) const {
  HairRoots kept;
  kept.minDistance = roots.minDistance;
  for (size_t i = 0; i < roots.size(); ++i) {
    const float share = paintedValue(density, GroomBrush::PaintDensity, roots.position(i) - proxy_.headCenter(), 1.0f);
    if (share <= random01(seed, i, 21)) continue;
    for (int d = 0; d < 3; ++d) {
      kept.positions.push_back(roots.positions[3 * i + d]);
      kept.normals.push_back(roots.normals[3 * i + d]);
    }
  }
  roots = std::move(kept);
}

void HairGroom::sampleAllRoots(size_t guides, size_t children, const HairStyle& style) {
  const uint32_t seed = style.seed;
  std::vector<GroomStroke> density = strokesOf(style.strokes, GroomBrush::PaintDensity);
  if (sampled_ && guides == sampledGuides_ && children == sampledChildren_ && seed == sampledSeed_ &&
      density == sampledDensity_)
    return;
  auto start = std::chrono::steady_clock::now();
  guideRoots_ = sampleRoots(scalp_, guides, seed);
  childRoots_ = sampleRoots(scalp_, children, seed ^ 0x5bd1e995u);
  if (!density.empty()) thinRoots(childRoots_, density, seed);
  for (HairRoots* roots : {&guideRoots_, &childRoots_})
    for (size_t i = 0; i < roots->size(); ++i) {
      glm::vec3 p = roots->position(i);
      if (proxy_.pushOut(p, 0.0f))
        for (int d = 0; d < 3; ++d) roots->positions[3 * i + d] = p[d];
    }
  findGuideNeighbours();
  tracedKey_.clear();
  sampledGuides_ = guides;
  sampledChildren_ = children;
  sampledSeed_ = seed;
  sampledDensity_ = std::move(density);
  sampled_ = true;
  timings_.roots = secondsSince(start);
}

// Three nearest guide roots of every child root, through a uniform grid.
void HairGroom::findGuideNeighbours() {
  const size_t children = childRoots_.size(), guides = guideRoots_.size();
  neighbours_.assign(3 * children, 0);
  weights_.assign(3 * children, 0.0f);
  if (guides == 0) return;
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (size_t g = 0; g < guides; ++g) {
    lo = glm::min(lo, guideRoots_.position(g));
    hi = glm::max(hi, guideRoots_.position(g));
  }
  const float cell = std::max(2.0f * guideRoots_.minDistance, 1e-4f);
  const glm::ivec3 dims = glm::clamp(glm::ivec3((hi - lo) / cell) + 1, glm::ivec3(1), glm::ivec3(256));
  auto cellOf = [&](const glm::vec3& p) { return glm::clamp(glm::ivec3((p - lo) / cell), glm::ivec3(0), dims - 1); };
  std::vector<int> start(size_t(dims.x) * dims.y * dims.z + 1, 0), order(guides);
  auto flat = [&](const glm::ivec3& c) { return (size_t(c.z) * dims.y + c.y) * dims.x + c.x; };
  for (size_t g = 0; g < guides; ++g) ++start[flat(cellOf(guideRoots_.position(g))) + 1];
  for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (size_t g = 0; g < guides; ++g) order[fill[flat(cellOf(guideRoots_.position(g)))]++] = int(g);

  ThreadPool::shared().parallelFor(0, children, 256, [&](size_t begin, size_t end) {
    for (size_t c = begin; c < end; ++c) {
      const glm::vec3 p = childRoots_.position(c);
      const glm::ivec3 home = cellOf(p);
      std::array<float, 3> bestD{1e30f, 1e30f, 1e30f};
      std::array<int, 3> best{0, 0, 0};
      const int want = int(std::min<size_t>(3, guides));
      for (int ring = 1; ring < 256; ++ring) {
        const glm::ivec3 a = glm::max(home - ring, glm::ivec3(0)), b = glm::min(home + ring, dims - 1);
        for (int z = a.z; z <= b.z; ++z)
          for (int y = a.y; y <= b.y; ++y)
            for (int x = a.x; x <= b.x; ++x) {
              const glm::ivec3 q(x, y, z);
              if (ring > 1 && glm::all(glm::lessThan(glm::abs(q - home), glm::ivec3(ring)))) continue;  // seen
              const size_t f = flat(q);
              for (int k = start[f]; k < start[f + 1]; ++k) {
                const glm::vec3 d = guideRoots_.position(order[k]) - p;
                float d2 = glm::dot(d, d);
                int g = order[k];
                for (int s = 0; s < 3; ++s)
                  if (d2 < bestD[s]) {
                    std::swap(d2, bestD[s]);
                    std::swap(g, best[s]);
                  }
              }
            }
        const bool coveredAll = glm::all(glm::equal(a, glm::ivec3(0))) && glm::all(glm::equal(b, dims - 1));
        if (bestD[want - 1] <= float(ring * ring) * cell * cell || coveredAll) break;
      }
      float sum = 0.0f;
      for (int s = 0; s < 3; ++s) {
        const float w = s < want ? 1.0f / (bestD[s] + 1e-8f) : 0.0f;
        neighbours_[3 * c + s] = best[s];
        weights_[3 * c + s] = w;
        sum += w;
      }
      for (int s = 0; s < 3; ++s) weights_[3 * c + s] /= sum;
    }
  });
}

float HairGroom::strandLength(const HairStyle& style, const glm::vec3& root, uint64_t key) const {
  float scale = 1.0f;
  for (const LengthPoint& lp : style.lengthMap) {
    const glm::vec3 d = root - (proxy_.headCenter() + lp.position);
    scale += (lp.scale - 1.0f) * std::exp(-glm::dot(d, d) / std::max(lp.radius * lp.radius, 1e-8f));
  }
  scale *= paintedValue(style.strokes, GroomBrush::PaintLength, root - proxy_.headCenter(), 1.0f);
  const float variation = 1.0f + style.lengthVariation * (2.0f * random01(style.seed, key, 1) - 1.0f);
  return std::max(0.005f, style.length * std::max(scale, 0.05f) * variation);
}

void HairGroom::grow(const HairStyle& style, size_t strandCount) {
  size_t total = strandCount;
  if (total == 0) total = rootCountForDensity(scalp_, style.density, size_t(std::max(0, style.maxStrands)));
  total = std::min(total, kMaxStrands);
  // Positions, rest shape, velocities and the children's frames: about 64
  // bytes a point over the groom and its dynamics.
  checkMemoryBudget(
      "hair: " + std::to_string(total) + " strands of " + std::to_string(style.pointsPerStrand) + " points",
      64.0 * double(total) * style.pointsPerStrand);
  const size_t guides = std::min(total, size_t(std::max(1, style.guideCount)));
  sampleAllRoots(guides, total - guides, style);
  regrowGuides(style);
  growChildren(style);
}

void HairGroom::regrowGuides(const HairStyle& style) {
  const auto start = std::chrono::steady_clock::now();
  const size_t guides = guideRoots_.size(), total = guides + childRoots_.size();
  const int points = std::max(2, style.pointsPerStrand);
  // The traced guides depend on everything but the strokes, except the
  // painted length map (it changes their lengths), and the dynamics.
  HairStyle unbrushed = style;
  unbrushed.dynamics = {};
  std::erase_if(unbrushed.strokes, [](const GroomStroke& s) { return s.brush != GroomBrush::PaintLength; });
  const std::string key = toJson(unbrushed).dump();
  if (key != tracedKey_ || strands_.points.size() != 3 * total * points) {
    traceGuides(style);
    tracedGuides_.assign(strands_.points.begin(), strands_.points.begin() + 3 * guides * points);
    tracedKey_ = key;
    brushedStrokes_.clear();
    brushedGuides_ = tracedGuides_;
  }
  // Start from the cached strokes when the style begins with them.
  const std::vector<GroomStroke>& strokes = style.strokes;
  const size_t cached = brushedStrokes_.size();
  const bool prefix =
      cached <= strokes.size() && std::equal(brushedStrokes_.begin(), brushedStrokes_.end(), strokes.begin());
  const size_t settled = strokes.empty() ? 0 : strokes.size() - 1;
  size_t from = 0;
  if (prefix && cached <= settled) {
    std::copy(brushedGuides_.begin(), brushedGuides_.end(), strands_.points.begin());
    from = cached;
  } else {
    std::copy(tracedGuides_.begin(), tracedGuides_.end(), strands_.points.begin());
  }
  const glm::vec3 center = proxy_.headCenter();
  applyGroomStrokes(strokes, from, settled, center, proxy_, kMargin, style.seed, strands_, guides);
  if (from != settled || brushedStrokes_.size() != settled) {
    brushedGuides_.assign(strands_.points.begin(), strands_.points.begin() + 3 * guides * points);
    brushedStrokes_.assign(strokes.begin(), strokes.begin() + settled);
  }
  applyGroomStrokes(strokes, settled, strokes.size(), center, proxy_, kMargin, style.seed, strands_, guides);
  paintPigments(style, 0, guides);
  timings_.guides = secondsSince(start);
}

void HairGroom::paintPigments(const HairStyle& style, size_t first, size_t end) {
  const bool painted = std::any_of(style.strokes.begin(), style.strokes.end(), [](const GroomStroke& s) {
    return s.brush == GroomBrush::PaintMelanin || s.brush == GroomBrush::PaintPheomelanin;
  });
  if (!painted) {
    strands_.pigmentPaint.clear();
    return;
  }
  const size_t guides = guideRoots_.size();
  const size_t total = guides + childRoots_.size();
  if (strands_.pigmentPaint.size() != 4 * total) {  // the style's until computed
    strands_.pigmentPaint.clear();
    for (size_t s = 0; s < total; ++s)
      strands_.pigmentPaint.insert(strands_.pigmentPaint.end(), {1.0f, 0.0f, 1.0f, 0.0f});
  }
  const std::vector<GroomStroke> eumelanin = strokesOf(style.strokes, GroomBrush::PaintMelanin);
  const std::vector<GroomStroke> pheomelanin = strokesOf(style.strokes, GroomBrush::PaintPheomelanin);
  ThreadPool::shared().parallelFor(first, end, 256, [&](size_t begin, size_t stop) {
    for (size_t s = begin; s < stop; ++s) {
      const glm::vec3 at =
          (s < guides ? guideRoots_.position(s) : childRoots_.position(s - guides)) - proxy_.headCenter();
      const PaintedShare eu = paintedShare(eumelanin, GroomBrush::PaintMelanin, at);
      const PaintedShare pheo = paintedShare(pheomelanin, GroomBrush::PaintPheomelanin, at);
      float* out = &strands_.pigmentPaint[4 * s];
      out[0] = eu.keep, out[1] = eu.add, out[2] = pheo.keep, out[3] = pheo.add;
    }
  });
}

void HairGroom::traceGuides(const HairStyle& style) {
  flow_.setPrimitives(style.primitives, proxy_.headCenter(), style.scalpOutflow);
  flow_.setNoise(style.seed, style.noiseAmplitude, style.noiseScale);
  const int points = std::max(2, style.pointsPerStrand);
  const size_t guides = guideRoots_.size(), total = guides + childRoots_.size();
  strands_.pointsPerStrand = points;
  strands_.points.resize(3 * total * points);
  strands_.rootNormals.resize(3 * total);
  strands_.guideOf.resize(total);
  guideLengths_.resize(guides);
  const float stretch = fibreStretch(style);
  const PerlinNoise phaseField(style.seed + 7);
  const Wander wander(style.seed);
  const StrandShaper shaper{style, phaseField, wander, proxy_};
  TraceOptions options;
  options.margin = kMargin;
  ThreadPool::shared().parallelFor(0, guides, 8, [&](size_t begin, size_t end) {
    for (size_t g = begin; g < end; ++g) {
      const glm::vec3 root = guideRoots_.position(g), normal = guideRoots_.normal(g);
      const float length = strandLength(style, root, g);
      guideLengths_[g] = length;
      float* pts = strands_.strand(g);
      traceStreamline(flow_, proxy_, root, normal, length / stretch, points, options, pts);
      shaper.apply(pts, points, length / stretch / float(points - 1), normal, length, g);
      for (int d = 0; d < 3; ++d) strands_.rootNormals[3 * g + d] = normal[d];
      strands_.guideOf[g] = -1;
    }
  });
}

void HairGroom::growChildren(const HairStyle& style) {
  const auto start = std::chrono::steady_clock::now();
  const int points = strands_.pointsPerStrand;
  const size_t guides = guideRoots_.size(), children = childRoots_.size();
  std::vector<float> clumpAt(points), frizzAt(points);
  for (int k = 0; k < points; ++k) {
    const float t = points > 1 ? float(k) / float(points - 1) : 0.0f;
    clumpAt[k] = std::pow(t, std::max(style.clumpShape, 0.01f));  // times the clumping
    frizzAt[k] = style.frizz * t;
  }
  const Wander wander(style.seed ^ 0xA5A5A5u);
  ThreadPool::shared().parallelFor(0, children, 64, [&](size_t begin, size_t end) {
    for (size_t c = begin; c < end; ++c) {
      const size_t s = guides + c;
      const uint64_t key = kChildKey + c;
      const glm::vec3 root = childRoots_.position(c);
      const int32_t* near = &neighbours_[3 * c];
      const float* g0 = strands_.strand(near[0]);
      const float* g1 = strands_.strand(near[1]);
      const float* g2 = strands_.strand(near[2]);
      // Where neighbouring guides part (left and right of a parting, either
      // side of the face), a blend of them would cut across the gap: follow
      // the nearest guide alone there.
      const int last = points - 1;
      const float spread = std::max({glm::length(load(g0, last) - load(g1, last)) * float(weights_[3 * c + 1] > 0.0f),
                                     glm::length(load(g0, last) - load(g2, last)) * float(weights_[3 * c + 2] > 0.0f)});
      const float alone = std::clamp((spread - kPartingSpread) / kPartingSpread, 0.0f, 1.0f);
      const float w[3] = {weights_[3 * c] + alone * (1.0f - weights_[3 * c]), (1.0f - alone) * weights_[3 * c + 1],
                          (1.0f - alone) * weights_[3 * c + 2]};
      const float guideLength =
          w[0] * guideLengths_[near[0]] + w[1] * guideLengths_[near[1]] + w[2] * guideLengths_[near[2]];
      const float ratio = strandLength(style, root, key) / std::max(guideLength, 1e-6f);
      const float wanderStart = 256.0f * random01(style.seed, key, 5);
      const float clumping =
          std::clamp(paintedValue(style.strokes, GroomBrush::PaintClumping, root - proxy_.headCenter(),
                                  unpaintedValue(style, GroomBrush::PaintClumping)),
                     0.0f, 1.0f);
      const float wanderRate = style.frizzFrequency * guideLength * ratio / float(std::max(1, points - 1));
      float* out = strands_.strand(s);
      const glm::vec3 r0 = load(g0, 0), r1 = load(g1, 0), r2 = load(g2, 0);
      store(out, 0, root);
      for (int k = 1; k < points; ++k) {
        const glm::vec3 a = load(g0, k);
        const glm::vec3 offset = w[0] * (a - r0) + w[1] * (load(g1, k) - r1) + w[2] * (load(g2, k) - r2);
        glm::vec3 p = root + ratio * offset;
        p += clumping * clumpAt[k] * (a - p);
        p += frizzAt[k] * wander.at(wanderStart + wanderRate * float(k));
        proxy_.pushOut(p, kMargin);
        store(out, k, p);
      }
      for (int d = 0; d < 3; ++d) strands_.rootNormals[3 * s + d] = childRoots_.normals[3 * c + d];
      strands_.guideOf[s] = near[0];
    }
  });
  paintPigments(style, guides, guides + children);
  timings_.children = secondsSince(start);
}

size_t HairGroom::countPointsInside() const {
  size_t inside = 0;
  const size_t n = strands_.points.size() / 3;
  for (size_t i = 0; i < n; ++i)
    inside += proxy_.contains({strands_.points[3 * i], strands_.points[3 * i + 1], strands_.points[3 * i + 2]}, 0.0f);
  return inside;
}

}  // namespace mq
