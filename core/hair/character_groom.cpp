#include "core/hair/character_groom.h"

#include "core/hair/head_fit.h"

namespace mq {

std::unique_ptr<HairGroom> makeCharacterGroom(const Character& character, const ScalpRegion& region, int panelCount) {
  ScalpSurface scalp = extractScalp(character, region);
  std::vector<glm::vec3> scalpPoints;
  for (size_t v = 0; v < scalp.positions.size() / 3; ++v) scalpPoints.push_back(scalp.position(v));
  BodyProxy proxy = fitBodyProxy(character, region.bone, scalpPoints);
  return std::make_unique<HairGroom>(std::move(scalp), std::move(proxy), panelCount);
}

std::unique_ptr<HairGroom> makeSectionGroom(const Character& character, HairSection& section, int panelCount) {
  if (!section.scalpGiven) {
    section.scalp = automaticScalpRegion(character);
    section.scalpGiven = true;
  }
  std::unique_ptr<HairGroom> groom = makeCharacterGroom(character, section.scalp, panelCount);
  if (section.fitToHead) {
    section.style = fitHairStyleToHead(section.style, groom->proxy());
    section.fitToHead = false;
  }
  return groom;
}

}  // namespace mq
