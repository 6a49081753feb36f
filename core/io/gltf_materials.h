#pragma once
// Private to core/io: glTF 2.0 materials, textures, samplers and images
// (KHR_texture_transform, KHR_materials_emissive_strength) read into a
// Character. Images stay encoded; an external image that is missing is a
// warning naming it (the material keeps its factors), never an error.

#include "core/character/character.h"
#include "core/io/gltf_document.h"

namespace mq::gltf {

void readMaterials(const Document& doc, Character& character);

}  // namespace mq::gltf
