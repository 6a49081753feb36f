#include "core/hair/groom_stroke.h"

#include <algorithm>
#include <cmath>

#include "core/hair/body_proxy.h"
#include "core/hair/strands.h"
#include "core/util/error.h"
#include "core/util/thread_pool.h"

namespace mq {

namespace {

// Per-dab rates (see the header): how far one dab goes.
constexpr float kLengthRate = 0.15f;  // length changes by up to 15 %
constexpr float kPuffRate = 0.3f;     // segment directions turn this share towards the root normal
constexpr float kSmoothRate = 0.6f;   // share of the turn towards the local chord
constexpr float kClumpRate = 0.5f;    // share of the way to the clump's centre line
constexpr float kFrizzRate = 0.15f;   // random offsets of this share of the radius
constexpr float kMinLength = 0.005f;  // metres, as the groom's shortest strand

glm::vec3 load(const float* p, int k) { return {p[3 * k], p[3 * k + 1], p[3 * k + 2]}; }
void store(float* p, int k, const glm::vec3& v) {
  p[3 * k] = v.x;
  p[3 * k + 1] = v.y;
  p[3 * k + 2] = v.z;
}

float falloff(const glm::vec3& p, const glm::vec3& center, float radius) {
  const glm::vec3 d = p - center;
  const float q = glm::dot(d, d) / (radius * radius);
  return q < 1.0f ? (1.0f - q) * (1.0f - q) : 0.0f;
}

uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
// In -1..1, the same for the same key on any thread.
float signedRandom(uint64_t key) {
  return float(mix64(key * 0x9E3779B97F4A7C15ull) >> 40) * (2.0f / 16777216.0f) - 1.0f;
}

// One strand while a dab works on it: its points and segment lengths.
class StrandEdit {
 public:
  StrandEdit(float* points, int count, const BodyProxy& proxy, float margin)
      : p_(points), n_(count), proxy_(proxy), margin_(margin), lengths_(size_t(std::max(count - 1, 0))) {
    for (int k = 1; k < n_; ++k) lengths_[k - 1] = glm::length(at(k) - at(k - 1));
  }
  int count() const { return n_; }
  glm::vec3 at(int k) const { return load(p_, k); }
  void set(int k, const glm::vec3& v) { store(p_, k, v); }
  float t(int k) const { return n_ > 1 ? float(k) / float(n_ - 1) : 0.0f; }
  float length() const {
    float sum = 0.0f;
    for (float l : lengths_) sum += l;
    return sum;
  }

  // Follow the leader from the root: every segment back to its length, in
  // the direction the edit gave it, and out of the body.
  void restoreLengths() {
    for (int k = 1; k < n_; ++k) place(k, at(k) - at(k - 1), lengths_[k - 1]);
  }
  // The strand rebuilt from its root with these segment directions.
  void rebuild(const std::vector<glm::vec3>& directions) {
    for (int k = 1; k < n_; ++k) place(k, directions[k - 1], lengths_[k - 1]);
  }
  // Resampled to `length` along itself (past its end: straight on).
  void resample(float length) {
    std::vector<glm::vec3> old(n_);
    for (int k = 0; k < n_; ++k) old[k] = at(k);
    const float step = length / float(n_ - 1);
    int segment = 0;
    float segmentStart = 0.0f;
    for (int k = 1; k < n_; ++k) {
      const float s = step * float(k);
      while (segment < n_ - 2 && segmentStart + lengths_[segment] < s) segmentStart += lengths_[segment++];
      const float l = lengths_[segment];
      const glm::vec3 a = old[segment], b = old[segment + 1];
      const glm::vec3 p = l > 1e-9f ? a + (b - a) * ((s - segmentStart) / l) : b;
      set(k, p);
    }
    std::fill(lengths_.begin(), lengths_.end(), step);
    restoreLengths();
  }

 private:
  void place(int k, const glm::vec3& direction, float length) {
    const glm::vec3 previous = at(k - 1);
    const float dl = glm::length(direction);
    glm::vec3 p = dl > 1e-12f ? previous + direction * (length / dl) : at(k);
    if (proxy_.pushOut(p, margin_)) {
      const glm::vec3 slid = p - previous;
      const float sl = glm::length(slid);
      if (sl > 1e-9f) p = previous + slid * (length / sl);
      proxy_.pushOut(p, margin_);
    }
    set(k, p);
  }

  float* p_;
  int n_;
  const BodyProxy& proxy_;
  float margin_;
  std::vector<float> lengths_;
};

struct Dab {
  glm::vec3 center, motion;
  float radius, strength;
  GroomBrush brush;
  uint64_t key;  // the frizz's random stream
  // Per clump index: the affected guides' weighted mean point.
  const std::vector<glm::vec3>* clumpCenters;
};

// Arc length from the root to where the strand first enters the sphere;
// negative when it never does.
float cutLength(const StrandEdit& s, const glm::vec3& c, float r) {
  float travelled = 0.0f;
  if (glm::length(s.at(0) - c) < r) return 0.0f;
  for (int k = 1; k < s.count(); ++k) {
    const glm::vec3 a = s.at(k - 1), b = s.at(k), d = b - a;
    const float l = glm::length(d);
    // |a + t d - c| = r, the first t in [0, 1].
    const glm::vec3 m = a - c;
    const float A = glm::dot(d, d), B = 2.0f * glm::dot(m, d), C = glm::dot(m, m) - r * r;
    const float disc = B * B - 4.0f * A * C;
    if (A > 1e-18f && disc >= 0.0f) {
      const float t = (-B - std::sqrt(disc)) / (2.0f * A);
      if (t >= 0.0f && t <= 1.0f) return travelled + t * l;
    }
    travelled += l;
  }
  return -1.0f;
}

// Whether a dab can reach the strand at all (a segment may cross the
// sphere between two points): most strands are far from any dab.
bool reaches(const float* p, int n, const glm::vec3& c, float r) {
  for (int k = 0; k < n; ++k) {
    const float segment = k > 0 ? glm::length(load(p, k) - load(p, k - 1)) : 0.0f;
    const float reach = r + segment;
    const glm::vec3 d = load(p, k) - c;
    if (glm::dot(d, d) < reach * reach) return true;
  }
  return false;
}

void applyDab(const Dab& dab, StrandEdit& s, size_t guide, const glm::vec3& rootNormal) {
  const int n = s.count();
  std::vector<float> w(n, 0.0f);
  float strongest = 0.0f;
  for (int k = 1; k < n; ++k) {
    w[k] = falloff(s.at(k), dab.center, dab.radius);
    strongest = std::max(strongest, w[k]);
  }
  if (strongest <= 0.0f && dab.brush != GroomBrush::Cut) return;
  switch (dab.brush) {
    case GroomBrush::Comb: {
      // The hair below the brush goes with it, as a comb drags it.
      float carried = 0.0f;
      for (int k = 1; k < n; ++k) {
        carried = std::max(carried, w[k]);
        s.set(k, s.at(k) + dab.strength * carried * dab.motion);
      }
      s.restoreLengths();
      break;
    }
    case GroomBrush::Cut: {
      const float length = cutLength(s, dab.center, dab.radius);
      if (length >= 0.0f && dab.strength > 0.0f) s.resample(std::max(length, kMinLength));
      break;
    }
    case GroomBrush::Length:
      s.resample(std::max(kMinLength, s.length() * (1.0f + kLengthRate * dab.strength * strongest)));
      break;
    case GroomBrush::Puff: {
      // Segments near the root turn towards the root's outward direction;
      // the rest of the strand keeps its directions, so it is lifted whole.
      std::vector<glm::vec3> directions(n - 1);
      for (int k = 1; k < n; ++k) {
        const glm::vec3 d = glm::normalize(s.at(k) - s.at(k - 1) + glm::vec3(1e-9f));
        const float a = std::min(1.0f, kPuffRate * dab.strength * strongest * (1.0f - s.t(k - 1)));
        directions[k - 1] = glm::mix(d, rootNormal, a);
      }
      s.rebuild(directions);
      break;
    }
    case GroomBrush::Smooth: {
      // Each segment turns towards the chord of the strand around it, a
      // sixth of the strand either side: curls and waves straighten (a mean
      // of a few neighbours would keep a helix's constant curvature), the
      // length stays.
      const int window = std::max(2, n / 6);
      std::vector<glm::vec3> smoothed(n - 1);
      for (int i = 0; i < n - 1; ++i) {
        const glm::vec3 d = s.at(i + 1) - s.at(i);
        const glm::vec3 chord = s.at(std::min(i + 1 + window, n - 1)) - s.at(std::max(i - window, 0));
        const float a = kSmoothRate * dab.strength * std::max(w[size_t(i)], w[size_t(i + 1)]);
        smoothed[size_t(i)] =
            glm::mix(glm::normalize(d + glm::vec3(1e-9f)), glm::normalize(chord + glm::vec3(1e-9f)), a);
      }
      s.rebuild(smoothed);
      break;
    }
    case GroomBrush::Clump:
      for (int k = 1; k < n; ++k)
        s.set(k, s.at(k) + kClumpRate * dab.strength * strongest * s.t(k) * ((*dab.clumpCenters)[k] - s.at(k)));
      s.restoreLengths();
      break;
    case GroomBrush::PaintDensity:
    case GroomBrush::PaintLength:
    case GroomBrush::PaintClumping:
    case GroomBrush::PaintMelanin:
    case GroomBrush::PaintPheomelanin:
      break;
    case GroomBrush::Frizz:
      for (int k = 1; k < n; ++k) {
        const uint64_t key = mix64(dab.key + guide) + uint64_t(k) * 3;
        const glm::vec3 r(signedRandom(key), signedRandom(key + 1), signedRandom(key + 2));
        s.set(k, s.at(k) + kFrizzRate * dab.radius * dab.strength * w[k] * s.t(k) * r);
      }
      s.restoreLengths();
      break;
  }
}

// The weighted mean, per point index, of the guides a clump dab touches
// (among `candidates`).
std::vector<glm::vec3> clumpCenters(const Strands& strands, const std::vector<size_t>& candidates, const glm::vec3& c,
                                    float r) {
  const int n = strands.pointsPerStrand;
  std::vector<glm::vec3> sum(n, glm::vec3(0.0f));
  float total = 0.0f;
  for (size_t g : candidates) {
    const float* p = strands.strand(g);
    float strongest = 0.0f;
    for (int k = 1; k < n; ++k) strongest = std::max(strongest, falloff(load(p, k), c, r));
    if (strongest <= 0.0f) continue;
    for (int k = 0; k < n; ++k) sum[k] += strongest * load(p, k);
    total += strongest;
  }
  for (glm::vec3& v : sum) v /= std::max(total, 1e-12f);
  return sum;
}

// A strand's box grown by how far a dab of `radius` can reach it from: the
// radius plus its longest segment (a segment may cross the sphere between
// two points). A dab whose centre is outside it cannot touch the strand.
struct ReachBox {
  glm::vec3 lo, hi;
  bool holds(const glm::vec3& c) const {
    return glm::all(glm::lessThanEqual(lo, c)) && glm::all(glm::lessThanEqual(c, hi));
  }
};

ReachBox reachBox(const float* p, int n, float radius) {
  glm::vec3 a = load(p, 0), b = a;
  float segment = 0.0f;
  for (int k = 1; k < n; ++k) {
    const glm::vec3 q = load(p, k);
    a = glm::min(a, q);
    b = glm::max(b, q);
    segment = std::max(segment, glm::length(q - load(p, k - 1)));
  }
  const float reach = radius + segment;
  return {a - reach, b + reach};
}

// The guides a stroke may touch: those a dab can reach at the stroke's
// start, with their reach boxes. A guide changes only when a dab reaches
// it, so the others stay out of reach for the whole stroke.
void strokeCandidates(const Strands& strands, size_t guides, const GroomStroke& stroke, const glm::vec3& headCenter,
                      std::vector<size_t>& candidates, std::vector<ReachBox>& boxes) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const GroomDab& d : stroke.dabs)
    for (int side = 0; side < (stroke.mirror ? 2 : 1); ++side) {
      const glm::vec3 c = headCenter + (side ? glm::vec3(-1.0f, 1.0f, 1.0f) : glm::vec3(1.0f)) * d.position;
      lo = glm::min(lo, c);
      hi = glm::max(hi, c);
    }
  candidates.clear();
  boxes.clear();
  for (size_t g = 0; g < guides; ++g) {
    const ReachBox box = reachBox(strands.strand(g), strands.pointsPerStrand, stroke.radius);
    if (glm::all(glm::lessThanEqual(box.lo, hi)) && glm::all(glm::greaterThanEqual(box.hi, lo))) {
      candidates.push_back(g);
      boxes.push_back(box);
    }
  }
}

}  // namespace

const std::vector<std::string>& groomBrushNames() {
  static const std::vector<std::string> names{
      "comb",  "cut",           "length",       "puff",           "smooth",        "clump",
      "frizz", "paint_density", "paint_length", "paint_clumping", "paint_melanin", "paint_pheomelanin"};
  return names;
}

PaintRange paintRange(GroomBrush brush) {
  switch (brush) {
    case GroomBrush::PaintDensity:
      return {0.0f, 1.0f, 1.0f};  // the share of the hair kept
    case GroomBrush::PaintLength:
      return {0.05f, 10.0f, 1.0f};  // times the style's length
    case GroomBrush::PaintClumping:
      return {0.0f, 1.0f, -1.0f};  // -1: the style's clumping
    case GroomBrush::PaintMelanin:
    case GroomBrush::PaintPheomelanin:
      return {0.0f, 8.0f, -1.0f};  // concentrations; -1: the style's
    default:
      return {0.0f, 0.0f, 0.0f};
  }
}

float paintedValue(const std::vector<GroomStroke>& strokes, GroomBrush brush, const glm::vec3& at, float unpainted) {
  float value = unpainted;
  for (const GroomStroke& stroke : strokes) {
    if (stroke.brush != brush || !(stroke.radius > 0.0f)) continue;
    for (const GroomDab& dab : stroke.dabs)
      for (int side = 0; side < (stroke.mirror ? 2 : 1); ++side) {
        const glm::vec3 center = (side ? glm::vec3(-1.0f, 1.0f, 1.0f) : glm::vec3(1.0f)) * dab.position;
        const float w = stroke.strength * falloff(at, center, stroke.radius);
        if (w > 0.0f) value += w * (stroke.value - value);
      }
  }
  return value;
}

PaintedShare paintedShare(const std::vector<GroomStroke>& strokes, GroomBrush brush, const glm::vec3& at) {
  // paintedValue() of 0 is what the dabs add; the share of the unpainted
  // value they keep is paintedValue() of 1 minus that.
  PaintedShare share;
  share.add = paintedValue(strokes, brush, at, 0.0f);
  share.keep = paintedValue(strokes, brush, at, 1.0f) - share.add;
  return share;
}

std::vector<GroomStroke> strokesOf(const std::vector<GroomStroke>& strokes, GroomBrush brush) {
  std::vector<GroomStroke> out;
  for (const GroomStroke& s : strokes)
    if (s.brush == brush) out.push_back(s);
  return out;
}

std::string groomBrushName(GroomBrush brush) { return groomBrushNames()[size_t(brush)]; }

GroomBrush groomBrushFromName(const std::string& name) {
  const std::vector<std::string>& names = groomBrushNames();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it != names.end()) return GroomBrush(it - names.begin());
  std::string known;
  for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
  throw Error("unknown brush '" + name + "' (" + known + ")");
}

std::vector<GroomDab> dabsAlong(const glm::vec3& from, const glm::vec3& to, float radius) {
  const float distance = glm::length(to - from);
  const int steps = std::clamp(int(std::ceil(distance / std::max(0.25f * radius, 1e-4f))), 0, 10000);
  if (steps == 0) return {{from, glm::vec3(0.0f)}};
  std::vector<GroomDab> dabs;
  const glm::vec3 step = (to - from) / float(steps);
  for (int i = 1; i <= steps; ++i) dabs.push_back({from + step * float(i), step});
  return dabs;
}

void applyGroomStrokes(const std::vector<GroomStroke>& strokes, size_t first, size_t end, const glm::vec3& headCenter,
                       const BodyProxy& proxy, float margin, uint32_t seed, Strands& strands, size_t guides) {
  const int n = strands.pointsPerStrand;
  guides = std::min(guides, strands.strandCount());
  end = std::min(end, strokes.size());
  if (n < 2 || guides == 0) return;
  // Each dab's random stream follows from its place among all dabs.
  auto dabCount = [](const GroomStroke& stroke) {
    return stroke.radius > 0.0f ? stroke.dabs.size() * (stroke.mirror ? 2 : 1) : 0;
  };
  uint64_t dabKey = seed;
  for (size_t i = 0; i < first && i < end; ++i) dabKey += dabCount(strokes[i]);
  std::vector<glm::vec3> centers;
  std::vector<size_t> candidates;
  std::vector<ReachBox> boxes;
  for (size_t i = first; i < end; ++i) {
    const GroomStroke& stroke = strokes[i];
    uint64_t key = dabKey;
    dabKey += dabCount(stroke);
    // Paint strokes are read where the strands grow, not here.
    if (!(stroke.radius > 0.0f) || isPaintBrush(stroke.brush)) continue;
    strokeCandidates(strands, guides, stroke, headCenter, candidates, boxes);
    if (candidates.empty()) continue;
    for (const GroomDab& d : stroke.dabs)
      for (int side = 0; side < (stroke.mirror ? 2 : 1); ++side) {
        const glm::vec3 flip = side ? glm::vec3(-1.0f, 1.0f, 1.0f) : glm::vec3(1.0f);
        Dab dab{headCenter + flip * d.position,
                flip * d.motion,
                stroke.radius,
                stroke.strength,
                stroke.brush,
                mix64(++key),
                &centers};
        if (dab.brush == GroomBrush::Clump) centers = clumpCenters(strands, candidates, dab.center, dab.radius);
        ThreadPool::shared().parallelFor(0, candidates.size(), 64, [&](size_t begin, size_t end) {
          for (size_t j = begin; j < end; ++j) {
            const size_t g = candidates[j];
            if (!boxes[j].holds(dab.center) || !reaches(strands.strand(g), n, dab.center, dab.radius)) continue;
            StrandEdit s(strands.strand(g), n, proxy, margin);
            const glm::vec3 normal = strands.rootNormals.size() >= 3 * (g + 1)
                                         ? glm::vec3(strands.rootNormals[3 * g], strands.rootNormals[3 * g + 1],
                                                     strands.rootNormals[3 * g + 2])
                                         : glm::normalize(s.at(1) - s.at(0) + glm::vec3(0.0f, 1e-9f, 0.0f));
            applyDab(dab, s, g, normal);
            boxes[j] = reachBox(strands.strand(g), n, dab.radius);  // where the dab left it
          }
        });
      }
  }
}

}  // namespace mq
