#pragma once
// Grooming brushes: strokes a user paints over the hair (comb, cut, length,
// puff, smooth, clump, frizz), stored in the hairstyle and replayed on the
// guides every time they are traced, so moving a flow primitive afterwards
// keeps the combing; children follow their guides.
//
// A stroke is a list of dabs, each a sphere of the stroke's radius at a
// point in head space (see hairstyle.h); a guide point inside it is weighted
// by a smooth falloff, (1 - (d/r)^2)^2. The rates below are per dab: a
// stroke lays a dab every quarter radius or so, so a point under a stroke
// sees a few of them.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace mq {

class BodyProxy;
struct Strands;

// The shaping brushes move the guides. The paint brushes paint a map over
// the scalp instead, read where each strand grows: the share of the hair
// kept (density), a length factor, the clumping, and the colour as the
// fibre's pigments (eumelanin, pheomelanin: core/optics/hair_bsdf.h).
enum class GroomBrush {
  Comb,
  Cut,
  Length,
  Puff,
  Smooth,
  Clump,
  Frizz,
  PaintDensity,
  PaintLength,
  PaintClumping,
  PaintMelanin,
  PaintPheomelanin
};
inline bool isPaintBrush(GroomBrush brush) { return brush >= GroomBrush::PaintDensity; }
// The values a paint brush may paint, and the map's value where nothing is
// painted (-1: the style's own, its clumping or pigments).
struct PaintRange {
  float min, max, unpainted;
};
PaintRange paintRange(GroomBrush brush);

// "comb", "cut", "length", "puff", "smooth", "clump", "frizz", "paint_density",
// "paint_length", "paint_clumping", "paint_melanin", "paint_pheomelanin".
const std::vector<std::string>& groomBrushNames();
std::string groomBrushName(GroomBrush brush);
// Throws mq::Error naming the brushes when `name` is not one of them.
GroomBrush groomBrushFromName(const std::string& name);

struct GroomDab {
  glm::vec3 position{0.0f};  // head space, metres
  glm::vec3 motion{0.0f};    // the brush's movement since the last dab (comb)
  bool operator==(const GroomDab&) const = default;
};

struct GroomStroke {
  GroomBrush brush = GroomBrush::Comb;
  float radius = 0.03f;  // metres
  // 0..1; for Length, -1..1: negative shortens. A paint brush's opacity.
  float strength = 0.5f;
  // What a paint brush paints (see paintRange()); unused by the others.
  float value = 1.0f;
  // Also applied mirrored across the head's symmetry plane (x = 0 in head space).
  bool mirror = false;
  std::vector<GroomDab> dabs;
  bool operator==(const GroomStroke&) const = default;
};

// What a document may hold (time and memory: every regrow replays them).
constexpr size_t kMaxGroomStrokes = 10000;
constexpr size_t kMaxGroomDabs = 200000;

// Dabs every quarter radius along the segment from `from` to `to` (head
// space), each carrying its share of the motion; one dab when they meet.
std::vector<GroomDab> dabsAlong(const glm::vec3& from, const glm::vec3& to, float radius);

// The map painted by `brush`'s strokes at head-space point `at`: from
// `unpainted`, each dab in order blends towards its stroke's value by its
// strength times its falloff.
float paintedValue(const std::vector<GroomStroke>& strokes, GroomBrush brush, const glm::vec3& at, float unpainted);
// The same map as keep * unpainted + add (each dab's blend is affine in the
// value), so a map over a value that changes later (the style's pigments)
// is stored once: {1, 0} where nothing is painted.
struct PaintedShare {
  float keep = 1.0f, add = 0.0f;
  float of(float unpainted) const { return keep * unpainted + add; }
};
PaintedShare paintedShare(const std::vector<GroomStroke>& strokes, GroomBrush brush, const glm::vec3& at);
// The strokes that paint `brush`'s map.
std::vector<GroomStroke> strokesOf(const std::vector<GroomStroke>& strokes, GroomBrush brush);

// Replays the shaping strokes of strokes[first, end) on the first `guides` strands of `strands`
// (world space; the head centre `headCenter` is head space's origin), which
// hold the hair as the strokes before `first` left it. Strands keep their
// point count; cut and length resample them. Every point stays out of
// `proxy` by `margin`. Deterministic for a given seed, whatever the thread
// count, and the same whether the strokes are replayed at once or in parts.
void applyGroomStrokes(const std::vector<GroomStroke>& strokes, size_t first, size_t end, const glm::vec3& headCenter,
                       const BodyProxy& proxy, float margin, uint32_t seed, Strands& strands, size_t guides);

}  // namespace mq
