#pragma once
// The head of a character without bones (a static mesh: a head scan, a body
// from another program), found from the mesh's top: hair needs a head to
// grow on and a proxy to flow around.

#include <cstdint>
#include <vector>

#include "core/character/character.h"

namespace mq {

// Per mesh, 1 for each vertex of the head in the rest pose: every vertex of
// a mesh no taller than kHeadOnlyHeight (a head alone), else those in the
// top kHeadShareOfHeight of the character's height (a person's head is
// about an eighth of their height).
constexpr float kHeadOnlyHeight = 0.5f;  // metres
constexpr float kHeadShareOfHeight = 0.13f;
std::vector<std::vector<uint8_t>> staticHeadVertices(const Character& character);

}  // namespace mq
