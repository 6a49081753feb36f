#include "core/io/baked_surface.h"

#include <cctype>
#include <cstdio>
#include <ostream>

#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace mq {

BakedSurface strandLines(size_t strands, int pointsPerStrand, const glm::vec3& rootColor, const glm::vec3& tipColor) {
  BakedSurface s;
  s.name = "hair";
  s.color = glm::vec4(0.5f * (rootColor + tipColor), 1.0f);
  for (size_t k = 0; k < strands; ++k)
    for (int i = 0; i < pointsPerStrand; ++i) {
      const uint32_t v = uint32_t(k * pointsPerStrand + i);
      if (i + 1 < pointsPerStrand) s.lines.insert(s.lines.end(), {v, v + 1});
      const float along = pointsPerStrand > 1 ? float(i) / float(pointsPerStrand - 1) : 0.0f;
      const glm::vec3 c = glm::mix(rootColor, tipColor, along);
      s.colors.insert(s.colors.end(), {c.x, c.y, c.z});
    }
  return s;
}

void writeSurfaceObj(const BakedSurface& surface, const std::string& path) {
  if (surface.frames.empty()) throw FileError(path, "'" + surface.name + "' has no frame to write");
  const std::vector<float>& p = surface.frames.front();
  writeFileAtomically(path, [&](std::ostream& out) {
    out << "# mannequin " << surface.name << ", frame 1 (the mesh its point cache deforms)\no "
        << surfaceFileStem(surface.name) << "\n";
    char line[96];
    for (size_t k = 0; k + 2 < p.size(); k += 3) {
      std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n", p[k], p[k + 1], p[k + 2]);
      out << line;
    }
    for (size_t t = 0; t + 2 < surface.triangles.size(); t += 3)
      out << "f " << surface.triangles[t] + 1 << ' ' << surface.triangles[t + 1] + 1 << ' '
          << surface.triangles[t + 2] + 1 << '\n';
    for (size_t l = 0; l + 1 < surface.lines.size(); l += 2)
      out << "l " << surface.lines[l] + 1 << ' ' << surface.lines[l + 1] + 1 << '\n';
  });
}

std::string surfaceFileStem(const std::string& name) {
  std::string stem;
  for (char c : name) stem += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  return stem.empty() ? "surface" : stem;
}

}  // namespace mq
