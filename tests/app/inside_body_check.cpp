// mannequin_inside_body_check BODY.obj CLOTH.obj MAX: counts the vertices of
// CLOTH (a simulated garment frame) inside BODY (the character posed at that
// frame's time, a closed triangle mesh) by ray parity, the way the sewing
// unit tests do. Prints the count; exit 0 when at most MAX, 1 when more, 2
// when a file cannot be read. Also prints the lowest and highest cloth y.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "obj_vertices.h"

namespace {

struct Vec3 {
  double x, y, z;
};
Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// The triangles of an OBJ ("f a b c", "f a/t/n ...", polygons fanned), 0-based.
bool readObjTriangles(const char* path, std::vector<size_t>& out) {
  std::ifstream in(path);
  if (!in) return false;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("f ", 0) != 0) continue;
    std::istringstream s(line.substr(2));
    std::vector<size_t> polygon;
    for (std::string corner; s >> corner;) polygon.push_back(std::stoul(corner.substr(0, corner.find('/'))) - 1);
    for (size_t i = 1; i + 1 < polygon.size(); ++i) out.insert(out.end(), {polygon[0], polygon[i], polygon[i + 1]});
  }
  return true;
}

// Odd crossings of a ray (slightly off +X, to miss edges) with the mesh.
bool inside(const std::vector<double>& v, const std::vector<size_t>& triangles, Vec3 p) {
  const double length = std::sqrt(1.0 + 0.0123 * 0.0123 + 0.0217 * 0.0217);
  const Vec3 dir{1.0 / length, 0.0123 / length, 0.0217 / length};
  auto at = [&](size_t i) { return Vec3{v[3 * i], v[3 * i + 1], v[3 * i + 2]}; };
  int crossings = 0;
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const Vec3 a = at(triangles[t]), e1 = at(triangles[t + 1]) - a, e2 = at(triangles[t + 2]) - a;
    const Vec3 q = cross(dir, e2);
    const double det = dot(e1, q);
    if (std::abs(det) < 1e-15) continue;
    const Vec3 s = p - a;
    const double u = dot(s, q) / det;
    if (u < 0.0 || u > 1.0) continue;
    const Vec3 r = cross(s, e1);
    const double w = dot(dir, r) / det;
    if (w < 0.0 || u + w > 1.0) continue;
    if (dot(e2, r) / det > 0.0) ++crossings;
  }
  return crossings % 2 == 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s BODY.obj CLOTH.obj MAX\n", argv[0]);
    return 2;
  }
  std::vector<double> body, cloth;
  std::vector<size_t> triangles;
  if (!readObjVertices(argv[1], body) || !readObjTriangles(argv[1], triangles) || triangles.empty()) {
    std::fprintf(stderr, "%s: cannot read a triangle mesh\n", argv[1]);
    return 2;
  }
  if (!readObjVertices(argv[2], cloth)) {
    std::fprintf(stderr, "%s: cannot read the vertices\n", argv[2]);
    return 2;
  }
  for (size_t i : triangles)
    if (3 * i + 2 >= body.size()) {
      std::fprintf(stderr, "%s: a face names vertex %zu of %zu\n", argv[1], i + 1, body.size() / 3);
      return 2;
    }
  int count = 0;
  double lowest = 1e30, highest = -1e30;
  for (size_t i = 0; i + 2 < cloth.size(); i += 3) {
    count += inside(body, triangles, {cloth[i], cloth[i + 1], cloth[i + 2]});
    lowest = std::min(lowest, cloth[i + 1]), highest = std::max(highest, cloth[i + 1]);
  }
  std::printf("%d of %zu vertices inside the body, y %.4f %.4f\n", count, cloth.size() / 3, lowest, highest);
  return count <= std::atoi(argv[3]) ? 0 : 1;
}
