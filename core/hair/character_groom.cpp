#include "core/hair/character_groom.h"

namespace mq {

std::unique_ptr<HairGroom> makeCharacterGroom(const Character& character, const ScalpRegion& region, int panelCount) {
  ScalpSurface scalp = extractScalp(character, region);
  std::vector<glm::vec3> scalpPoints;
  for (size_t v = 0; v < scalp.positions.size() / 3; ++v) scalpPoints.push_back(scalp.position(v));
  BodyProxy proxy = fitBodyProxy(character, region.bone, scalpPoints);
  return std::make_unique<HairGroom>(std::move(scalp), std::move(proxy), panelCount);
}

}  // namespace mq
