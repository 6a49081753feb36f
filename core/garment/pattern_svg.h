#pragma once
// A garment's sewing pattern as SVG at true scale (one user unit is one
// millimetre, so it prints or goes to a cutter at 1:1): per panel its sewing
// line as one path (straight and Bezier edges exactly), the grain line
// (pattern v, along the body), its name, a notch and a label on both edges of
// each seam, and on request the cutting line a seam allowance outside.
// Panels are laid out left to right, as seen from the outside of the garment.

#include <string>

#include "core/garment/garment.h"

namespace mq {

struct PatternSvgOptions {
  float seamAllowance = 0.0f;  // metres; 0: no cutting line
};

// Throws mq::Error for an invalid garment (Garment::validate) or a seam
// allowance that is negative, not finite or over 10 cm.
std::string patternSvg(const Garment& garment, const PatternSvgOptions& options = {});
// Writes patternSvg atomically; FileError naming `path` when it cannot.
void writePatternSvg(const std::string& path, const Garment& garment, const PatternSvgOptions& options = {});

}  // namespace mq
