#pragma once
// Shading of the character's surfaces, done in a fragment shader replacement
// (vtkShaderProperty) that reads the view's lights every frame:
//  - hemisphere ambient (sky above, warm ground bounce below);
//  - wrap lighting with a scatter tint (Green, "Real-time approximations to
//    subsurface scattering", GPU Gems 1, ch. 16, 2004), for the wood;
//  - normalised Blinn-Phong gloss with a Schlick-style Fresnel rise;
//  - rim light: grazing light from the lights behind the character,
//    strongest on the silhouette (pow(1 - N.V, p));
//  - lighting in linear space, written out sRGB-encoded.
// Skin (SurfaceLook::skinShading) is physically based instead, in
// render/skin_shader.cpp: pre-integrated scattering, Kelemen/Szirmay-Kalos
// specular, translucency through thin parts, micro-relief and wrinkles.

#include <string>

#include <glm/glm.hpp>

class vtkActor;
class vtkOpenGLPolyDataMapper;
class vtkTexture;

namespace mq::render {

struct SurfaceLook {
  glm::vec3 albedo{0.80f, 0.70f, 0.58f};        // sRGB
  float ambient = 0.35f;                        // hemisphere ambient strength
  float wrap = 0.25f;                           // 0 = Lambert; 0.5 = light reaches 60 degrees past the terminator
  glm::vec3 scatterColour{1.0f, 0.55f, 0.35f};  // tint of light that went under the surface
  float scatter = 0.5f;                         // strength of the wrapped, tinted light
  float translucency = 0.0f;                    // back light shining through thin parts
  float specular = 0.25f;                       // gloss strength
  float glossiness = 28.0f;                     // Blinn-Phong exponent
  float rim = 2.0f;                             // rim light strength
  float rimPower = 3.5f;                        // higher: a thinner rim
  float exposure = 0.75f;                       // scales the linear result before sRGB encoding
  float grain = 0.14f;                          // wood grain: how much it darkens the albedo (0 = none)
  float grainScale = 60.0f;                     // streaks per metre, about

  // Skin: physically based (render/skin_shader.cpp). Above, `albedo`,
  // `ambient`, `translucency`, `specular` (the specular reflectance rho_s),
  // `rim`, `rimPower` and `exposure` apply to it too; the wrap, scatter and
  // grain fields do not.
  bool skinShading = false;
  // The scattering profile (core/optics/skin_tone.h): a preset ("skin1",
  // "skin2", "light", "medium", "tan", "dark"), or, when empty, the tone
  // model with these volume fractions.
  std::string skinPreset = "skin1";
  float melanin = 0.05f;
  float hemoglobin = 0.01f;
  float radiusScale = 1.0f;  // scattering distance x this: softer light and deeper translucency
  // Specular: two Beckmann lobes (slopes m), mixed lobeMix : 1 - lobeMix.
  float roughness0 = 0.3f;
  float roughness1 = 0.55f;
  float lobeMix = 0.85f;
  // Micro-relief: cellular plateaus and furrows, `microScale` mm across,
  // of slope `microStrength` (height / cell size); fades out below 4 px a cell.
  float microStrength = 0.15f;
  float microScale = 1.2f;  // mm
  // Volino wrinkles where the posed skin is compressed: depth (mm) at full
  // compression, Volino's lambda, and the spacing between folds (mm).
  float wrinkleDepth = 0.6f;
  float wrinkleLambda = 1.0f;  // 1: none at rest
  float wrinkleSpacing = 9.0f;

  static SurfaceLook mannequin();                    // satin, light warm wood
  static SurfaceLook skin(const glm::vec3& albedo);  // physically based skin in this colour (sRGB)
  // Skin coloured by its own preset's total diffuse reflectance R_d.
  static SurfaceLook skinPresetLook(const std::string& preset);
  static SurfaceLook plain(const glm::vec3& albedo);  // no scattering (imported materials)
};

// Point-data array the surface shader reads the rest (bind) positions from:
// 3 floats per point, set once; patterns stay fixed on the skin.
inline constexpr const char* kRestPositionArray = "mqRestPosition";

// A polydata mapper that feeds the view's lights to the surface shader each
// frame (render/surface_mapper.h), with the rest positions and the skin's
// per-vertex arrays (render/skin_surface_arrays.h) mapped to attributes.
vtkOpenGLPolyDataMapper* newSurfaceMapper();
// Installs the surface shader on `actor` (whose mapper came from
// newSurfaceMapper). For skin, `albedoMap` (sRGB, may be null) multiplies
// the albedo, read through the point data's texture coordinates.
void applySurfaceLook(vtkActor* actor, const SurfaceLook& look, vtkTexture* albedoMap = nullptr);

}  // namespace mq::render
