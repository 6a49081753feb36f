#pragma once
// Image checks for the render tests: differences between images, the
// foreground against a background-only render, and baseline comparison in
// the manner of f3d (a missing baseline writes the image to the build tree
// and fails, naming where it went).

#include <string>

#include <glm/glm.hpp>

#include "render/offscreen.h"

namespace mq::test {

struct ImageDifference {
  // Root mean square of the channel differences, in 8-bit levels (0..255).
  // 0 = identical; ~1 = rasterisation noise; >~3 = a visible change.
  double rms = 0.0;
  // Fraction of pixels with some channel differing by more than 24 levels:
  // how much of the picture visibly changed.
  double changedFraction = 0.0;
};
ImageDifference compareImages(const render::RgbImage& a, const render::RgbImage& b);

struct Foreground {
  double fraction = 0.0;          // of all pixels
  glm::dvec2 centre{0.0};         // centre of mass, 0..1 across, 0..1 down
  glm::dvec2 min{1.0}, max{0.0};  // bounding box, same units
};
// Pixels of `image` that differ from `background` by more than 24 levels.
Foreground foregroundOf(const render::RgbImage& image, const render::RgbImage& background);

// Tolerance for baselines: an image matches when rms <= 2.0 levels and at
// most 0.5% of the pixels changed visibly. That absorbs rasterisation
// differences between Mesa builds but fails on any change of pose, framing,
// lighting or material one would notice.
struct BaselineTolerance {
  double maxRms = 2.0;
  double maxChangedFraction = 0.005;
};

// Compares `image` with tests/render/baselines/<name>.png. Returns "" when it
// matches; otherwise the reason, after writing the image (and the baseline's
// difference) under <build>/Testing/Temporary/.
std::string checkAgainstBaseline(const render::RgbImage& image, const std::string& name,
                                 const BaselineTolerance& tolerance = {});

// Forces Mesa's software rasteriser so images are reproducible; call before
// the first window is created.
void useSoftwareRendering();

}  // namespace mq::test
