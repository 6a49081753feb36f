#pragma once
// Sets a groom up on a character: its scalp (tagged faces or a region) and a
// body proxy fitted to its head bone and upper body.

#include <memory>

#include "core/character/character.h"
#include "core/hair/hair_groom.h"
#include "core/hair/scalp.h"

namespace mq {

// The head bone is region.bone (default "head"). Throws mq::Error when the
// scalp is empty or the head bone is missing.
std::unique_ptr<HairGroom> makeCharacterGroom(const Character& character, const ScalpRegion& region,
                                              int panelCount = 320);

}  // namespace mq
