#include "render/material_look.h"

#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkProperty.h>
#include <vtkShaderProperty.h>
#include <vtkTexture.h>
#include <vtkUniforms.h>

#include "render/material_textures.h"

namespace mq::render {
namespace {

// Runs after VTK's PBR lighting, which wrote the colour with the base colour
// map's alpha: applies the factor's alpha and the alpha mode.
const char* kAlphaModes = R"(//VTK::Light::Impl
  gl_FragData[0].a *= mqBaseAlpha;
  if (mqAlphaMode == 1) {
    if (gl_FragData[0].a < mqAlphaCutoff) discard;
    gl_FragData[0].a = 1.0;
  } else if (mqAlphaMode == 0) {
    gl_FragData[0].a = 1.0;
  }
)";

// VTK adds emission only from an emissive map: a white texel lets the
// factor alone shine.
vtkTexture* whiteTexture() {
  static vtkTexture* white = [] {
    vtkImageData* image = vtkImageData::New();
    image->SetDimensions(1, 1, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* texel = static_cast<unsigned char*>(image->GetScalarPointer());
    texel[0] = texel[1] = texel[2] = 255;
    vtkTexture* texture = vtkTexture::New();
    texture->SetInputData(image);
    image->Delete();
    return texture;
  }();
  return white;
}

}  // namespace

const TextureRef* textureCoordinateSource(const Material& material) {
  if (material.baseColorTexture.present()) return &material.baseColorTexture;
  for (const TextureSlot& slot : material.textureSlots())
    if (slot.ref->present()) return slot.ref;
  return nullptr;
}

void applyMaterial(vtkActor* actor, const Material& material, MaterialTextures& textures) {
  vtkProperty* p = actor->GetProperty();
  p->RemoveAllTextures();
  p->SetInterpolationToPBR();
  p->SetColor(material.baseColorFactor.x, material.baseColorFactor.y, material.baseColorFactor.z);
  p->SetDiffuse(1.0);
  p->SetOpacity(1.0);  // alpha is applied in the shader, after VTK's own
  p->SetMetallic(material.metallicFactor);
  p->SetRoughness(material.roughnessFactor);
  p->SetBackfaceCulling(!material.doubleSided);
  if (vtkTexture* t = textures.colour(material.baseColorTexture)) p->SetBaseColorTexture(t);
  bool withOcclusion = false;
  if (vtkTexture* t = textures.occlusionRoughnessMetallic(material, withOcclusion)) p->SetORMTexture(t);
  p->SetOcclusionStrength(withOcclusion ? material.occlusionStrength : 0.0);
  if (vtkTexture* t = textures.data(material.normalTexture)) {
    p->SetNormalTexture(t);
    p->SetNormalScale(material.normalScale);
  }
  const glm::vec3 emission = material.emissiveFactor * material.emissiveStrength;
  if (vtkTexture* t = textures.colour(material.emissiveTexture))
    p->SetEmissiveTexture(t);
  else if (emission != glm::vec3(0.0f))
    p->SetEmissiveTexture(whiteTexture());
  p->SetEmissiveFactor(emission.x, emission.y, emission.z);

  vtkShaderProperty* sp = actor->GetShaderProperty();
  sp->ClearAllShaderReplacements();
  sp->AddFragmentShaderReplacement("//VTK::Light::Impl", true, kAlphaModes, false);
  vtkUniforms* u = sp->GetFragmentCustomUniforms();
  u->SetUniformf("mqBaseAlpha", material.baseColorFactor.w);
  u->SetUniformi("mqAlphaMode", static_cast<int>(material.alphaMode));
  u->SetUniformf("mqAlphaCutoff", material.alphaCutoff);
  actor->SetForceTranslucent(material.alphaMode == AlphaMode::Blend);
  actor->SetForceOpaque(material.alphaMode != AlphaMode::Blend);
}

}  // namespace mq::render
