#pragma once
// A garment's sewing pattern as DXF, the file pattern CAD programs exchange,
// after the AAMA/ASTM D6673 conventions: one block per panel, inserted side
// by side, in millimetres ($INSUNITS 4), with the layers
//   1 boundary (the cutting line; the sewing line when there is no seam
//     allowance) and the "Piece Name: ..." text, 2 turn points (corners),
//   4 notches, 7 grain line, 14 sew line (one LINE or SPLINE per edge, Bezier
//   edges exactly as single-span B-splines);
// and three of Mannequin's own, so that a pattern comes back whole:
//   MQ_EDGE the edge names, MQ_SEAM "seam N a" / "seam N b [reversed]" at the
//   middle of each sewn edge, MQ_PLACEMENT where the panel sits on the body.
// The garment's name is the "Style Name: ..." text.
//
// Reading takes what another program wrote as well: pieces are the blocks (or
// model space) holding a closed outline on layer 14, else on layer 1, else,
// in a file without those layers, any closed outline (polylines, lines, arcs,
// splines chained end to end). Units from $INSUNITS (millimetres when absent).
// An outline without Mannequin's layers gets corners at its turn points
// (layer 2, or bends over 20 degrees), curves fitted with cubic Beziers within
// 0.5 mm, edges named e0, e1, ..., no seams, and panels laid flat side by
// side in front of the body.

#include <string>

#include "core/garment/garment.h"

namespace mq {

struct PatternDxfOptions {
  float seamAllowance = 0.0f;  // metres; 0: the boundary is the sewing line
};

// Throws mq::Error for an invalid garment or allowance (as patternSvg), and
// FileError naming `path` when it cannot be written. The write is atomic.
void writePatternDxf(const std::string& path, const Garment& garment, const PatternDxfOptions& options = {});

// The garment a DXF pattern describes (named fallbackName when the file has
// no style name). Throws mq::Error saying what is wrong
// (not DXF, no closed outline, an outline that does not close, too large, a
// pattern Garment::validate refuses).
Garment patternFromDxf(const std::string& dxfText, const std::string& fallbackName = "pattern");
// Throws FileError naming `path` and the problem.
Garment readPatternDxf(const std::string& path);

}  // namespace mq
