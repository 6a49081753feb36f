#pragma once
// Writes a character as a rigged glTF 2.0 / GLB: its skeleton as nodes, each
// skinned mesh in bind space with JOINTS_0 / WEIGHTS_0 and a skin, meshes
// that follow one bone as that bone's children, and every clip as an
// animation sampled at `fps` on the clip's own time axis (linear
// translation, rotation and scale per bone). Procedural bones (helper bones)
// are baked into the samples, so any engine plays them with plain linear
// blend skinning. Morph targets and materials are not written. Written
// atomically; failures throw FileError naming the file.

#include <string>

#include "core/character/character.h"

namespace mq {

void exportRiggedCharacter(const Character& character, const std::string& path, float fps);

// True when `path` ends in .gltf or .glb.
bool isRiggedExportPath(const std::string& path);

}  // namespace mq
