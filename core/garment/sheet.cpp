#include "core/garment/sheet.h"

#include <cmath>

#include "core/util/error.h"

namespace mq {

namespace {

void addQuad(Sheet& s, int r, int c) {
  const uint32_t a = s.index(r, c), b = s.index(r, c + 1), d = s.index(r + 1, c), e = s.index(r + 1, c + 1);
  const bool flip = (r + c) % 2 == 1;
  if (flip) {
    s.triangles.insert(s.triangles.end(), {a, b, e, a, e, d});
  } else {
    s.triangles.insert(s.triangles.end(), {a, b, d, b, e, d});
  }
}

}  // namespace

Sheet makeSheet(const SheetSpec& spec) {
  if (spec.columns < 2 || spec.rows < 2) throw Error("a sheet needs at least 2 x 2 vertices");
  if (!(spec.width > 0.0f) || !(spec.height > 0.0f) || !std::isfinite(spec.width) || !std::isfinite(spec.height))
    throw Error("a sheet needs a positive width and height");
  Sheet s;
  s.columns = spec.columns;
  s.rows = spec.rows;
  s.positions.reserve(3 * spec.columns * spec.rows);
  for (int r = 0; r < spec.rows; ++r) {
    for (int c = 0; c < spec.columns; ++c) {
      const float u = float(c) / float(spec.columns - 1), v = float(r) / float(spec.rows - 1);
      const glm::vec3 p = spec.origin + u * spec.width * spec.widthAxis + v * spec.height * spec.heightAxis;
      s.positions.insert(s.positions.end(), {p.x, p.y, p.z});
      s.uvs.insert(s.uvs.end(), {u, v});
    }
  }
  for (int r = 0; r + 1 < spec.rows; ++r)
    for (int c = 0; c + 1 < spec.columns; ++c) addQuad(s, r, c);
  return s;
}

SheetSpec horizontalSheet(int n, float size, const glm::vec3& centre) {
  SheetSpec spec;
  spec.columns = spec.rows = n;
  spec.width = spec.height = size;
  spec.origin = centre - glm::vec3(0.5f * size, 0.0f, 0.5f * size);
  spec.widthAxis = {1.0f, 0.0f, 0.0f};
  spec.heightAxis = {0.0f, 0.0f, 1.0f};
  return spec;
}

}  // namespace mq
