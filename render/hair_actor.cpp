#include "render/hair_actor.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

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
#include <vtkRenderer.h>
#include <vtkShader.h>
#include <vtkShaderProperty.h>
#include <vtkSmartPointer.h>
#include <vtkUniforms.h>

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

// Runs after VTK's own lighting and replaces its result.
const char* kFragmentImpl = R"(//VTK::Light::Impl
  {
    vec3 T = normalize(hairTangentVC);
    vec3 V = normalize(-vertexVC.xyz);
    // The point normals carry the hair volume's outward direction (VTK
    // lights lines only when they have normals, and passes them in VC).
    float volumeLength = length(normalVCVSOutput);
    vec3 volumeNormal = volumeLength > 1e-4 ? normalVCVSOutput / volumeLength : V;
    float along = hairParams.x;
    float shadow = hairParams.y;
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
    // Thinner towards the tip: screen-door transparency (no sorting needed).
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

// ---- The mapper: per frame, lights into uniforms and shadows refreshed ----

class HairMapper : public vtkOpenGLPolyDataMapper {
 public:
  static HairMapper* New();
  vtkTypeMacro(HairMapper, vtkOpenGLPolyDataMapper);
  std::function<void(vtkRenderer*, vtkActor*)> beforeRender;

  void RenderPiece(vtkRenderer* renderer, vtkActor* actor) override {
    if (beforeRender) beforeRender(renderer, actor);
    vtkOpenGLPolyDataMapper::RenderPiece(renderer, actor);
  }
};
vtkStandardNewMacro(HairMapper);

// ---- HairActor ----

struct HairActor::Impl {
  HairShading shading;
  Strands strands;
  vtkNew<vtkPolyData> polyData;
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> tangents, volumeNormals, params;
  vtkNew<HairMapper> mapper;
  vtkNew<vtkActor> actor;
  glm::vec3 shadowLight{0.0f};  // direction the shadow term was computed for
  bool shadowDirty = true;

  Impl();
  void installShaders();
  void updateUniforms();
  void updateGeometry();
  void updateShadow(const glm::vec3& towardLight);
};

HairActor::Impl::Impl() {
  tangents->SetName("hairTangent");
  tangents->SetNumberOfComponents(3);
  volumeNormals->SetName("hairVolumeNormal");  // set as the point normals
  volumeNormals->SetNumberOfComponents(3);
  params->SetName("hairParams");
  params->SetNumberOfComponents(3);
  points->SetDataTypeToFloat();
  polyData->SetPoints(points);
  polyData->GetPointData()->AddArray(tangents);
  polyData->GetPointData()->SetNormals(volumeNormals);
  polyData->GetPointData()->AddArray(params);
  mapper->SetInputData(polyData);
  mapper->ScalarVisibilityOff();
  mapper->MapDataArrayToVertexAttribute("hairTangentMC", "hairTangent", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  mapper->MapDataArrayToVertexAttribute("hairParamsMC", "hairParams", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  mapper->beforeRender = [this](vtkRenderer* renderer, vtkActor*) {
    const LightSet lights = gatherLights(renderer);
    vtkUniforms* uniforms = actor->GetShaderProperty()->GetFragmentCustomUniforms();
    uniforms->SetUniformi("hairLightCount", lights.count);
    uniforms->SetUniform3fv("hairLightDirVC", kMaxLights, lights.directionVC);
    uniforms->SetUniform3fv("hairLightColor", kMaxLights, lights.color);
    if (shading.selfShadowing && (shadowDirty || glm::dot(shadowLight, lights.keyTowardLightWorld) < 0.9986f))
      updateShadow(lights.keyTowardLightWorld);  // refreshed when the key light turned by > 3 degrees
  };
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLineWidth(1.0f);  // wider lines go through a geometry shader that drops our varyings
  actor->GetProperty()->LightingOn();
  actor->PickableOff();
  installShaders();
  updateUniforms();
}

void HairActor::Impl::installShaders() {
  vtkShaderProperty* sp = actor->GetShaderProperty();
  sp->AddVertexShaderReplacement("//VTK::Normal::Dec", true, kVertexDec, false);
  sp->AddVertexShaderReplacement("//VTK::Light::Impl", true, kVertexImpl, false);
  sp->AddFragmentShaderReplacement("//VTK::Normal::Dec", true, kFragmentDec, false);
  sp->AddFragmentShaderReplacement("//VTK::Light::Impl", true, kFragmentImpl, false);
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
  // Declared here so the first frame's shader has them before the lights are read.
  const float zeros[kMaxLights][3] = {};
  u->SetUniformi("hairLightCount", 0);
  u->SetUniform3fv("hairLightDirVC", kMaxLights, zeros);
  u->SetUniform3fv("hairLightColor", kMaxLights, zeros);
}

namespace {
glm::vec3 load(const std::vector<float>& a, size_t i) { return {a[3 * i], a[3 * i + 1], a[3 * i + 2]}; }

// A stable per-strand random number in [0, 1).
float strandRandom(size_t s) {
  uint32_t x = uint32_t(s) * 747796405u + 2891336453u;
  x = ((x >> ((x >> 28u) + 4u)) ^ x) * 277803737u;
  return float((x >> 22u) ^ x) / 4294967296.0f;
}
}  // namespace

// Points, tangents (central differences) and the volume normal (away from
// the centroid of all the hair: which side of the hair volume a point is on).
void HairActor::Impl::updateGeometry() {
  const int n = strands.pointsPerStrand;
  const size_t count = strands.strandCount() * size_t(std::max(n, 0));
  points->SetNumberOfPoints(vtkIdType(count));
  tangents->SetNumberOfTuples(vtkIdType(count));
  volumeNormals->SetNumberOfTuples(vtkIdType(count));
  params->SetNumberOfTuples(vtkIdType(count));
  if (count == 0) {
    polyData->Modified();
    return;
  }
  glm::dvec3 sum(0.0);
  for (size_t k = 0; k < count; ++k) sum += glm::dvec3(load(strands.points, k));
  const glm::vec3 centroid = glm::vec3(sum / double(count));
  float* p = static_cast<vtkFloatArray*>(points->GetData())->GetPointer(0);
  std::copy(strands.points.begin(), strands.points.begin() + 3 * count, p);
  float* t = tangents->GetPointer(0);
  float* v = volumeNormals->GetPointer(0);
  float* q = params->GetPointer(0);
  ThreadPool::shared().parallelFor(0, strands.strandCount(), 256, [&](size_t begin, size_t end) {
    for (size_t s = begin; s < end; ++s) {
      const size_t base = s * n;
      const float random = strandRandom(s);
      for (int i = 0; i < n; ++i) {
        const size_t k = base + i;
        const glm::vec3 ahead = load(strands.points, base + std::min(i + 1, n - 1));
        const glm::vec3 behind = load(strands.points, base + std::max(i - 1, 0));
        glm::vec3 tangent = ahead - behind;
        const float len = glm::length(tangent);
        tangent = len > 1e-12f ? tangent / len : glm::vec3(0.0f, -1.0f, 0.0f);
        glm::vec3 outward = load(strands.points, k) - centroid;
        const float outLen = glm::length(outward);
        outward = outLen > 1e-12f ? outward / outLen : glm::vec3(0.0f);
        for (int c = 0; c < 3; ++c) {
          t[3 * k + c] = tangent[c];
          v[3 * k + c] = outward[c];
        }
        q[3 * k] = n > 1 ? float(i) / float(n - 1) : 0.0f;
        if (shadowDirty || !shading.selfShadowing) q[3 * k + 1] = 1.0f;
        q[3 * k + 2] = random;
      }
    }
  });
  points->Modified();
  tangents->Modified();
  volumeNormals->Modified();
  params->Modified();
  polyData->Modified();
}

void HairActor::Impl::updateShadow(const glm::vec3& towardLight) {
  const std::vector<float> shadow = computeSelfShadow(strands, towardLight, shading);
  float* q = params->GetPointer(0);
  for (size_t k = 0; k < shadow.size() && vtkIdType(k) < params->GetNumberOfTuples(); ++k) q[3 * k + 1] = shadow[k];
  params->Modified();
  polyData->Modified();
  shadowLight = towardLight;
  shadowDirty = false;
}

HairActor::HairActor() : impl_(std::make_unique<Impl>()) {}
HairActor::~HairActor() = default;

vtkActor* HairActor::actor() { return impl_->actor; }

void HairActor::setStrands(const Strands& strands) {
  impl_->strands = strands;
  const int n = strands.pointsPerStrand;
  vtkNew<vtkCellArray> lines;
  if (n >= 2) {
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfValues(vtkIdType(strands.strandCount() + 1));
    connectivity->SetNumberOfValues(vtkIdType(strands.strandCount() * n));
    for (size_t s = 0; s <= strands.strandCount(); ++s) offsets->SetValue(vtkIdType(s), vtkIdType(s * n));
    for (size_t k = 0; k < strands.strandCount() * n; ++k) connectivity->SetValue(vtkIdType(k), vtkIdType(k));
    lines->SetData(offsets, connectivity);
  }
  impl_->polyData->SetLines(lines);
  impl_->shadowDirty = true;
  impl_->updateGeometry();
}

void HairActor::updatePositions(const std::vector<float>& points) {
  if (points.size() != impl_->strands.points.size()) return;
  impl_->strands.points = points;
  impl_->shadowDirty = true;
  impl_->updateGeometry();
}

void HairActor::setColors(const glm::vec3& root, const glm::vec3& tip) {
  impl_->shading.rootColor = root;
  impl_->shading.tipColor = tip;
  impl_->updateUniforms();
  impl_->actor->Modified();
}

void HairActor::setShading(const HairShading& shading) {
  const bool shadowChanged = shading.selfShadowing != impl_->shading.selfShadowing ||
                             shading.shadowMethod != impl_->shading.shadowMethod ||
                             shading.opacityMapCount != impl_->shading.opacityMapCount ||
                             shading.shadowPerStrand != impl_->shading.shadowPerStrand ||
                             shading.shadowCellSize != impl_->shading.shadowCellSize ||
                             shading.minShadow != impl_->shading.minShadow;
  impl_->shading = shading;
  impl_->updateUniforms();
  if (shadowChanged) {
    impl_->shadowDirty = true;
    impl_->updateGeometry();
  }
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
