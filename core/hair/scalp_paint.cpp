#include "core/hair/scalp_paint.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>

#include "core/character/posed_character.h"
#include "core/util/error.h"

namespace mq {
namespace {

glm::vec3 faceCentre(const std::vector<uint32_t>& triangles, const std::vector<float>& p, uint32_t f) {
  glm::vec3 c(0.0f);
  for (int k = 0; k < 3; ++k) {
    const uint32_t v = triangles[3 * f + k];
    c += glm::vec3(p[3 * v], p[3 * v + 1], p[3 * v + 2]);
  }
  return c / 3.0f;
}

// Each mesh's faces whose corners all lie on `surface` (matched by rest position).
std::map<int, std::vector<uint32_t>> facesOnSurface(const Character& character, const ScalpSurface& surface) {
  std::set<std::array<float, 3>> corners;
  for (size_t k = 0; k + 2 < surface.positions.size(); k += 3)
    corners.insert({surface.positions[k], surface.positions[k + 1], surface.positions[k + 2]});
  PosedCharacter rest;
  rest.evaluate(character, -1, 0.0f, nullptr, nullptr);
  std::map<int, std::vector<uint32_t>> faces;
  for (size_t m = 0; m < character.meshes.size(); ++m) {
    const Mesh& mesh = character.meshes[m];
    const std::vector<float>& p = rest.meshes()[m].positions;
    for (uint32_t f = 0; f < mesh.triangleCount(); ++f) {
      bool all = true;
      for (int k = 0; k < 3 && all; ++k) {
        const uint32_t v = mesh.triangles[3 * f + k];
        all = corners.count({p[3 * v], p[3 * v + 1], p[3 * v + 2]}) > 0;
      }
      if (all) faces[int(m)].push_back(f);
    }
  }
  return faces;
}

}  // namespace

ScalpRegion scalpAsFaces(const Character& character, const ScalpRegion& region) {
  if (region.kind == ScalpRegion::Kind::Faces) return region;
  ScalpRegion out;
  out.kind = ScalpRegion::Kind::Faces;
  out.bone = region.bone;
  out.mesh = 0;
  ScalpSurface surface;
  try {
    surface = extractScalp(character, region);
  } catch (const Error&) {
    return out;  // nothing to start from: paint from scratch
  }
  for (const auto& [mesh, faces] : facesOnSurface(character, surface))
    if (faces.size() > out.faces.size()) {
      out.mesh = mesh;
      out.faces = faces;
    }
  return out;
}

int meshUnderBrush(const std::vector<std::vector<float>>& meshPositions, const glm::vec3& point) {
  int best = -1;
  float bestDistance = 1e30f;
  for (size_t m = 0; m < meshPositions.size(); ++m) {
    const std::vector<float>& p = meshPositions[m];
    for (size_t k = 0; k + 2 < p.size(); k += 3) {
      const float d = glm::length(glm::vec3(p[k], p[k + 1], p[k + 2]) - point);
      if (d < bestDistance) {
        bestDistance = d;
        best = int(m);
      }
    }
  }
  return best;
}

ScalpRegion paintScalp(const ScalpRegion& region, int mesh, const std::vector<uint32_t>& triangles,
                       const std::vector<float>& positions, const glm::vec3& point, float radius, bool erase) {
  ScalpRegion out = region;
  out.kind = ScalpRegion::Kind::Faces;
  if (out.mesh != mesh) out.faces.clear();
  out.mesh = mesh;
  std::set<uint32_t> faces(out.faces.begin(), out.faces.end());
  for (uint32_t f = 0; 3 * size_t(f) + 2 < triangles.size(); ++f) {
    if (glm::length(faceCentre(triangles, positions, f) - point) > radius) continue;
    if (erase)
      faces.erase(f);
    else
      faces.insert(f);
  }
  out.faces.assign(faces.begin(), faces.end());
  return out;
}

}  // namespace mq
