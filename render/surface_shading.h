#pragma once
// Shading of the character's surfaces, done in a fragment shader replacement
// (vtkShaderProperty) that reads the view's lights every frame:
//  - hemisphere ambient (sky above, warm ground bounce below);
//  - wrap lighting with a scatter tint as the subsurface-scattering
//    approximation: light reaches past the terminator and arrives reddened
//    (Green, "Real-time approximations to subsurface scattering", GPU Gems 1,
//    ch. 16, 2004);
//  - translucency of thin parts lit from behind (Barré-Brisebois & Bouchard,
//    "Approximating translucency for a fast, cheap and convincing
//    subsurface-scattering look", GDC 2011);
//  - normalised Blinn-Phong gloss with a Schlick-style Fresnel rise;
//  - rim light: grazing light from the lights behind the character,
//    strongest on the silhouette (pow(1 - N.V, p));
//  - lighting in linear space, written out sRGB-encoded.

#include <glm/glm.hpp>

class vtkActor;
class vtkOpenGLPolyDataMapper;

namespace mq::render {

struct SurfaceLook {
  glm::vec3 albedo{0.80f, 0.70f, 0.58f};  // sRGB
  float ambient = 0.35f;       // hemisphere ambient strength
  float wrap = 0.25f;          // 0 = Lambert; 0.5 = light reaches 60 degrees past the terminator
  glm::vec3 scatterColour{1.0f, 0.55f, 0.35f};  // tint of light that went under the surface
  float scatter = 0.5f;        // strength of the wrapped, tinted light
  float translucency = 0.0f;   // back light shining through thin parts
  float specular = 0.25f;      // gloss strength
  float glossiness = 28.0f;    // Blinn-Phong exponent
  float rim = 2.0f;            // rim light strength
  float rimPower = 3.5f;       // higher: a thinner rim
  float exposure = 0.75f;      // scales the linear result before sRGB encoding
  float grain = 0.14f;         // wood grain: how much it darkens the albedo (0 = none)
  float grainScale = 60.0f;    // streaks per metre, about

  static SurfaceLook mannequin();                     // satin, light warm wood
  static SurfaceLook skin(const glm::vec3& albedo);   // soft, scattering, low gloss
  static SurfaceLook plain(const glm::vec3& albedo);  // no scattering (imported materials)
};

// Point-data array the surface shader reads the rest (bind) positions from:
// 3 floats per point, set once; patterns stay fixed on the skin.
inline constexpr const char* kRestPositionArray = "mqRestPosition";

// A polydata mapper that feeds the view's lights to the surface shader each frame.
vtkOpenGLPolyDataMapper* newSurfaceMapper();
// Installs the surface shader on `actor` (whose mapper came from newSurfaceMapper).
void applySurfaceLook(vtkActor* actor, const SurfaceLook& look);

}  // namespace mq::render
