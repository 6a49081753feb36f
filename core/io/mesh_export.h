#pragma once
// Writes posed meshes (world-space positions and normals, the meshes' own
// triangles, vertices in importer order, no welding) to OBJ, PLY, glTF or GLB,
// chosen by the file extension. PLY is binary little-endian (float xyz +
// normals, int triangle lists); glTF/GLB hold static meshes (one node per
// mesh, no skin, with their materials; .gltf embeds its buffer as a data URI). Files are written
// atomically (temporary file, then rename); failures throw FileError naming
// the file.

#include <string>
#include <vector>

#include "core/character/posed_character.h"
#include "core/mesh/mesh.h"

namespace mq {

// meshes[i] gives the topology (triangles, uvs, names) of posed[i].
// materials: the character whose materials the meshes use (glTF writes
// them, textures embedded), or null.
void exportPosedMesh(const std::vector<const Mesh*>& meshes, const std::vector<PosedMesh>& posed,
                     const std::string& path, const Character* materials = nullptr);

// Convenience: every mesh of a posed character.
void exportPosedCharacter(const Character& character, const PosedCharacter& posed, const std::string& path);

// True when exportPosedMesh can write `path` (by extension).
bool isMeshExportPath(const std::string& path);

}  // namespace mq
