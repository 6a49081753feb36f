#pragma once
// Strands to a PLY file other tools read: binary little-endian, one vertex
// element (float x, y, z) and one edge element (int vertex1, vertex2) per
// segment, so each strand is a polyline. Written atomically; failures throw
// FileError naming the file.

#include <string>

#include "core/hair/strands.h"

namespace mq {

void writeStrandsPly(const Strands& strands, const std::string& path);

}  // namespace mq
