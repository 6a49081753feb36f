#pragma once
// Reads the vertex positions ("v x y z" lines) of an OBJ file, for the CLI
// tests' small checkers.

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

// False when the file cannot be read or a vertex line is malformed.
template <typename Real>
bool readObjVertices(const char* path, std::vector<Real>& out) {
  std::ifstream in(path);
  if (!in) return false;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream s(line.substr(2));
    Real x, y, z;
    if (!(s >> x >> y >> z)) return false;
    out.insert(out.end(), {x, y, z});
  }
  return true;
}
