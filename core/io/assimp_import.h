#pragma once
// Private to core/io: FBX and Collada characters through Assimp (the only
// translation unit that includes Assimp).
//
// Bones are the skin-bound nodes and the animated nodes of the node
// hierarchy; non-bone ancestors in between go into Bone::parentFromOffset.
// Skin weights are normalised per vertex and all influences are kept (the
// FBX test character has up to 6). Inverse bind matrices come from the rest
// (node) pose, because Assimp 5.2's FBX bone offsets are unreliable (assimp
// issue 4620); Assimp's offsets are used when they agree with the nodes.

#include <string>

#include "core/character/character.h"

namespace mq {

// Throws FileError.
Character importWithAssimp(const std::string& path);

}  // namespace mq
