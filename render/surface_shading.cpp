#include "render/surface_shading.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <vtkActor.h>
#include <vtkDataObject.h>
#include <vtkProperty.h>
#include <vtkShaderProperty.h>
#include <vtkUniforms.h>

#include "core/optics/skin_tone.h"
#include "render/skin_shader.h"
#include "render/skin_surface_arrays.h"
#include "render/surface_mapper.h"

namespace mq::render {
namespace {

// The rest (bind) position rides along as a vertex attribute, so surface
// patterns stay fixed on the body while it moves.
const char* kVertexDec = R"(//VTK::Normal::Dec
in vec3 mqRestMC;
out vec3 mqRest;
)";
const char* kVertexImpl = R"(//VTK::Normal::Impl
  mqRest = mqRestMC;
)";
const char* kFragmentDec = R"(//VTK::Normal::Dec
in vec3 mqRest;
// Value noise from a hash: smooth, cheap, no texture.
float mqHash(vec3 p) { return fract(sin(dot(p, vec3(127.1, 311.7, 74.7))) * 43758.5453); }
float mqNoise(vec3 p) {
  vec3 i = floor(p), f = fract(p);
  f = f * f * (3.0 - 2.0 * f);
  return mix(mix(mix(mqHash(i), mqHash(i + vec3(1, 0, 0)), f.x),
                 mix(mqHash(i + vec3(0, 1, 0)), mqHash(i + vec3(1, 1, 0)), f.x), f.y),
             mix(mix(mqHash(i + vec3(0, 0, 1)), mqHash(i + vec3(1, 0, 1)), f.x),
                 mix(mqHash(i + vec3(0, 1, 1)), mqHash(i + vec3(1, 1, 1)), f.x), f.y), f.z);
}
// Wood grain: fine streaks along the body's long axis (y), wavering.
float mqGrain(vec3 p) {
  vec3 q = p * vec3(1.0, 0.08, 1.0) * mqGrainScale;
  float waver = mqNoise(q * 0.3) * 14.0 + mqNoise(q * 1.3) * 2.0;
  float streaks = 0.5 + 0.5 * sin(q.x * 7.0 + q.z * 5.0 + waver);
  return pow(streaks, 6.0) * 0.65 + mqNoise(q * vec3(3.0, 1.0, 3.0)) * 0.35;
}
)";

// Runs after VTK's own lighting (the tag stays first) and replaces its result.
const char* kSurfaceLight = R"(//VTK::Light::Impl
  {
    vec3 N = normalize(normalVCVSOutput);
    vec3 V = normalize(-vertexVC.xyz);
    float NdV = clamp(dot(N, V), 0.0, 1.0);
    // Grain shows close up and fades out before streaks come closer than
    // about 4 pixels (seen from afar they would read as pinstripes or alias).
    float streaksPerPixel = length(fwidth(mqRest.xz)) * mqGrainScale * 7.0 / 6.2832;
    float grainAmount = mqGrainStrength * clamp((0.25 - streaksPerPixel) / 0.15, 0.0, 1.0);
    vec3 albedo = pow(mqAlbedo, vec3(2.2)) * (1.0 - grainAmount * mqGrain(mqRest));
    vec3 scatterTint = pow(mqScatterColour, vec3(2.2));
    // Hemisphere ambient: cool sky above, warm floor bounce below.
    float skyward = 0.5 + 0.5 * dot(N, mqUpVC);
    vec3 colour = mqAmbient * albedo * mix(vec3(0.10, 0.085, 0.07), vec3(0.20, 0.23, 0.28), skyward);
    vec3 rimLight = vec3(0.0);
    for (int i = 0; i < mqLightCount; ++i) {
      vec3 L = mqLightDirVC[i];
      vec3 C = mqLightColour[i];
      float NdL = dot(N, L);
      float lambert = max(NdL, 0.0);
      // Subsurface scattering, approximated: light wraps past the terminator
      // and what arrives there has travelled under the skin, so it is tinted.
      float wrapped = max((NdL + mqWrap) / (1.0 + mqWrap), 0.0);
      vec3 diffuse = vec3(lambert) + mqScatter * scatterTint * (wrapped - lambert);
      // Translucency: back light seen through thin parts.
      float through = pow(clamp(dot(V, -normalize(L + 0.3 * N)), 0.0, 1.0), 6.0);
      diffuse += mqTranslucency * through * scatterTint;
      // Gloss: normalised Blinn-Phong, brighter at grazing angles (Fresnel).
      vec3 H = normalize(L + V);
      float NdH = max(dot(N, H), 0.0);
      float fresnel = 1.0 + 4.0 * pow(1.0 - clamp(dot(H, V), 0.0, 1.0), 5.0);
      float gloss = mqSpecular * fresnel * (mqGlossiness + 8.0) / 8.0 * pow(NdH, mqGlossiness) * lambert;
      // Lights from behind mostly outline the silhouette (the rim term
      // below) rather than flood the sides they face.
      float behind = clamp(0.25 - dot(L, V), 0.0, 1.0);
      colour += C * (albedo * diffuse * (1.0 - 0.6 * behind) + vec3(gloss));
      rimLight += C * behind * smoothstep(-0.2, 0.4, NdL);
    }
)";

}  // namespace

SurfaceLook SurfaceLook::mannequin() { return SurfaceLook{}; }

SurfaceLook SurfaceLook::skin(const glm::vec3& albedo) {
  SurfaceLook look;
  look.skinShading = true;
  look.albedo = albedo;
  look.translucency = 1.0f;
  look.grain = 0.0f;
  look.specular = 1.0f;  // rho_s of the Kelemen/Szirmay-Kalos lobes
  look.rim = 1.0f;
  look.rimPower = 2.5f;
  return look;
}

SurfaceLook SurfaceLook::skinPresetLook(const std::string& preset) {
  const optics::Rgb reflectance = optics::skinPreset(preset).totalReflectance();
  auto srgb = [](double linear) { return float(std::pow(std::clamp(linear, 0.0, 1.0), 1.0 / 2.2)); };
  SurfaceLook look = skin({srgb(reflectance[0]), srgb(reflectance[1]), srgb(reflectance[2])});
  look.skinPreset = preset;
  return look;
}

SurfaceLook SurfaceLook::plain(const glm::vec3& albedo) {
  SurfaceLook look;
  look.albedo = albedo;
  look.wrap = 0.0f;
  look.scatter = 0.0f;
  look.grain = 0.0f;
  return look;
}

vtkOpenGLPolyDataMapper* newSurfaceMapper() {
  SurfaceMapper* mapper = SurfaceMapper::New();
  mapper->MapDataArrayToVertexAttribute("mqRestMC", kRestPositionArray, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  mapper->MapDataArrayToVertexAttribute("mqCurvatureMC", kCurvatureArray, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  mapper->MapDataArrayToVertexAttribute("mqThicknessMC", kThicknessArray, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  mapper->MapDataArrayToVertexAttribute("mqWrinkleMC", kWrinkleArray, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  mapper->MapDataArrayToVertexAttribute("mqWrinklePhaseMC", kWrinklePhaseArray, vtkDataObject::FIELD_ASSOCIATION_POINTS,
                                        -1);
  return mapper;
}

void applySurfaceLook(vtkActor* actor, const SurfaceLook& look, vtkTexture* albedoMap) {
  vtkProperty* p = actor->GetProperty();
  p->RemoveAllTextures();  // a file material's, when switching looks
  p->SetBackfaceCulling(false);
  p->SetOpacity(1.0);
  actor->SetForceTranslucent(false);
  actor->SetForceOpaque(false);
  p->SetInterpolationToPhong();
  p->SetColor(look.albedo.x, look.albedo.y, look.albedo.z);  // for renderers without the shader
  if (look.skinShading) {
    applySkinShading(actor, look, albedoMap);
    return;
  }
  if (auto* mapper = SurfaceMapper::SafeDownCast(actor->GetMapper())) mapper->setSamplers({});
  vtkShaderProperty* sp = actor->GetShaderProperty();
  sp->ClearAllShaderReplacements();
  sp->AddVertexShaderReplacement("//VTK::Normal::Dec", true, kVertexDec, false);
  sp->AddVertexShaderReplacement("//VTK::Normal::Impl", true, kVertexImpl, false);
  sp->AddFragmentShaderReplacement("//VTK::Normal::Dec", true, kFragmentDec, false);
  sp->AddFragmentShaderReplacement("//VTK::Light::Impl", true, std::string(kSurfaceLight) + kRimLightAndOutputGlsl,
                                   false);
  vtkUniforms* u = sp->GetFragmentCustomUniforms();
  setUniform3(u, "mqAlbedo", look.albedo);
  setUniform3(u, "mqScatterColour", look.scatterColour);
  u->SetUniformf("mqAmbient", look.ambient);
  u->SetUniformf("mqWrap", look.wrap);
  u->SetUniformf("mqScatter", look.scatter);
  u->SetUniformf("mqTranslucency", look.translucency);
  u->SetUniformf("mqSpecular", look.specular);
  u->SetUniformf("mqGlossiness", look.glossiness);
  u->SetUniformf("mqRim", look.rim);
  u->SetUniformf("mqRimPower", look.rimPower);
  u->SetUniformf("mqExposure", look.exposure);
  u->SetUniformf("mqGrainStrength", look.grain);
  u->SetUniformf("mqGrainScale", look.grainScale);
  declareViewLightUniforms(u);
}

}  // namespace mq::render
