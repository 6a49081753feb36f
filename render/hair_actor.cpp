#include "render/hair_actor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMatrix4x4.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShader.h>
#include <vtkShaderProperty.h>
#include <vtkSmartPointer.h>
#include <vtkUniforms.h>

#include "core/optics/hair_bsdf.h"
#include "core/util/thread_pool.h"

namespace mq::render {

namespace {

constexpr int kMaxLights = 4;

// ---- Shader replacements ----

const char* kVertexDec = R"(//VTK::Normal::Dec
in vec3 hairTangentMC;
in vec3 hairParamsMC;
out vec3 hairTangentVC;
out vec3 hairParams;
)";

const char* kVertexImpl = R"(//VTK::Light::Impl
  hairTangentVC = (MCVCMatrix * vec4(hairTangentMC, 0.0)).xyz;
  hairParams = hairParamsMC;
)";

const char* kFragmentDec = R"(//VTK::Normal::Dec
in vec3 hairTangentVC;
in vec3 hairParams;  // x: 0 root .. 1 tip, y: self-shadow, z: per-strand random
)";

// Both models' fragment code runs after VTK's own lighting and replaces its
// result: this frame of the fibre first, their lighting, then the tip fade.
const char* kFibreFrame = R"(//VTK::Light::Impl
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
const char* kTipFade = R"(
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
const char* kKajiyaKayLighting = R"(
    vec3 base = mix(hairRootColor, hairTipColor, along) * (1.0 + hairColorVariation * (2.0 * hairParams.z - 1.0));
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
    for (int i = 0; i < hairLightCount; ++i) {
      vec3 L = hairLightDirVC[i];
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
      color += hairLightColor[i] * shadow * facing * lit;
    }
)";

// The physically based fibre (core/optics/hair_bsdf.h), per light:
//   S = sum_p M_p(theta_i, theta_o - 2 alpha_p) Nbar_p(phi, |sin theta_o|) + M_3 Abar_3 / 2 pi
// M_p in the shader (hairLongitudinal: hair_bsdf.cpp's, in floats, always
// through logarithms), Nbar_p from the core's table (hairAzimuthalTable).
// The table's size is in kTablePhi, kTableTheta below.
constexpr int kTablePhi = 32, kTableTheta = 8;

std::string physicalFragmentDec() {
  return std::string(R"(//VTK::Normal::Dec
in vec3 hairTangentVC;
in vec3 hairParams;  // x: 0 root .. 1 tip, y: self-shadow, z: per-strand random
const int kHairPhi = )") + std::to_string(kTablePhi) + R"(;
const int kHairTheta = )" + std::to_string(kTableTheta) + R"(;
// log I0(x): the series below 12, the asymptotic series above.
float hairLogI0(float x) {
  if (x > 12.0) {
    float y = 1.0 / x;
    return x - 0.5 * log(6.2831853 * x) + log(1.0 + y * (0.125 + y * (0.0703125 + y * 0.0732421875)));
  }
  float q = 0.25 * x * x, term = 1.0, sum = 1.0;
  for (int k = 1; k < 18; ++k) {
    term *= q / float(k * k);
    sum += term;
  }
  return log(sum);
}
// d'Eon's M: csch(1/v) / (2v) exp(-sin_i sin_o / v) I0(cos_i cos_o / v).
float hairLongitudinal(float sinI, float cosI, float sinO, float cosO, float v) {
  float logNorm = v > 0.1 ? -log(2.0 * v * sinh(1.0 / v)) : -1.0 / v + 0.6931472 - log(2.0 * v);
  return exp(hairLogI0(cosI * cosO / v) - sinI * sinO / v + logNorm);
}
// Nbar_p, bilinear in (phi in [0, pi], |sin theta_o| in [0, 1]).
vec3 hairAzimuthalAt(int p, float phi, float sinO) {
  float x = phi * 0.31830989 * float(kHairPhi - 1), y = sinO * float(kHairTheta - 1);
  int k = min(int(x), kHairPhi - 2), t = min(int(y), kHairTheta - 2);
  float fx = x - float(k), fy = y - float(t);
  int i = (p * kHairTheta + t) * kHairPhi + k;
  return mix(mix(hairAzimuthalTable[i], hairAzimuthalTable[i + 1], fx),
             mix(hairAzimuthalTable[i + kHairPhi], hairAzimuthalTable[i + kHairPhi + 1], fx), fy);
}
vec3 hairResidualAt(float sinO) {
  float y = sinO * float(kHairTheta - 1);
  int t = min(int(y), kHairTheta - 2);
  return mix(hairResidualTable[t], hairResidualTable[t + 1], y - float(t));
}
)";
}

const char* kPhysicalLighting = R"(
    float sinO = clamp(dot(V, T), -1.0, 1.0);
    float cosO = sqrt(max(0.0, 1.0 - sinO * sinO));
    vec3 Vp = V - sinO * T;
    // Ambient: light from all around, times the share the fibre sends back.
    vec3 color = hairAmbient * hairAlbedo;
    for (int i = 0; i < hairLightCount; ++i) {
      vec3 L = hairLightDirVC[i];
      float sinI = clamp(dot(L, T), -1.0, 1.0);
      float cosI = sqrt(max(0.0, 1.0 - sinI * sinI));
      vec3 Lp = L - sinI * T;
      float across = length(Lp) * length(Vp);
      float phi = across > 1e-6 ? acos(clamp(dot(Lp, Vp) / across, -1.0, 1.0)) : 0.0;
      vec3 S = vec3(0.0);
      for (int p = 0; p < 3; ++p) {
        float sinOp = sinO * hairShiftCos[p] - cosO * hairShiftSin[p];
        float cosOp = abs(cosO * hairShiftCos[p] + sinO * hairShiftSin[p]);
        S += hairLobeWeight[p] * hairLongitudinal(sinI, cosI, sinOp, cosOp, hairVariance[p]) *
             hairAzimuthalAt(p, phi, abs(sinO));
      }
      S += hairLobeWeight[3] * hairLongitudinal(sinI, cosI, sinO, cosO, hairVariance[3]) *
           hairResidualAt(abs(sinO)) * 0.15915494;
      // Light reaching this side of the hair volume, as for Kajiya-Kay.
      // VTK's lights give a white Lambertian surface the radiance E cos,
      // which is pi times the physical E cos / pi: S takes the same pi.
      // The volume term stands for light scattered between fibres.
      float facing = clamp(0.55 + 0.45 * dot(volumeNormal, L), 0.0, 1.0);
      color += hairLightColor[i] * shadow * facing * (3.14159265 * S + hairLobeWeight4 * hairVolumeAlbedo);
    }
    color *= 1.0 + hairColorVariation * (2.0 * hairParams.z - 1.0);
)";

// ---- Lights ----

struct LightSet {
  int count = 0;
  float directionVC[kMaxLights][3] = {};
  float color[kMaxLights][3] = {};
  glm::vec3 keyTowardLightWorld{0.0f, 1.0f, 0.0f};
};

glm::vec3 toGlm(const double v[3]) { return {float(v[0]), float(v[1]), float(v[2])}; }

// Directions toward the renderer's lights in view coordinates, and the key
// light's in world coordinates (for self-shadowing).
LightSet gatherLights(vtkRenderer* renderer) {
  LightSet set;
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();
  glm::mat3 viewFromWorld(1.0f);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) viewFromWorld[c][r] = float(view->GetElement(r, c));
  const glm::mat3 worldFromView = glm::transpose(viewFromWorld);
  float strongest = -1.0f;
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem()) {
    if (!light->GetSwitch() || set.count >= kMaxLights) continue;
    glm::vec3 towardVC;
    if (light->LightTypeIsHeadlight()) {
      towardVC = {0.0f, 0.0f, 1.0f};
    } else if (light->LightTypeIsCameraLight()) {
      // Camera-light space has the camera at (0, 0, 1) looking at the
      // origin: its axes are the view axes.
      towardVC = toGlm(light->GetPosition()) - toGlm(light->GetFocalPoint());
    } else {
      towardVC = viewFromWorld * (toGlm(light->GetPosition()) - toGlm(light->GetFocalPoint()));
    }
    if (glm::length(towardVC) < 1e-9f) continue;
    towardVC = glm::normalize(towardVC);
    const float intensity = float(light->GetIntensity());
    const glm::vec3 color = toGlm(light->GetDiffuseColor()) * intensity;
    for (int k = 0; k < 3; ++k) {
      set.directionVC[set.count][k] = towardVC[k];
      set.color[set.count][k] = color[k];
    }
    ++set.count;
    // The key for shadows: strong and from the viewer's side (a rim light
    // behind the hair would put everything the viewer sees in shadow).
    const float score = intensity * (0.2f + std::max(towardVC.z, 0.0f));
    if (score > strongest) {
      strongest = score;
      set.keyTowardLightWorld = glm::normalize(worldFromView * towardVC);
    }
  }
  return set;
}

// Light-aligned frame: w toward the light, (u, v) across its rays.
struct LightFrame {
  glm::vec3 u, v, w;
};
LightFrame lightFrame(const glm::vec3& towardLight) {
  const glm::vec3 w = glm::normalize(towardLight);
  const glm::vec3 helper = std::abs(w.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 u = glm::normalize(glm::cross(helper, w));
  return {u, glm::cross(w, u), w};
}

}  // namespace

// ---- Geometry: built on any thread, shown on the GUI thread ----

namespace {

// One drawable part of the hair; the poly data is assembled from the arrays.
struct StrandArrays {
  vtkSmartPointer<vtkPoints> points;
  vtkSmartPointer<vtkCellArray> lines;
  vtkSmartPointer<vtkFloatArray> tangents, volumeNormals, params;
  vtkSmartPointer<vtkPolyData> polyData;
};

}  // namespace

// The strands in interleaved chunks: chunk c holds strands c, c + C, c + 2C,
// ... of C chunks, so the first chunks drawn are an even sample of the hair.
struct HairGeometry {
  std::shared_ptr<const Strands> strands;
  std::vector<StrandArrays> chunks;
  // What the shadow term was computed for (no light: lit everywhere), and
  // whether the strands moved since.
  std::optional<glm::vec3> shadowLight;
  HairShading shadowShading;
  bool shadowStale = false;
};

namespace {

// The render window asks for more frames a second than this only during an
// interaction (VTK's interactor sets 15 then, 0.0001 when still).
constexpr double kInteractiveUpdateRate = 1.0;

glm::vec3 load(const std::vector<float>& a, size_t i) { return {a[3 * i], a[3 * i + 1], a[3 * i + 2]}; }

// A stable per-strand random number in [0, 1).
float strandRandom(size_t s) {
  uint32_t x = uint32_t(s) * 747796405u + 2891336453u;
  x = ((x >> ((x >> 28u) + 4u)) ^ x) * 277803737u;
  return float((x >> 22u) ^ x) / 4294967296.0f;
}

bool sameShadowSettings(const HairShading& a, const HairShading& b) {
  return a.selfShadowing == b.selfShadowing && a.shadowMethod == b.shadowMethod &&
         a.opacityMapCount == b.opacityMapCount && a.shadowPerStrand == b.shadowPerStrand &&
         a.shadowCellSize == b.shadowCellSize && a.minShadow == b.minShadow;
}

// The geometry's shadow term is the one `shading` and a key light from
// `towardLight` ask for (within 3 degrees).
bool shadowCurrent(const HairGeometry& geometry, const HairShading& shading, const glm::vec3& towardLight) {
  if (!shading.selfShadowing) return !geometry.shadowLight;
  return geometry.shadowLight && !geometry.shadowStale && sameShadowSettings(geometry.shadowShading, shading) &&
         glm::dot(*geometry.shadowLight, towardLight) >= 0.9986f;
}

size_t chunkCountFor(size_t strands) {
  return std::max<size_t>(1, (strands + HairActor::kStrandsPerChunk - 1) / HairActor::kStrandsPerChunk);
}

// Strands first, first + stride, ... below `strands`.
size_t takenCount(size_t strands, size_t first, size_t stride) {
  return strands > first ? (strands - first + stride - 1) / stride : 0;
}

vtkSmartPointer<vtkFloatArray> newPointArray(const char* name, size_t points) {
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(vtkIdType(points));
  return array;
}

// Polylines of n consecutively numbered points each.
vtkSmartPointer<vtkCellArray> consecutiveLines(size_t strands, int n) {
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  if (n < 2 || strands == 0) return lines;
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(vtkIdType(strands + 1));
  connectivity->SetNumberOfValues(vtkIdType(strands * n));
  vtkIdType* o = offsets->GetPointer(0);
  for (size_t s = 0; s <= strands; ++s) o[s] = vtkIdType(s * n);
  vtkIdType* c = connectivity->GetPointer(0);
  for (size_t k = 0; k < strands * size_t(n); ++k) c[k] = vtkIdType(k);
  lines->SetData(offsets, connectivity);
  return lines;
}

glm::vec3 centroidOf(const Strands& strands) {
  const size_t count = strands.points.size() / 3;
  glm::dvec3 sum(0.0);
  for (size_t k = 0; k < count; ++k) sum += glm::dvec3(load(strands.points, k));
  return count ? glm::vec3(sum / double(count)) : glm::vec3(0.0f);
}

// Parameters of strands first, first + stride, ...: x 0 at the root .. 1 at
// the tip, y the shadow term (1 without `shadow`), z the strand's random.
vtkSmartPointer<vtkFloatArray> strandParams(const Strands& strands, size_t first, size_t stride,
                                            const std::vector<float>& shadow) {
  const int n = std::max(strands.pointsPerStrand, 0);
  const size_t taken = takenCount(strands.strandCount(), first, stride);
  auto params = newPointArray("hairParams", taken * n);
  float* q = params->GetPointer(0);
  for (size_t j = 0; j < taken; ++j) {
    const size_t s = first + j * stride;
    const float random = strandRandom(s);
    for (int i = 0; i < n; ++i) {
      const size_t k = j * n + i;
      q[3 * k] = n > 1 ? float(i) / float(n - 1) : 0.0f;
      q[3 * k + 1] = shadow.empty() ? 1.0f : shadow[s * n + i];
      q[3 * k + 2] = random;
    }
  }
  return params;
}

void assemble(StrandArrays& arrays) {
  arrays.polyData = vtkSmartPointer<vtkPolyData>::New();
  arrays.polyData->SetPoints(arrays.points);
  arrays.polyData->SetLines(arrays.lines);
  arrays.polyData->GetPointData()->AddArray(arrays.tangents);
  arrays.polyData->GetPointData()->SetNormals(arrays.volumeNormals);
  arrays.polyData->GetPointData()->AddArray(arrays.params);
}

// Points, tangents (central differences) and volume normals (away from
// `centroid`: which side of the hair volume a point is on) of strands first,
// first + stride, ...; `lines` when the layout is known already.
StrandArrays strandArrays(const Strands& strands, size_t first, size_t stride, const glm::vec3& centroid,
                          vtkSmartPointer<vtkFloatArray> params, vtkSmartPointer<vtkCellArray> lines = nullptr) {
  const int n = std::max(strands.pointsPerStrand, 0);
  const size_t taken = takenCount(strands.strandCount(), first, stride);
  const size_t count = taken * size_t(n);
  StrandArrays arrays;
  arrays.points = vtkSmartPointer<vtkPoints>::New();
  arrays.points->SetDataTypeToFloat();
  arrays.points->SetNumberOfPoints(vtkIdType(count));
  arrays.tangents = newPointArray("hairTangent", count);
  arrays.volumeNormals = newPointArray("hairVolumeNormal", count);  // set as the point normals
  arrays.params = std::move(params);
  arrays.lines = lines ? lines : consecutiveLines(taken, n);
  float* p = static_cast<vtkFloatArray*>(arrays.points->GetData())->GetPointer(0);
  float* t = arrays.tangents->GetPointer(0);
  float* v = arrays.volumeNormals->GetPointer(0);
  for (size_t j = 0; j < taken; ++j) {
    const size_t base = (first + j * stride) * n;  // the strand's first point in `strands`
    for (int i = 0; i < n; ++i) {
      const size_t k = j * n + i;
      const glm::vec3 point = load(strands.points, base + i);
      const glm::vec3 ahead = load(strands.points, base + std::min(i + 1, n - 1));
      const glm::vec3 behind = load(strands.points, base + std::max(i - 1, 0));
      glm::vec3 tangent = ahead - behind;
      const float len = glm::length(tangent);
      tangent = len > 1e-12f ? tangent / len : glm::vec3(0.0f, -1.0f, 0.0f);
      glm::vec3 outward = point - centroid;
      const float outLen = glm::length(outward);
      outward = outLen > 1e-12f ? outward / outLen : glm::vec3(0.0f);
      for (int c = 0; c < 3; ++c) {
        p[3 * k + c] = point[c];
        t[3 * k + c] = tangent[c];
        v[3 * k + c] = outward[c];
      }
    }
  }
  assemble(arrays);
  return arrays;
}

// The chunks of `strands` (`layout`'s lines and parameters when given: the
// same strands moved).
std::vector<StrandArrays> strandChunks(const Strands& strands, const std::vector<float>& shadow,
                                       const std::vector<StrandArrays>* layout = nullptr) {
  const size_t chunkCount = chunkCountFor(strands.strandCount());
  const glm::vec3 centroid = centroidOf(strands);
  std::vector<StrandArrays> chunks(chunkCount);
  ThreadPool::shared().parallelFor(0, chunkCount, 1, [&](size_t begin, size_t end) {
    for (size_t c = begin; c < end; ++c)
      chunks[c] = layout ? strandArrays(strands, c, chunkCount, centroid, (*layout)[c].params, (*layout)[c].lines)
                         : strandArrays(strands, c, chunkCount, centroid, strandParams(strands, c, chunkCount, shadow));
  });
  return chunks;
}

}  // namespace

std::shared_ptr<const HairGeometry> HairActor::prepareGeometry(std::shared_ptr<const Strands> strands,
                                                               const HairShading& shading,
                                                               const std::optional<glm::vec3>& towardLight) {
  auto geometry = std::make_shared<HairGeometry>();
  geometry->shadowShading = shading;
  std::vector<float> shadow;
  if (shading.selfShadowing && towardLight) {
    shadow = computeSelfShadow(*strands, *towardLight, shading);
    geometry->shadowLight = *towardLight;
  }
  geometry->chunks = strandChunks(*strands, shadow);
  geometry->strands = std::move(strands);
  return geometry;
}

std::shared_ptr<const HairGeometry> HairActor::reshade(const std::shared_ptr<const HairGeometry>& geometry,
                                                       const HairShading& shading, const glm::vec3& towardLight) {
  auto reshaded = std::make_shared<HairGeometry>(*geometry);
  reshaded->shadowShading = shading;
  reshaded->shadowLight.reset();
  reshaded->shadowStale = false;
  std::vector<float> shadow;
  if (shading.selfShadowing) {
    shadow = computeSelfShadow(*geometry->strands, towardLight, shading);
    reshaded->shadowLight = towardLight;
  }
  const size_t chunkCount = reshaded->chunks.size();
  for (size_t c = 0; c < chunkCount; ++c) {
    StrandArrays& chunk = reshaded->chunks[c];
    chunk.params = strandParams(*geometry->strands, c, chunkCount, shadow);
    assemble(chunk);  // the other arrays shared
  }
  return reshaded;
}

size_t HairActor::strandCount(const HairGeometry& geometry) { return geometry.strands->strandCount(); }

// ---- The mapper: per frame, lights into uniforms, the shadow checked, the
// chunks drawn ----

class HairMapper : public vtkOpenGLPolyDataMapper {
 public:
  static HairMapper* New();
  vtkTypeMacro(HairMapper, vtkOpenGLPolyDataMapper);
  std::function<void(vtkRenderer*)> beforeRender;
  // One per chunk of the geometry shown (the extra ones, left from a larger
  // geometry, have an empty input).
  std::vector<vtkSmartPointer<vtkOpenGLPolyDataMapper>> chunkMappers;
  size_t chunkCount = 0;
  size_t nextChunk = 0;       // the first chunk not drawn in this frame yet
  size_t framesDrawn = 0;
  double frameBudgetMs = 0.0;  // 0: every chunk in every frame

  // A frame draws chunks from the first until the budget is spent (the
  // first chunk's wait includes what the frame drew before it); a frame
  // that does not erase (a continuation, see the header) draws the next
  // ones.
  void RenderPiece(vtkRenderer* renderer, vtkActor* actor) override {
    if (beforeRender) beforeRender(renderer);
    ++framesDrawn;
    if (renderer->GetErase()) nextChunk = 0;
    const auto start = std::chrono::steady_clock::now();
    while (nextChunk < chunkCount) {
      chunkMappers[nextChunk++]->RenderPiece(renderer, actor);
      if (frameBudgetMs <= 0.0) continue;
      renderer->GetRenderWindow()->WaitForCompletion();  // the drawing is done on the CPU: time it
      if (std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() >= frameBudgetMs)
        break;
    }
  }
  void ReleaseGraphicsResources(vtkWindow* window) override {
    for (auto& m : chunkMappers) m->ReleaseGraphicsResources(window);
    vtkOpenGLPolyDataMapper::ReleaseGraphicsResources(window);
  }
};
vtkStandardNewMacro(HairMapper);

// ---- HairActor ----

struct HairActor::Impl {
  HairShading shading;
  std::shared_ptr<const HairGeometry> geometry;
  vtkNew<vtkPolyData> empty;
  vtkNew<HairMapper> mapper;
  vtkNew<vtkActor> actor;
  std::optional<glm::vec3> keyLight;
  std::function<void()> requestReshade;
  // The fragment shader installed, and the fibre the physical uniforms hold.
  std::optional<HairShadingModel> installedModel;
  std::optional<std::pair<HairShadingParams, unsigned>> physicalUniformsFor;

  Impl();
  void installShaders();
  void updatePhysicalUniforms();
  void updateUniforms();
  void show(std::shared_ptr<const HairGeometry> shown);
  void beforeRender(vtkRenderer* renderer);
};

HairActor::Impl::Impl() {
  mapper->SetInputData(empty);  // bounds: the first chunk's, an even sample of the hair
  mapper->beforeRender = [this](vtkRenderer* renderer) { beforeRender(renderer); };
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLineWidth(1.0f);  // wider lines go through a geometry shader that drops our varyings
  actor->GetProperty()->LightingOn();
  actor->PickableOff();
  updateUniforms();  // installs the shaders
}

void HairActor::Impl::beforeRender(vtkRenderer* renderer) {
  const LightSet lights = gatherLights(renderer);
  vtkUniforms* uniforms = actor->GetShaderProperty()->GetFragmentCustomUniforms();
  uniforms->SetUniformi("hairLightCount", lights.count);
  uniforms->SetUniform3fv("hairLightDirVC", kMaxLights, lights.directionVC);
  uniforms->SetUniform3fv("hairLightColor", kMaxLights, lights.color);
  keyLight = lights.keyTowardLightWorld;
  // While the camera moves the shadow keeps its light: recomputing it for
  // every frame of an orbit (the key light turns with the camera) is what
  // made orbiting lag.
  const bool moving = renderer->GetRenderWindow()->GetDesiredUpdateRate() > kInteractiveUpdateRate;
  if (moving || !geometry || shadowCurrent(*geometry, shading, *keyLight)) return;
  if (requestReshade)
    requestReshade();
  else
    show(HairActor::reshade(geometry, shading, *keyLight));
}

void HairActor::Impl::show(std::shared_ptr<const HairGeometry> shown) {
  geometry = std::move(shown);
  const size_t count = geometry ? geometry->chunks.size() : 0;
  while (mapper->chunkMappers.size() < count) {
    auto m = vtkSmartPointer<vtkOpenGLPolyDataMapper>::New();
    m->ScalarVisibilityOff();
    m->MapDataArrayToVertexAttribute("hairTangentMC", "hairTangent", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    m->MapDataArrayToVertexAttribute("hairParamsMC", "hairParams", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    mapper->chunkMappers.push_back(m);
  }
  for (size_t c = 0; c < mapper->chunkMappers.size(); ++c)
    mapper->chunkMappers[c]->SetInputData(c < count ? geometry->chunks[c].polyData.Get() : empty.Get());
  mapper->chunkCount = count;
  mapper->nextChunk = 0;
  mapper->SetInputData(count ? geometry->chunks[0].polyData.Get() : empty.Get());
}

// The fragment shader of the shading's model (a change rebuilds the program).
void HairActor::Impl::installShaders() {
  const HairShadingModel model = shading.fibre.model;
  if (installedModel == model) return;
  vtkShaderProperty* sp = actor->GetShaderProperty();
  if (!installedModel) {
    sp->AddVertexShaderReplacement("//VTK::Normal::Dec", true, kVertexDec, false);
    sp->AddVertexShaderReplacement("//VTK::Light::Impl", true, kVertexImpl, false);
  }
  sp->ClearAllFragmentShaderReplacements();
  if (model == HairShadingModel::Physical) {
    sp->AddFragmentShaderReplacement("//VTK::Normal::Dec", true, physicalFragmentDec(), false);
    sp->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
                                     std::string(kFibreFrame) + kPhysicalLighting + kTipFade, false);
  } else {
    sp->AddFragmentShaderReplacement("//VTK::Normal::Dec", true, kFragmentDec, false);
    sp->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
                                     std::string(kFibreFrame) + kKajiyaKayLighting + kTipFade, false);
  }
  installedModel = model;
}

// The fibre's table, lobe shifts and widths and mean albedo (recomputed when
// the pigments or the roughness change: a few milliseconds).
void HairActor::Impl::updatePhysicalUniforms() {
  if (shading.fibre.model != HairShadingModel::Physical) return;
  const auto key = std::make_pair(shading.fibre, shading.physicalLobes);
  if (physicalUniformsFor == key) return;
  physicalUniformsFor = key;
  optics::HairFibre fibre;
  fibre.sigmaA = optics::hairSigmaAFromPigment({shading.fibre.melanin, shading.fibre.pheomelanin});
  fibre.longitudinalRoughness = fibre.azimuthalRoughness = std::clamp(double(shading.fibre.roughness), 0.05, 1.0);
  const optics::HairAzimuthalTable table = optics::hairAzimuthalTable(fibre, kTablePhi, kTableTheta);
  std::vector<float> lobes(table.lobes.size() * 3), residual(table.residual.size() * 3);
  for (size_t k = 0; k < table.lobes.size(); ++k)
    for (int c = 0; c < 3; ++c) lobes[3 * k + c] = float(table.lobes[k][c]);
  for (size_t k = 0; k < table.residual.size(); ++k)
    for (int c = 0; c < 3; ++c) residual[3 * k + c] = float(table.residual[k][c]);
  const optics::Rgb albedo = optics::hairMeanAlbedo(fibre);
  const double v = optics::hairLongitudinalVariance(fibre.longitudinalRoughness);
  const double alpha = fibre.alphaDegrees * 3.14159265358979323846 / 180.0;
  const double shifts[3] = {alpha, -0.5 * alpha, -1.5 * alpha};  // alpha_R, alpha_TT, alpha_TRT
  float shiftSin[3], shiftCos[3];
  for (int p = 0; p < 3; ++p) {
    shiftSin[p] = float(std::sin(2.0 * shifts[p]));
    shiftCos[p] = float(std::cos(2.0 * shifts[p]));
  }
  const float variance[4] = {float(v), float(0.25 * v), float(4.0 * v), float(4.0 * v)};
  float lobeWeight[4];
  for (int p = 0; p < 4; ++p) lobeWeight[p] = (shading.physicalLobes >> p) & 1u ? 1.0f : 0.0f;
  const float albedoF[3] = {float(albedo[0]), float(albedo[1]), float(albedo[2])};
  const optics::Rgb volume = optics::hairVolumeReflectance(albedo);
  const float volumeF[3] = {float(volume[0]), float(volume[1]), float(volume[2])};
  vtkUniforms* u = actor->GetShaderProperty()->GetFragmentCustomUniforms();
  u->SetUniform3fv("hairAzimuthalTable", int(table.lobes.size()), reinterpret_cast<const float(*)[3]>(lobes.data()));
  u->SetUniform3fv("hairResidualTable", int(table.residual.size()), reinterpret_cast<const float(*)[3]>(residual.data()));
  u->SetUniform3f("hairShiftSin", shiftSin);
  u->SetUniform3f("hairShiftCos", shiftCos);
  u->SetUniform4f("hairVariance", variance);
  u->SetUniform4f("hairLobeWeight", lobeWeight);
  u->SetUniform3f("hairAlbedo", albedoF);
  u->SetUniform3f("hairVolumeAlbedo", volumeF);
  u->SetUniformf("hairLobeWeight4", (shading.physicalLobes >> 4) & 1u ? 1.0f : 0.0f);
}

void HairActor::Impl::updateUniforms() {
  vtkUniforms* u = actor->GetShaderProperty()->GetFragmentCustomUniforms();
  const float root[3] = {shading.rootColor.x, shading.rootColor.y, shading.rootColor.z};
  const float tip[3] = {shading.tipColor.x, shading.tipColor.y, shading.tipColor.z};
  u->SetUniform3f("hairRootColor", root);
  u->SetUniform3f("hairTipColor", tip);
  u->SetUniformf("hairColorVariation", shading.colorVariation);
  u->SetUniformf("hairDiffuse", shading.diffuse);
  u->SetUniformf("hairAmbient", shading.ambient);
  u->SetUniformf("hairPrimarySpecular", shading.primarySpecular);
  u->SetUniformf("hairPrimaryExponent", shading.primaryExponent);
  u->SetUniformf("hairPrimaryShift", shading.primaryShift);
  u->SetUniformf("hairSecondarySpecular", shading.secondaryHighlight ? shading.secondarySpecular : 0.0f);
  u->SetUniformf("hairSecondaryExponent", shading.secondaryExponent);
  u->SetUniformf("hairSecondaryShift", shading.secondaryShift);
  u->SetUniformf("hairTipOpacity", shading.tipOpacity);
  u->SetUniformf("hairTipFadeStart", shading.tipFadeStart);
  installShaders();
  updatePhysicalUniforms();
  // Declared here so the first frame's shader has them before the lights are read.
  const float zeros[kMaxLights][3] = {};
  u->SetUniformi("hairLightCount", 0);
  u->SetUniform3fv("hairLightDirVC", kMaxLights, zeros);
  u->SetUniform3fv("hairLightColor", kMaxLights, zeros);
}

HairActor::HairActor() : impl_(std::make_unique<Impl>()) {}
HairActor::~HairActor() = default;

vtkActor* HairActor::actor() { return impl_->actor; }

void HairActor::setStrands(const Strands& strands) {
  impl_->show(prepareGeometry(std::make_shared<const Strands>(strands), impl_->shading, impl_->keyLight));
}

// The shadow stays until the next still frame recomputes it (no flicker to
// lit and back while the strands move).
void HairActor::updatePositions(const std::vector<float>& points) {
  const std::shared_ptr<const HairGeometry>& old = impl_->geometry;
  if (!old || points.size() != old->strands->points.size()) return;
  auto strands = std::make_shared<Strands>();
  strands->pointsPerStrand = old->strands->pointsPerStrand;
  strands->points = points;
  auto moved = std::make_shared<HairGeometry>(*old);
  moved->shadowStale = true;
  moved->chunks = strandChunks(*strands, {}, &old->chunks);
  moved->strands = std::move(strands);
  impl_->show(std::move(moved));
}

void HairActor::showGeometry(std::shared_ptr<const HairGeometry> geometry) { impl_->show(std::move(geometry)); }

std::shared_ptr<const HairGeometry> HairActor::geometry() const { return impl_->geometry; }

std::optional<glm::vec3> HairActor::keyLight() const { return impl_->keyLight; }

glm::vec3 HairActor::keyLightOf(vtkRenderer* renderer) { return gatherLights(renderer).keyTowardLightWorld; }

void HairActor::setReshadeRequest(std::function<void()> request) { impl_->requestReshade = std::move(request); }

bool HairActor::hasMoreToDraw() const {
  return impl_->actor->GetVisibility() && impl_->mapper->nextChunk < impl_->mapper->chunkCount;
}

size_t HairActor::framesDrawn() const { return impl_->mapper->framesDrawn; }

void HairActor::setFrameBudget(double milliseconds) { impl_->mapper->frameBudgetMs = milliseconds; }

void HairActor::setColors(const glm::vec3& root, const glm::vec3& tip) {
  impl_->shading.rootColor = root;
  impl_->shading.tipColor = tip;
  impl_->updateUniforms();
  impl_->actor->Modified();
}

void HairActor::setFibre(const HairShadingParams& fibre) {
  impl_->shading.fibre = fibre;
  impl_->updateUniforms();
  impl_->actor->Modified();
}

// A change of the shadow settings is seen by the next frame (shadowCurrent).
void HairActor::setShading(const HairShading& shading) {
  impl_->shading = shading;
  impl_->updateUniforms();
  impl_->actor->Modified();
}

const HairShading& HairActor::shading() const { return impl_->shading; }

void HairActor::setVisible(bool visible) { impl_->actor->SetVisibility(visible); }

// ---- Self-shadowing on the CPU ----

std::vector<float> HairActor::computeSelfShadow(const Strands& strands, const glm::vec3& towardLight,
                                                const HairShading& shading) {
  if (shading.shadowMethod == HairShadowMethod::OpacityMaps)
    return computeOpacityMapShadow(strands, towardLight, shading);
  const size_t count = strands.points.size() / 3;
  std::vector<float> shadow(count, 1.0f);
  const int n = strands.pointsPerStrand;
  if (count == 0 || n < 2) return shadow;
  const auto [u, v, w] = lightFrame(towardLight);

  std::vector<glm::vec3> projected(count);  // (u, v, depth toward the light)
  glm::vec2 lo(1e30f), hi(-1e30f);
  double segmentSum = 0.0;
  for (size_t k = 0; k < count; ++k) {
    const glm::vec3 p = load(strands.points, k);
    projected[k] = {glm::dot(p, u), glm::dot(p, v), glm::dot(p, w)};
    lo = glm::min(lo, glm::vec2(projected[k]));
    hi = glm::max(hi, glm::vec2(projected[k]));
    if (k % n != 0) segmentSum += glm::length(p - load(strands.points, k - 1));
  }
  const float segment = float(segmentSum / double(count - count / n));
  float cell = std::max(shading.shadowCellSize, 1e-4f);
  const glm::vec2 extent = hi - lo;
  cell = std::max(cell, std::max(extent.x, extent.y) / 1024.0f);  // at most 1024 x 1024 columns
  const int columns = int(extent.x / cell) + 2, rows = int(extent.y / cell) + 2;

  // Counting sort of the points into columns, then each column by depth.
  std::vector<uint32_t> start(size_t(columns) * rows + 1, 0);
  auto columnOf = [&](float a, float b) {
    return size_t(int((b - lo.y) / cell)) * columns + size_t(int((a - lo.x) / cell));
  };
  for (size_t k = 0; k < count; ++k) ++start[columnOf(projected[k].x, projected[k].y) + 1];
  for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<float> depths(count);
  {
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t k = 0; k < count; ++k) depths[fill[columnOf(projected[k].x, projected[k].y)]++] = projected[k].z;
  }
  ThreadPool::shared().parallelFor(0, start.size() - 1, 1024, [&](size_t begin, size_t end) {
    for (size_t c = begin; c < end; ++c) std::sort(depths.begin() + start[c], depths.begin() + start[c + 1]);
  });

  // Points nearer the light than depth d in column (i, j).
  auto aheadIn = [&](int i, int j, float d) -> float {
    if (i < 0 || j < 0 || i >= columns || j >= rows) return 0.0f;
    const size_t c = size_t(j) * columns + size_t(i);
    const auto first = depths.begin() + start[c], last = depths.begin() + start[c + 1];
    return float(last - std::upper_bound(first, last, d + 1e-6f));
  };
  // A strand crossing a column leaves about cell / segment points in it.
  const float crossingsPerPoint = segment / cell;
  ThreadPool::shared().parallelFor(0, count, 4096, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      // Bilinear over the four nearest column centres: no blocky edges.
      const float a = (projected[k].x - lo.x) / cell - 0.5f, b = (projected[k].y - lo.y) / cell - 0.5f;
      const int i = int(std::floor(a)), j = int(std::floor(b));
      const float fa = a - float(i), fb = b - float(j);
      const float d = projected[k].z;
      const float ahead = (1 - fa) * (1 - fb) * aheadIn(i, j, d) + fa * (1 - fb) * aheadIn(i + 1, j, d) +
                          (1 - fa) * fb * aheadIn(i, j + 1, d) + fa * fb * aheadIn(i + 1, j + 1, d);
      const float transmitted = std::exp(-shading.shadowPerStrand * crossingsPerPoint * ahead);
      shadow[k] = std::max(shading.minShadow, transmitted);
    }
  });
  return shadow;
}

// Opacity shadow maps (Kim and Neumann, "Opacity Shadow Maps", 2001): the
// hair's depth range along the light is cut by `slices` maps; each point's
// density is splatted (bilinearly across the light's rays) into the slab
// between the two maps around it, a prefix sum along the light turns slabs
// into the opacity in front of each map, and a vertex reads the opacity in
// front of it by interpolating its two maps in depth and across the rays.
std::vector<float> HairActor::computeOpacityMapShadow(const Strands& strands, const glm::vec3& towardLight,
                                                      const HairShading& shading) {
  const size_t count = strands.points.size() / 3;
  std::vector<float> shadow(count, 1.0f);
  const int n = strands.pointsPerStrand;
  if (count == 0 || n < 2) return shadow;
  const auto [u, v, w] = lightFrame(towardLight);

  // (u, v, distance from the hair's front along the light).
  std::vector<glm::vec3> projected(count);
  glm::vec3 lo(1e30f), hi(-1e30f);
  double segmentSum = 0.0;
  for (size_t k = 0; k < count; ++k) {
    const glm::vec3 p = load(strands.points, k);
    projected[k] = {glm::dot(p, u), glm::dot(p, v), -glm::dot(p, w)};
    lo = glm::min(lo, projected[k]);
    hi = glm::max(hi, projected[k]);
    if (k % n != 0) segmentSum += glm::length(p - load(strands.points, k - 1));
  }
  const float segment = float(segmentSum / double(count - count / n));
  const glm::vec2 extent = glm::vec2(hi) - glm::vec2(lo);
  const float cell = std::max({shading.shadowCellSize, 1e-4f, std::max(extent.x, extent.y) / 384.0f});
  const int columns = int(extent.x / cell) + 2, rows = int(extent.y / cell) + 2;
  const int slices = std::clamp(shading.opacityMapCount, 2, 256);
  const float depthRange = std::max(hi.z - lo.z, 1e-6f);
  const float slab = depthRange / float(slices - 1);
  const size_t pixels = size_t(columns) * rows;

  // Map coordinates: (a, b) in pixels from the first pixel centre, s in slabs.
  struct Sample {
    int i, j, slice;
    float fa, fb, fs;
  };
  auto sampleOf = [&](const glm::vec3& q) {
    const float a = (q.x - lo.x) / cell - 0.5f, b = (q.y - lo.y) / cell - 0.5f, s = (q.z - lo.z) / slab;
    Sample m{int(std::floor(a)), int(std::floor(b)), std::min(int(s), slices - 2), 0, 0, 0};
    m.fa = a - float(m.i);
    m.fb = b - float(m.j);
    m.fs = std::clamp(s - float(m.slice), 0.0f, 1.0f);
    return m;
  };
  auto pixelIndex = [&](int i, int j) -> long {
    return i < 0 || j < 0 || i >= columns || j >= rows ? -1 : long(j) * columns + i;
  };

  // Slab densities: maps[slice * pixels + pixel] holds the points between
  // map `slice` and map `slice + 1`; after the prefix sum, the points in
  // front of map `slice`.
  std::vector<float> maps(size_t(slices) * pixels, 0.0f);
  for (size_t k = 0; k < count; ++k) {
    const Sample m = sampleOf(projected[k]);
    const float weights[4] = {(1 - m.fa) * (1 - m.fb), m.fa * (1 - m.fb), (1 - m.fa) * m.fb, m.fa * m.fb};
    const long corners[4] = {pixelIndex(m.i, m.j), pixelIndex(m.i + 1, m.j), pixelIndex(m.i, m.j + 1),
                             pixelIndex(m.i + 1, m.j + 1)};
    for (int c = 0; c < 4; ++c)
      if (corners[c] >= 0) maps[size_t(m.slice) * pixels + size_t(corners[c])] += weights[c];
  }
  ThreadPool::shared().parallelFor(0, pixels, 4096, [&](size_t begin, size_t end) {
    for (size_t p = begin; p < end; ++p) {
      float ahead = 0.0f;
      for (int s = 0; s < slices; ++s) {
        const float inSlab = maps[size_t(s) * pixels + p];
        maps[size_t(s) * pixels + p] = ahead;
        ahead += inSlab;
      }
    }
  });

  const float crossingsPerPoint = segment / cell;
  ThreadPool::shared().parallelFor(0, count, 4096, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      const Sample m = sampleOf(projected[k]);
      auto opacity = [&](int i, int j) {
        const long p = pixelIndex(i, j);
        if (p < 0) return 0.0f;
        return (1 - m.fs) * maps[size_t(m.slice) * pixels + size_t(p)] + m.fs * maps[size_t(m.slice + 1) * pixels + size_t(p)];
      };
      const float ahead = (1 - m.fa) * (1 - m.fb) * opacity(m.i, m.j) + m.fa * (1 - m.fb) * opacity(m.i + 1, m.j) +
                          (1 - m.fa) * m.fb * opacity(m.i, m.j + 1) + m.fa * m.fb * opacity(m.i + 1, m.j + 1);
      // The interpolation counts part of the vertex's own slab, itself
      // included: take its own share out (the exact count excludes it).
      const float own = m.fs * ((1 - m.fa) * (1 - m.fa) * (1 - m.fb) * (1 - m.fb) + m.fa * m.fa * (1 - m.fb) * (1 - m.fb) +
                                (1 - m.fa) * (1 - m.fa) * m.fb * m.fb + m.fa * m.fa * m.fb * m.fb);
      const float transmitted = std::exp(-shading.shadowPerStrand * crossingsPerPoint * std::max(0.0f, ahead - own));
      shadow[k] = std::max(shading.minShadow, transmitted);
    }
  });
  return shadow;
}

}  // namespace mq::render
