#pragma once
// Writes a character's materials into a glTF being written: metallic-roughness
// factors, the textures they sample (sampler, texture coordinate set,
// KHR_texture_transform) and their images, embedded in the buffer, so the
// file stands alone. Material i of the character is material i of the glTF.

#include <map>
#include <string>
#include <vector>

#include "core/character/character.h"
#include "core/io/gltf_writer.h"

namespace mq {

// Returns a warning per image that could not be embedded (a missing file);
// the textures that sample it are left out and their materials keep their
// factors.
std::vector<std::string> addGltfMaterials(GltfWriter& writer, const Character& character);

// The primitives of `mesh` sharing `attributes`: one per draw range, each
// with its own indices and material (none for -1 or an unknown material).
std::vector<tinygltf::Primitive> gltfPrimitives(GltfWriter& writer, const Mesh& mesh,
                                                const std::map<std::string, int>& attributes, size_t materialCount);

}  // namespace mq
