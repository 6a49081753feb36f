#pragma once
// A look at a DXF file's text before dxflib reads it: dxflib allocates
// arrays from the counts a file gives (a polyline's vertices, a spline's knots
// and control points, a hatch's loops) without checking them, so a hostile
// count would make it allocate gigabytes. Counts larger than the file's
// group-code pairs cannot be honest and are refused here, as are binary DXF,
// over-long lines and a file that ends before its EOF marker.

#include <string>

namespace mq {

// Throws mq::Error saying what is wrong.
void checkDxfText(const std::string& text);

}  // namespace mq
