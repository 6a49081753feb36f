#pragma once
// Grooming: from a scalp, a body proxy and a hairstyle to strands.
//   1. roots: Poisson-disk samples on the scalp, guides and children apart;
//   2. guides: streamlines of the styling flow (see flow_field.h), shaped
//      per strand by noise, waves and curls, kept outside the body;
//   3. children: each follows its three nearest guides over the scalp
//      (inverse-distance weights on the guides' offsets from their roots),
//      pulled into wisps around its nearest guide (clumping), plus frizz.
// Everything is deterministic for a given seed, whatever the thread count.
// Editing: regrowGuides() after a primitive moves (fast, the panel matrix is
// kept), growChildren() when the edit is done. Brush strokes (groom_stroke.h)
// replay on the traced guides; a change of strokes alone does not retrace.

#include <cstddef>
#include <string>
#include <vector>

#include "core/hair/body_proxy.h"
#include "core/hair/flow_field.h"
#include "core/hair/hairstyle.h"
#include "core/hair/root_sampling.h"
#include "core/hair/scalp.h"
#include "core/hair/strands.h"

namespace mq {

struct GroomTimings {
  double roots = 0.0;     // seconds, root sampling and guide neighbours (cached between edits)
  double guides = 0.0;    // flow solve + guide tracing
  double children = 0.0;  // interpolation, clumping, frizz, push-out
};

class HairGroom {
 public:
  static constexpr size_t kMaxStrands = 150000;

  // Builds the flow obstacle: ~panelCount source panels over the proxy; those
  // near the scalp get the scalp outflow.
  HairGroom(ScalpSurface scalp, BodyProxy proxy, int panelCount = 320);

  // Grows the whole hairstyle: strandCount strands in total (0: from the
  // style's density and cap), guides included.
  void grow(const HairStyle& style, size_t strandCount = 0);
  // Re-solves the flow for the style's primitives and retraces the guides
  // (roots kept). Call grow() instead when density, seed or counts change.
  void regrowGuides(const HairStyle& style);
  // Re-interpolates the children from the current guides.
  void growChildren(const HairStyle& style);

  // All strands: the guides first (guideOf -1), then the children.
  const Strands& strands() const { return strands_; }
  size_t guideCount() const { return guideRoots_.size(); }
  const HairRoots& guideRoots() const { return guideRoots_; }
  const HairRoots& childRoots() const { return childRoots_; }
  const FlowField& flow() const { return flow_; }
  const BodyProxy& proxy() const { return proxy_; }
  const ScalpSurface& scalp() const { return scalp_; }
  const GroomTimings& timings() const { return timings_; }

  // Points of `strands` inside the proxy (margin 0): must be 0.
  size_t countPointsInside() const;

 private:
  // Roots, the children's thinned by the style's painted density.
  void sampleAllRoots(size_t guides, size_t children, const HairStyle& style);
  void findGuideNeighbours();
  void thinRoots(HairRoots& roots, const std::vector<GroomStroke>& density, uint32_t seed) const;
  // Traces the guides through the style's flow (no brushes).
  void traceGuides(const HairStyle& style);
  float strandLength(const HairStyle& style, const glm::vec3& root, uint64_t strandKey) const;
  // Strands [first, end)'s painted pigments (Strands::pigmentPaint), read at their roots.
  void paintPigments(const HairStyle& style, size_t first, size_t end);

  ScalpSurface scalp_;
  BodyProxy proxy_;
  FlowField flow_;
  HairRoots guideRoots_, childRoots_;
  size_t sampledGuides_ = 0, sampledChildren_ = 0;
  uint32_t sampledSeed_ = 0;
  std::vector<GroomStroke> sampledDensity_;  // the density paint the roots were thinned by
  bool sampled_ = false;
  // Per child: its 3 nearest guides and their weights (first = nearest).
  std::vector<int32_t> neighbours_;
  std::vector<float> weights_;
  std::vector<float> guideLengths_;  // as grown, before the brushes: children scale by them
  // The guides as traced, before the brushes, and what they were traced
  // for: a stroke replays on them without tracing again.
  std::vector<float> tracedGuides_;
  std::string tracedKey_;
  // The traced guides after the strokes below (all but the newest stroke at
  // the last regrow): a stroke being drawn replays alone.
  std::vector<float> brushedGuides_;
  std::vector<GroomStroke> brushedStrokes_;
  Strands strands_;
  GroomTimings timings_;
};

}  // namespace mq
