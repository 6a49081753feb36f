#include "core/hair/static_head.h"

#include <algorithm>

#include "core/character/posed_character.h"

namespace mq {

std::vector<std::vector<uint8_t>> staticHeadVertices(const Character& character) {
  PosedCharacter rest;
  rest.evaluate(character, -1, 0.0f, nullptr, nullptr);
  float low = 1e30f, high = -1e30f;
  for (const PosedMesh& mesh : rest.meshes())
    for (size_t k = 1; k < mesh.positions.size(); k += 3) {
      low = std::min(low, mesh.positions[k]);
      high = std::max(high, mesh.positions[k]);
    }
  const float height = high - low;
  const float chin = height <= kHeadOnlyHeight ? low : high - kHeadShareOfHeight * height;
  std::vector<std::vector<uint8_t>> head;
  for (const PosedMesh& mesh : rest.meshes()) {
    std::vector<uint8_t>& flags = head.emplace_back(mesh.positions.size() / 3, 0);
    for (size_t v = 0; v < flags.size(); ++v) flags[v] = mesh.positions[3 * v + 1] >= chin;
  }
  return head;
}

}  // namespace mq
