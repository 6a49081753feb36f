// mannequin_hair_roots_check STRANDS.ply POSED.obj TOLERANCE [STRIDE]: checks
// that hair strands (mannequin's binary PLY polylines) are rooted on a posed
// mesh (OBJ): the first point of every STRIDE-th strand lies within TOLERANCE
// metres of a vertex of the mesh. Prints the largest distance; exit 0 when
// within tolerance, 1 when not, 2 when a file cannot be read.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "obj_vertices.h"

namespace {

// The strand roots of a PLY written by writeStrandsPly: the header's comment
// gives the points per strand, the vertex block follows the header.
bool readPlyRoots(const char* path, std::vector<float>& roots) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::string line;
  size_t vertices = 0, points = 0;
  while (std::getline(in, line) && line != "end_header") {
    if (line.rfind("element vertex ", 0) == 0) vertices = std::stoul(line.substr(15));
    const size_t at = line.find(" points per strand");
    if (line.rfind("comment", 0) == 0 && at != std::string::npos) {
      const size_t comma = line.rfind(',', at);
      points = std::stoul(line.substr(comma + 1, at - comma - 1));
    }
  }
  if (vertices == 0 || points == 0 || vertices % points) return false;
  std::vector<float> all(3 * vertices);
  if (!in.read(reinterpret_cast<char*>(all.data()), std::streamsize(all.size() * sizeof(float)))) return false;
  for (size_t s = 0; s < vertices / points; ++s)
    roots.insert(roots.end(), &all[3 * s * points], &all[3 * s * points] + 3);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s STRANDS.ply POSED.obj TOLERANCE [STRIDE]\n", argv[0]);
    return 2;
  }
  std::vector<float> roots, mesh;
  if (!readPlyRoots(argv[1], roots)) {
    std::fprintf(stderr, "%s: not a strands PLY\n", argv[1]);
    return 2;
  }
  if (!readObjVertices(argv[2], mesh) || mesh.empty()) {
    std::fprintf(stderr, "%s: no vertices\n", argv[2]);
    return 2;
  }
  const double tolerance = std::atof(argv[3]);
  const size_t stride = argc > 4 ? std::max(1, std::atoi(argv[4])) : 1;
  double worst = 0.0;
  for (size_t r = 0; r < roots.size() / 3; r += stride) {
    double best = std::numeric_limits<double>::max();
    for (size_t v = 0; v < mesh.size(); v += 3) {
      const double dx = roots[3 * r] - mesh[v], dy = roots[3 * r + 1] - mesh[v + 1],
                   dz = roots[3 * r + 2] - mesh[v + 2];
      best = std::min(best, dx * dx + dy * dy + dz * dz);
    }
    worst = std::max(worst, std::sqrt(best));
  }
  std::printf("%zu roots, largest distance to the mesh %.6f m (tolerance %g)\n", roots.size() / 3, worst, tolerance);
  return worst <= tolerance ? 0 : 1;
}
