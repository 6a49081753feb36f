#pragma once
// A hairstyle as the user edits it: the flow primitives whose streamlines
// shape the hair (Hadap and Magnenat-Thalmann, "Interactive hair styler based
// on fluid flow", 2000) plus the parameters that turn streamlines into
// strands (density, length, clumping, frizz, colour, seed).
//
// Positions of primitives are in head space: metres, world axes (Y up, the
// character faces +Z), origin at the centre of the head proxy. So a style
// moves from one character to another.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/hair/groom_stroke.h"

namespace mq {

// A uniform stream: the overall fall of the hair.
struct UniformStream {
  glm::vec3 direction{0.0f, -1.0f, 0.0f};
  float strength = 1.0f;  // m/s
};

// A point source (sink when strength < 0) with a smooth core of `radius`:
//   v = strength * d * R^2 / (|d|^2 + R^2)^(3/2),  d = x - position
// so strength is the outward speed scale near the core.
struct PointSource {
  glm::vec3 position{0.0f};
  float strength = 0.5f;
  float radius = 0.05f;
};

// A localised vortex around `axis` through `position`: solid-body rotation
// in its core, Gaussian fall-off outside, divergence free:
//   v = strength * (a x d) / R * exp(1/2 - |d|^2 / (2 R^2))
// so strength is the swirl speed at distance R from the axis. Positive
// strength turns counter-clockwise seen from the tip of the axis.
struct Vortex {
  glm::vec3 position{0.0f};
  glm::vec3 axis{0.0f, -1.0f, 0.0f};
  float strength = 0.5f;
  float radius = 0.05f;
};

struct FlowPrimitives {
  std::vector<UniformStream> streams;
  std::vector<PointSource> sources;
  std::vector<Vortex> vortices;
};

// Optional length map over the scalp: a multiplier of the style's length,
// 1 everywhere except near these points (Gaussian blend of `radius`).
struct LengthPoint {
  glm::vec3 position{0.0f};  // head space
  float scale = 1.0f;
  float radius = 0.05f;
};

// How the strands are shaded (the document's "shading"): Kajiya-Kay with the
// root and tip colours, or the physically based fibre of
// core/optics/hair_bsdf.h coloured by its pigments.
enum class HairShadingModel { KajiyaKay, Physical };
struct HairShadingParams {
  HairShadingModel model = HairShadingModel::KajiyaKay;
  float melanin = 1.3f;      // eumelanin concentration (Chiang et al. 2016 units, 0 .. ~8)
  float pheomelanin = 0.1f;  // the red pigment, same units
  float roughness = 0.3f;    // longitudinal and azimuthal beta (0.1 sleek .. 0.6 coarse)
  bool operator==(const HairShadingParams& o) const {
    return model == o.model && melanin == o.melanin && pheomelanin == o.pheomelanin && roughness == o.roughness;
  }
  bool operator!=(const HairShadingParams& o) const { return !(*this == o); }
};

// How the hair moves against itself (sim/hair/hair_interaction.h): how
// strongly it holds its volume (0 off .. 1) and its internal friction (0 .. 1);
// and whether guides that move together are simulated as one wisp.
struct HairDynamicsParams {
  float volume = 0.0f;
  float friction = 0.0f;
  // Simulate merged wisps where the hair moves together (sim/hair/adaptive_wisps.h).
  bool adaptiveWisps = false;
  bool operator==(const HairDynamicsParams& o) const {
    return volume == o.volume && friction == o.friction && adaptiveWisps == o.adaptiveWisps;
  }
  bool operator!=(const HairDynamicsParams& o) const { return !(*this == o); }
};

struct HairStyle {
  std::string name = "custom";
  FlowPrimitives primitives;
  // Normal speed of the head's surface panels on the scalp (the boundary
  // condition b = v.n there): it makes the hair spring from the roots.
  float scalpOutflow = 0.6f;
  // Volumetric Perlin perturbation of the flow.
  float noiseAmplitude = 0.15f;  // relative to the local flow speed
  float noiseScale = 0.08f;      // wavelength in metres

  // Roots.
  float density = 150.0f;   // hairs per cm^2
  int maxStrands = 100000;  // cap on the total count (at most 150,000)
  int guideCount = 2000;    // strands traced through the field; the rest are interpolated
  // Strands.
  float length = 0.30f;          // metres
  float lengthVariation = 0.1f;  // relative random variation per strand
  std::vector<LengthPoint> lengthMap;
  int pointsPerStrand = 32;
  float strandNoise = 0.01f;   // per-strand wander at the tip, metres
  float waveAmplitude = 0.0f;  // per-strand planar waves, metres
  float waveLength = 0.08f;
  float curlRadius = 0.0f;   // per-strand helical curls, metres
  float curlLength = 0.05f;  // length of hair per turn
  // Children.
  float clumping = 0.4f;         // 0: children follow their guides' shape; 1: tips meet in wisps
  float clumpShape = 1.5f;       // exponent of the clump profile along the strand
  float frizz = 0.004f;          // random offset at the tips, metres
  float frizzFrequency = 40.0f;  // cycles per metre of hair
  glm::vec3 rootColor{0.10f, 0.06f, 0.035f};
  glm::vec3 tipColor{0.25f, 0.16f, 0.09f};
  HairShadingParams shading;
  HairDynamicsParams dynamics;
  uint32_t seed = 1;
  // Brush strokes, replayed in order on the traced guides (groom_stroke.h).
  std::vector<GroomStroke> strokes;
};

// What `brush`'s map holds where nothing is painted: the style's own
// clumping or pigments, else paintRange()'s unpainted value.
float unpaintedValue(const HairStyle& style, GroomBrush brush);

// The built-in hairstyles: "long_straight", "bob", "wavy", "curly".
std::vector<std::string> builtinHairStyleNames();
// Throws mq::Error naming the known styles when `name` is not one of them.
HairStyle builtinHairStyle(const std::string& name);

}  // namespace mq
