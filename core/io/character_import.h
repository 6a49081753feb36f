#pragma once
// Loading characters from files. Every failure (missing file, truncated or
// garbage content, unsupported type) is an mq::FileError naming the file.
//
// Supported: glTF 2.0 (.gltf, .glb) by our own reader; FBX (.fbx) and
// Collada (.dae) through Assimp; BVH (.bvh) motion capture as a skeleton with
// one clip and no meshes.

#include <string>

#include "core/character/character.h"

namespace mq {

// Dispatches on the file extension (case-insensitive).
Character importCharacter(const std::string& path);

}  // namespace mq
