#include "render/hair_shaders.h"

namespace mq::render {

const char* const kHairVertexDec = R"(//VTK::Normal::Dec
in vec3 hairTangentMC;
in vec3 hairParamsMC;
in vec3 hairTintMC;
out vec3 hairTangentVC;
out vec3 hairParams;
out vec3 hairTint;
)";

const char* const kHairVertexImpl = R"(//VTK::Light::Impl
  hairTangentVC = (MCVCMatrix * vec4(hairTangentMC, 0.0)).xyz;
  hairParams = hairParamsMC;
  hairTint = hairTintMC;
)";

const char* const kKajiyaKayFragmentDec = R"(//VTK::Normal::Dec
in vec3 hairTangentVC;
in vec3 hairParams;  // x: 0 root .. 1 tip, y: self-shadow, z: per-strand random
in vec3 hairTint;    // the painted pigments' colour against the style's (1: unpainted)
)";

// Both models' fragment code runs after VTK's own lighting and replaces its
// result: this frame of the fibre first, their lighting, then the tip fade.
const char* const kHairFibreFrame = R"(//VTK::Light::Impl
  {
    vec3 T = normalize(hairTangentVC);
    vec3 V = normalize(-vertexVC.xyz);
    // The point normals carry the hair volume's outward direction (VTK
    // lights lines only when they have normals, and passes them in VC).
    float volumeLength = length(normalVCVSOutput);
    vec3 volumeNormal = volumeLength > 1e-4 ? normalVCVSOutput / volumeLength : V;
    float along = hairParams.x;
    float shadow = hairParams.y;
)";

// Thinner towards the tip: screen-door transparency (no sorting needed).
const char* const kHairTipFade = R"(
    float fade = clamp((along - hairTipFadeStart) / max(1e-3, 1.0 - hairTipFadeStart), 0.0, 1.0);
    float opacity = mix(1.0, hairTipOpacity, fade);
    const float bayer[16] = float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0,
                                      3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);
    ivec2 cell = ivec2(mod(gl_FragCoord.xy, 4.0));
    // The per-strand offset keeps neighbouring tips from sharing one pattern.
    if (opacity < fract((bayer[cell.x + 4 * cell.y] + 0.5) / 16.0 + hairParams.z)) discard;
    gl_FragData[0] = vec4(color, 1.0);
  }
)";

// Kajiya-Kay with two shifted highlights.
const char* const kKajiyaKayLighting = R"(
    vec3 base = mix(hairRootColor, hairTipColor, along) * hairTint *
                (1.0 + hairColorVariation * (2.0 * hairParams.z - 1.0));
    // Shifted tangents (Scheuermann 2004, after Marschner et al. 2003): the
    // part of the view direction across the fibre stands in for its normal.
    vec3 across = V - dot(V, T) * T;
    float acrossLength = length(across);
    across = acrossLength > 1e-4 ? across / acrossLength : volumeNormal;
    vec3 T1 = normalize(T + hairPrimaryShift * across);
    vec3 T2 = normalize(T + hairSecondaryShift * across);
    float brightest = max(max(base.r, base.g), max(base.b, 1e-3));
    vec3 tint = mix(vec3(1.0), base / brightest, 0.85);
    vec3 color = hairAmbient * base;
    for (int i = 0; i < mqLightCount; ++i) {
      vec3 L = mqLightDirVC[i];
      vec3 H = normalize(L + V);
      float TL = dot(T, L);
      float kajiyaDiffuse = sqrt(max(0.0, 1.0 - TL * TL));
      // Light reaching this side of the hair volume (soft, wraps around).
      float facing = clamp(0.55 + 0.45 * dot(volumeNormal, L), 0.0, 1.0);
      float TH1 = dot(T1, H), TH2 = dot(T2, H);
      float primary = pow(sqrt(max(0.0, 1.0 - TH1 * TH1)), hairPrimaryExponent);
      float secondary = pow(sqrt(max(0.0, 1.0 - TH2 * TH2)), hairSecondaryExponent);
      vec3 lit = hairDiffuse * kajiyaDiffuse * base + hairPrimarySpecular * primary * vec3(1.0)
               + hairSecondarySpecular * secondary * tint * brightest;
      color += mqLightColour[i] * shadow * facing * lit;
    }
)";

}  // namespace mq::render
