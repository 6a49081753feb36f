// mannequin_obj_diff A.obj B.obj TOLERANCE [--tail]: compares the vertices of
// two OBJ files in order (--tail: B with the last vertices of A, as many as B
// has: the last mesh of a posed scene); prints the largest distance; exit 0
// when within tolerance, 1 when not, 2 when the files differ in vertex count
// or cannot be read.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "obj_vertices.h"

int main(int argc, char** argv) {
  const bool tail = argc == 5 && std::string(argv[4]) == "--tail";
  if (argc != 4 && !tail) {
    std::fprintf(stderr, "usage: mannequin_obj_diff A.obj B.obj TOLERANCE [--tail]\n");
    return 2;
  }
  std::vector<double> a, b;
  if (!readObjVertices(argv[1], a) || !readObjVertices(argv[2], b)) {
    std::fprintf(stderr, "cannot read %s or %s\n", argv[1], argv[2]);
    return 2;
  }
  if (tail && a.size() > b.size()) a.erase(a.begin(), a.end() - long(b.size()));
  if (a.size() != b.size() || a.empty()) {
    std::fprintf(stderr, "vertex counts differ: %zu vs %zu\n", a.size() / 3, b.size() / 3);
    return 2;
  }
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); i += 3)
    worst = std::max(worst, std::hypot(a[i] - b[i], a[i + 1] - b[i + 1], a[i + 2] - b[i + 2]));
  const double tolerance = std::atof(argv[3]);
  std::printf("%zu vertices, max distance %.3e (tolerance %.3e)\n", a.size() / 3, worst, tolerance);
  return worst <= tolerance ? 0 : 1;
}
