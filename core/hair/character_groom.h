#pragma once
// Sets a groom up on a character: its scalp (tagged faces or a region) and a
// body proxy fitted to its head bone and upper body.

#include <memory>

#include "core/character/character.h"
#include "core/hair/hair_groom.h"
#include "core/hair/hairstyle_json.h"
#include "core/hair/scalp.h"

namespace mq {

// The head bone is region.bone (default "head"). Throws mq::Error when the
// scalp is empty or the head bone is missing.
std::unique_ptr<HairGroom> makeCharacterGroom(const Character& character, const ScalpRegion& region,
                                              int panelCount = 320);

// The groom for a document's hair section on `character` (not grown yet).
// Resolves the section first: a scalp chosen by automaticScalpRegion() when
// the section names none, and a built-in style (fitToHead) fitted to the
// head (fitHairStyleToHead); afterwards section.style is the style to grow
// and fitToHead is false.
std::unique_ptr<HairGroom> makeSectionGroom(const Character& character, HairSection& section, int panelCount = 320);

}  // namespace mq
