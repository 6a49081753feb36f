#pragma once
// Private to core/io: our own glTF 2.0 reader (.gltf and .glb).
//
// Why not Assimp for glTF: Assimp 5.2.5's glTF2 importer reorders and joins
// vertices, drops CUBICSPLINE tangents and may drop zero-weight joints, so its
// result cannot follow the spec's skinning exactly. This reader keeps the
// file's vertex order (mesh-bearing nodes of the default scene in `nodes`
// order, primitives in order, vertices in accessor order, no welding).
//
// Mapping to a Character: the bones are the skin joints plus any other node an
// animation moves; a bone's parent is its nearest bone ancestor, and the fixed
// transforms of non-bone nodes in between go into Bone::parentFromOffset.
// A skinned node's own transform is ignored (as the spec says); unskinned
// meshes follow their nearest bone ancestor via attachBone/boneFromMesh.
// Skin weights are divided by their sum; zero-weight joints are tolerated.

#include <string>

#include "core/character/character.h"

namespace mq {

// Throws FileError for missing, truncated or malformed files.
Character readGltfCharacter(const std::string& path);

}  // namespace mq
