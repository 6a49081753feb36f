#pragma once
// Private to core/io: FBX and Collada characters through Assimp (the only
// translation unit that includes Assimp).
//
// Bones are the skin-bound nodes and the animated nodes of the node
// hierarchy; non-bone ancestors in between go into Bone::parentFromOffset.
// Skin weights are normalised per vertex and all influences are kept (the
// FBX test character has up to 6). FBX inverse bind matrices come from the
// rest (node) pose, because Assimp 5.2's FBX bone offsets are unreliable
// (assimp issue 4620); other formats keep Assimp's offsets (the file's own
// bind pose). Animated nodes whose keys all hold their rest value (exporters
// key the armature object too) stay fixed transforms, not bones.
// Collada: Assimp 5.2.5 refuses whitespace-padded arrays, so the XML is
// trimmed in memory first; its clip library is read by collada_clips.h.

#include <string>

#include "core/character/character.h"

namespace mq {

// Throws FileError.
Character importWithAssimp(const std::string& path);

}  // namespace mq
