#include "render/skin_shader.h"

#include <cstdio>
#include <string>

#include <vtkActor.h>
#include <vtkProperty.h>
#include <vtkShaderProperty.h>
#include <vtkTexture.h>
#include <vtkUniforms.h>

#include "core/geometry/cellular_relief.h"
#include "core/optics/skin_tone.h"
#include "render/skin_lut_texture.h"
#include "render/surface_mapper.h"

namespace mq::render {
namespace {

const char* kVertexDec = R"(//VTK::Normal::Dec
in vec3 mqRestMC;
in float mqCurvatureMC;
in float mqThicknessMC;
in vec4 mqWrinkleMC;
in float mqWrinklePhaseMC;
out vec3 mqRest;
out float mqCurvature;
out float mqThickness;
out vec4 mqWrinkle;
out float mqWrinklePhase;
)";
const char* kVertexImpl = R"(//VTK::Normal::Impl
  mqRest = mqRestMC;
  mqCurvature = mqCurvatureMC;
  mqThickness = mqThicknessMC;
  mqWrinkle = mqWrinkleMC;
  mqWrinklePhase = mqWrinklePhaseMC;
)";
const char* kVertexAlbedoDec = "in vec2 mqUVMC;\nout vec2 mqUV;\n";
const char* kVertexAlbedoImpl = "  mqUV = mqUVMC;\n";

const char* kFragmentDec = R"(//VTK::Normal::Dec
in vec3 mqRest;
in float mqCurvature;
in float mqThickness;
in vec4 mqWrinkle;
in float mqWrinklePhase;
uniform sampler2D mqSkinLut;
// Lattice hash and cellular relief: core/geometry/cellular_relief.cpp, line for line.
uint mqHash(uint x) {
  x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;
  return x;
}
vec3 mqReliefGradient(vec3 p) {
  vec3 base = floor(p);
  float f1 = 1e9, f2 = 1e9;
  vec3 c1 = vec3(0.0), c2 = vec3(0.0);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        vec3 cell = base + vec3(dx, dy, dz);
        ivec3 ic = ivec3(cell);
        uint seed = mqHash(uint(ic.x) + mqHash(uint(ic.y) + mqHash(uint(ic.z))));
        vec3 feature = cell + vec3(float(mqHash(seed)), float(mqHash(seed + 1u)), float(mqHash(seed + 2u))) * (1.0 / 4294967296.0);
        float d = length(p - feature);
        if (d < f1) { f2 = f1; c2 = c1; f1 = d; c1 = feature; }
        else if (d < f2) { f2 = d; c2 = feature; }
      }
  float x = min((f2 - f1) / MQ_FURROW, 1.0);
  if (x >= 1.0 || f1 < 1e-6 || f2 < 1e-6) return vec3(0.0);
  return 2.0 * (1.0 - x) * ((p - c2) / f2 - (p - c1) / f1) / MQ_FURROW;
}
// Beckmann distribution without the 1/pi, as d'Eon and Luebke's PH.
float mqBeckmann(float nDotH, float m) {
  float c2 = nDotH * nDotH;
  return exp((c2 - 1.0) / (m * m * c2)) / (m * m * c2 * c2);
}
)";
const char* kFragmentAlbedoDec = "in vec2 mqUV;\nuniform sampler2D mqAlbedoMap;\n";

// Runs after VTK's own lighting (the tag stays first) and replaces its result.
const char* kSkinLightBegin = R"(//VTK::Light::Impl
  {
    vec3 N = normalize(normalVCVSOutput);
    vec3 V = normalize(-vertexVC.xyz);
    float NdV = clamp(dot(N, V), 0.0, 1.0);
    // Bumps: height gradients on the rest surface (metres per metre).
    vec3 dPdx = dFdx(vertexVC.xyz), dPdy = dFdy(vertexVC.xyz);
    vec3 dRdx = dFdx(mqRest), dRdy = dFdy(mqRest);
    // A pixel's footprint on the surface, from depth and slant: smooth from
    // triangle to triangle (screen derivatives are constant per triangle and
    // would fade detail in facets). The derivatives stand in without perspective.
    float restPerPixel = mqPixelAngle > 0.0 ? -vertexVC.z * mqPixelAngle / max(NdV, 0.3)
                                            : max(length(dRdx), length(dRdy));
    restPerPixel = max(restPerPixel, 1e-12);
    vec3 slope = vec3(0.0);
    float cell = 1e-3 * mqMicroScale;
    float microFade = clamp((cell / restPerPixel - 4.0) / 8.0, 0.0, 1.0);  // reliefFade
    if (microFade * mqMicroStrength > 0.0) slope += mqMicroStrength * microFade * mqReliefGradient(mqRest / cell);
    // Volino: t = 2 lambda (1 / (1 + (l/L)^2) - 1) + 1, clamped; height
    // depth t (1 - cos ks) / 2, s the phase along the compression direction.
    float directed = length(mqWrinkle.xyz);
    float spacing = 1e-3 * mqWrinkleSpacing;
    // Faded by the folds' actual width on screen: where the phase field runs
    // faster than the nominal spacing (a twisted patch), folds would alias.
    float phasePixels = spacing / max(fwidth(mqWrinklePhase), 1e-12);
    float wrinkleFade = clamp((spacing / restPerPixel - 4.0) / 8.0, 0.0, 1.0) * clamp((phasePixels - 3.0) / 3.0, 0.0, 1.0) *
                        smoothstep(0.2, 0.8, directed);
    if (mqWrinkleDepth > 0.0 && wrinkleFade > 0.0) {
      vec3 across = mqWrinkle.xyz / directed;
      float ratio = mqWrinkle.w;
      float t = clamp(2.0 * mqWrinkleLambda * (1.0 / (1.0 + ratio * ratio) - 1.0) + 1.0, 0.0, 1.0);
      float k = 6.2831853 / spacing;
      slope += 1e-3 * mqWrinkleDepth * t * wrinkleFade * 0.5 * k * sin(k * mqWrinklePhase) * across;
    }
    vec3 Nb = N;
    if (slope != vec3(0.0)) {
      float dhx = dot(slope, dRdx), dhy = dot(slope, dRdy);
      vec3 r1 = cross(dPdy, N), r2 = cross(N, dPdx);
      float det = dot(dPdx, r1);
      if (abs(det) > 1e-30) Nb = normalize(N - (dhx * r1 + dhy * r2) / det);
    }
    // Scattering blurs the relief out of the diffuse light more than out of
    // the specular one (Penner: bumps smaller than the scatter radius fade).
    vec3 Nd = normalize(mix(N, Nb, 0.4));
)";
const char* kAlbedoConstant = "    vec3 albedo = pow(mqAlbedo, vec3(2.2));\n";
const char* kAlbedoMapped = "    vec3 albedo = pow(mqAlbedo, vec3(2.2)) * texture(mqAlbedoMap, mqUV).rgb;\n";
const char* kSkinLightEnd = R"(
    float skyward = 0.5 + 0.5 * dot(Nd, mqUpVC);
    vec3 colour = mqAmbient * albedo * mix(vec3(0.10, 0.085, 0.07), vec3(0.20, 0.23, 0.28), skyward);
    // The table's row: curvature (1/mm) on a square-root axis, texel centres.
    float curvature = mqCurvature * mqRadiusScale;
    float lutV = (0.5 + sqrt(clamp(curvature / mqLutMaxCurvature, 0.0, 1.0)) * (mqLutSize.y - 1.0)) / mqLutSize.y;
    vec3 through = mqTranslucency * exp(-mqThickness / (mqMeanFreePath * mqRadiusScale));
    vec3 rimLight = vec3(0.0);
    for (int i = 0; i < mqLightCount; ++i) {
      vec3 L = mqLightDirVC[i];
      vec3 C = mqLightColour[i];
      float NdL = clamp(dot(Nd, L), -1.0, 1.0);
      vec3 scattered = texture(mqSkinLut, vec2((0.5 + 0.5 * (NdL + 1.0) * (mqLutSize.x - 1.0)) / mqLutSize.x, lutV)).rgb;
      vec3 translucent = through * clamp(0.3 + dot(L, -N), 0.0, 1.0);
      // Kelemen/Szirmay-Kalos: PH F / |L + V|^2 (unnormalised half vector).
      float spec = 0.0;
      float NbdL = dot(Nb, L);
      if (NbdL > 0.0) {
        vec3 h = L + V;
        vec3 H = normalize(h);
        float NdH = max(dot(Nb, H), 1e-3);
        float F = 0.028 + 0.972 * pow(1.0 - clamp(dot(H, V), 0.0, 1.0), 5.0);
        float PH = mqLobeMix * mqBeckmann(NdH, mqRoughness0) + (1.0 - mqLobeMix) * mqBeckmann(NdH, mqRoughness1);
        spec = NbdL * mqSpecular * PH * F / max(dot(h, h), 1e-4);
      }
      // Lights from behind mostly outline the silhouette (the rim below).
      float behind = clamp(0.25 - dot(L, V), 0.0, 1.0);
      colour += C * (albedo * (scattered * (1.0 - 0.6 * behind) + translucent) + vec3(spec));
      rimLight += C * behind * smoothstep(-0.2, 0.4, dot(N, L));
    }
)";

// A stable name for the look's scattering profile: one table per name.
std::string skinKey(const SurfaceLook& look) {
  if (!look.skinPreset.empty()) return look.skinPreset;
  char key[64];
  std::snprintf(key, sizeof key, "tone:%.5g:%.5g", look.melanin, look.hemoglobin);
  return key;
}

}  // namespace

optics::SkinOptics skinOpticsOf(const SurfaceLook& look) {
  if (!look.skinPreset.empty()) return optics::skinPreset(look.skinPreset);
  optics::SkinTone tone;
  tone.melanin = look.melanin;
  tone.hemoglobin = look.hemoglobin;
  return optics::skinFromTone(tone);
}

void applySkinShading(vtkActor* actor, const SurfaceLook& look, vtkTexture* albedoMap) {
  const optics::SkinOptics skin = skinOpticsOf(look);
  vtkTexture* lut = preintegratedSkinTexture(skinKey(look), skin);
  const optics::PreintegratedLutSettings& lutLayout = skinLutSettings();
  if (auto* mapper = SurfaceMapper::SafeDownCast(actor->GetMapper())) {
    std::vector<std::pair<std::string, vtkSmartPointer<vtkTexture>>> samplers = {{"mqSkinLut", lut}};
    if (albedoMap) samplers.emplace_back("mqAlbedoMap", albedoMap);
    mapper->setSamplers(std::move(samplers));
  }
  vtkShaderProperty* sp = actor->GetShaderProperty();
  sp->ClearAllShaderReplacements();
  const std::string furrow = "#define MQ_FURROW " + std::to_string(kReliefFurrowWidth) + "\n";
  sp->AddVertexShaderReplacement("//VTK::Normal::Dec", true,
                                 std::string(kVertexDec) + (albedoMap ? kVertexAlbedoDec : ""), false);
  sp->AddVertexShaderReplacement("//VTK::Normal::Impl", true,
                                 std::string(kVertexImpl) + (albedoMap ? kVertexAlbedoImpl : ""), false);
  sp->AddFragmentShaderReplacement("//VTK::Normal::Dec", true,
                                   furrow + kFragmentDec + (albedoMap ? kFragmentAlbedoDec : ""), false);
  sp->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
                                   std::string(kSkinLightBegin) + (albedoMap ? kAlbedoMapped : kAlbedoConstant) +
                                       kSkinLightEnd + kRimLightAndOutputGlsl,
                                   false);
  vtkUniforms* u = sp->GetFragmentCustomUniforms();
  u->RemoveAllUniforms();  // the wood's, when switching looks
  setUniform3(u, "mqAlbedo", look.albedo);
  u->SetUniformf("mqAmbient", look.ambient);
  u->SetUniformf("mqTranslucency", look.translucency);
  u->SetUniformf("mqSpecular", look.specular);
  u->SetUniformf("mqRoughness0", look.roughness0);
  u->SetUniformf("mqRoughness1", look.roughness1);
  u->SetUniformf("mqLobeMix", look.lobeMix);
  u->SetUniformf("mqRim", look.rim);
  u->SetUniformf("mqRimPower", look.rimPower);
  u->SetUniformf("mqExposure", look.exposure);
  u->SetUniformf("mqRadiusScale", look.radiusScale);
  u->SetUniformf("mqMicroStrength", look.microStrength);
  u->SetUniformf("mqMicroScale", look.microScale);
  u->SetUniformf("mqWrinkleDepth", look.wrinkleDepth);
  u->SetUniformf("mqWrinkleLambda", look.wrinkleLambda);
  u->SetUniformf("mqWrinkleSpacing", look.wrinkleSpacing);
  const optics::Rgb mfp = skin.diffuseMeanFreePath();
  setUniform3(u, "mqMeanFreePath", glm::vec3(mfp[0], mfp[1], mfp[2]));
  const float lutSize[2] = {float(lutLayout.width), float(lutLayout.height)};
  u->SetUniform2f("mqLutSize", lutSize);
  u->SetUniformf("mqLutMaxCurvature", float(lutLayout.maxCurvature));
  declareViewLightUniforms(u);
  u->SetUniformf("mqPixelAngle", 0.0f);
}

}  // namespace mq::render
