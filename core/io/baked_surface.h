#pragma once
// A surface simulated outside the skeleton (a garment, a cloth sheet, hair
// strands), recorded frame by frame for an animated export (rigged_export.h).

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace mq {

struct BakedSurface {
  std::string name;
  std::vector<uint32_t> triangles;          // a cloth mesh, or
  std::vector<uint32_t> lines;              // index pairs: hair strands (glTF mode LINES)
  std::vector<std::vector<float>> frames;   // world space, 3 floats per vertex, every frame the same size
  std::vector<float> colors;                // linear RGB per vertex (COLOR_0), may be empty
  glm::vec4 color{0.8f, 0.8f, 0.8f, 1.0f};  // linear RGBA of its material
};

// Hair strands as line segments, `strands` polylines of `pointsPerStrand`
// points laid out one after the other (Strands::points), coloured from root
// to tip; no frames yet.
BakedSurface strandLines(size_t strands, int pointsPerStrand, const glm::vec3& rootColor, const glm::vec3& tipColor);

// The surface's first frame as OBJ (triangles as faces, strands as `l`
// polylines), the mesh a point cache of its frames deforms. Atomic; throws
// FileError naming the path.
void writeSurfaceObj(const BakedSurface& surface, const std::string& path);

// A file-name-safe form of the surface's name ("T-shirt" stays, "my coat" -> "my_coat").
std::string surfaceFileStem(const std::string& name);

}  // namespace mq
