#pragma once
// A file's material on a VTK actor through VTK's physically based pipeline
// (metallic-roughness, normal, occlusion and emissive maps; image-based
// lighting from the studio environment), plus what VTK 9.1 lacks: glTF's
// alpha modes (a fragment test for MASK, the factor's alpha for BLEND) and
// an emissive factor without an emissive map.

#include "core/material/material.h"

class vtkActor;

namespace mq::render {

class MaterialTextures;

// The uv set and transform the actor's texture coordinates must carry: VTK
// samples every map of a material with one set, so the base colour map's
// (else the first map's) decides.
const TextureRef* textureCoordinateSource(const Material& material);

void applyMaterial(vtkActor* actor, const Material& material, MaterialTextures& textures);

}  // namespace mq::render
