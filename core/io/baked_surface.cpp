#include "core/io/baked_surface.h"

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

}  // namespace mq
