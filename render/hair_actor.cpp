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
#include "core/optics/hair_self_shadow.h"
#include "core/util/thread_pool.h"
#include "render/hair_shaders.h"
#include "render/view_lights.h"

namespace mq::render {

// ---- Geometry: built on any thread, shown on the GUI thread ----

namespace {

// One drawable part of the hair; the poly data is assembled from the arrays.
struct StrandArrays {
  vtkSmartPointer<vtkPoints> points;
  vtkSmartPointer<vtkCellArray> lines;
  vtkSmartPointer<vtkFloatArray> tangents, volumeNormals, params, tints;
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

// A point array `name` over strands first, first + stride, ...: point i of
// strand s gets value(s, i, n).
template <typename PointValue>
vtkSmartPointer<vtkFloatArray> perPointArray(const char* name, const Strands& strands, size_t first, size_t stride,
                                             PointValue value) {
  const int n = std::max(strands.pointsPerStrand, 0);
  const size_t taken = takenCount(strands.strandCount(), first, stride);
  auto array = newPointArray(name, taken * n);
  float* q = array->GetPointer(0);
  for (size_t j = 0; j < taken; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::vec3 v = value(first + j * stride, i, n);
      for (int c = 0; c < 3; ++c) q[3 * (j * n + i) + c] = v[c];
    }
  return array;
}

// Parameters of strands first, first + stride, ...: x 0 at the root .. 1 at
// the tip, y the shadow term (1 without `shadow`), z the strand's random.
vtkSmartPointer<vtkFloatArray> strandParams(const Strands& strands, size_t first, size_t stride,
                                            const std::vector<float>& shadow) {
  return perPointArray("hairParams", strands, first, stride, [&](size_t s, int i, int n) {
    return glm::vec3(n > 1 ? float(i) / float(n - 1) : 0.0f, shadow.empty() ? 1.0f : shadow[s * n + i],
                     strandRandom(s));
  });
}

// Per strand, its painted pigments' colour against the style's, per
// channel: the ratio of the fibres' mean albedos (hairMeanAlbedo). The
// lobes keep the style's shapes; the colour of what the pigments absorb
// follows the paint. Albedos on a 0.25 lattice of concentrations, computed
// where the paint needs them, interpolated between.
class PigmentTints {
 public:
  // Divided by the lattice's albedo at the style's pigments (not the exact
  // one), so an unpainted strand's tint is exactly 1.
  explicit PigmentTints(const HairShadingParams& style)
      : styleAlbedo_(glm::max(albedoAt(style.melanin, style.pheomelanin), glm::vec3(1e-4f))) {}

  glm::vec3 tint(float eumelanin, float pheomelanin) { return albedoAt(eumelanin, pheomelanin) / styleAlbedo_; }

 private:
  static constexpr float kStep = 0.25f;
  static constexpr int kNodes = 33;  // 0 .. 8

  glm::vec3 albedoAt(float eumelanin, float pheomelanin) {
    const float x = std::clamp(eumelanin / kStep, 0.0f, float(kNodes - 1));
    const float y = std::clamp(pheomelanin / kStep, 0.0f, float(kNodes - 1));
    const int i = std::min(int(x), kNodes - 2), j = std::min(int(y), kNodes - 2);
    const float fx = x - float(i), fy = y - float(j);
    const glm::vec3 a = glm::mix(node(i, j), node(i + 1, j), fx), b = glm::mix(node(i, j + 1), node(i + 1, j + 1), fx);
    return glm::mix(a, b, fy);
  }
  static glm::vec3 albedo(const optics::HairPigment& pigment) {
    optics::HairFibre fibre;
    fibre.sigmaA = optics::hairSigmaAFromPigment(pigment);
    const optics::Rgb a = optics::hairMeanAlbedo(fibre);
    return {float(a[0]), float(a[1]), float(a[2])};
  }
  const glm::vec3& node(int i, int j) {
    std::optional<glm::vec3>& n = nodes_[size_t(i * kNodes + j)];
    if (!n) n = albedo({kStep * i, kStep * j});
    return *n;
  }

  std::vector<std::optional<glm::vec3>> nodes_ = std::vector<std::optional<glm::vec3>>(kNodes * kNodes);
  glm::vec3 styleAlbedo_;
};

// Each strand's tint (3 floats), empty when none is painted.
std::vector<float> strandTints(const Strands& strands, const HairShadingParams& style) {
  const size_t count = strands.strandCount();
  if (strands.pigmentPaint.size() != 4 * count) return {};
  PigmentTints tints(style);
  std::vector<float> out(3 * count);
  for (size_t s = 0; s < count; ++s) {
    const auto [eumelanin, pheomelanin] = strands.pigments(s, style.melanin, style.pheomelanin);
    const glm::vec3 t = tints.tint(eumelanin, pheomelanin);
    for (int c = 0; c < 3; ++c) out[3 * s + c] = t[c];
  }
  return out;
}

// Tints of strands first, first + stride, ... per point (1 without `tints`).
vtkSmartPointer<vtkFloatArray> strandTintArray(const Strands& strands, size_t first, size_t stride,
                                               const std::vector<float>& tints) {
  return perPointArray("hairTint", strands, first, stride, [&](size_t s, int, int) {
    return tints.empty() ? glm::vec3(1.0f) : glm::vec3(tints[3 * s], tints[3 * s + 1], tints[3 * s + 2]);
  });
}

void assemble(StrandArrays& arrays) {
  arrays.polyData = vtkSmartPointer<vtkPolyData>::New();
  arrays.polyData->SetPoints(arrays.points);
  arrays.polyData->SetLines(arrays.lines);
  arrays.polyData->GetPointData()->AddArray(arrays.tangents);
  arrays.polyData->GetPointData()->SetNormals(arrays.volumeNormals);
  arrays.polyData->GetPointData()->AddArray(arrays.params);
  arrays.polyData->GetPointData()->AddArray(arrays.tints);
}

// Points, tangents (central differences) and volume normals (away from
// `centroid`: which side of the hair volume a point is on) of strands first,
// first + stride, ...; `lines` when the layout is known already.
StrandArrays strandArrays(const Strands& strands, size_t first, size_t stride, const glm::vec3& centroid,
                          vtkSmartPointer<vtkFloatArray> params, vtkSmartPointer<vtkFloatArray> tints,
                          vtkSmartPointer<vtkCellArray> lines = nullptr) {
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
  arrays.tints = std::move(tints);
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

// The chunks of `strands` (`layout`'s lines, parameters and tints when
// given: the same strands moved).
std::vector<StrandArrays> strandChunks(const Strands& strands, const std::vector<float>& shadow,
                                       const std::vector<float>& tints,
                                       const std::vector<StrandArrays>* layout = nullptr) {
  const size_t chunkCount = chunkCountFor(strands.strandCount());
  const glm::vec3 centroid = centroidOf(strands);
  std::vector<StrandArrays> chunks(chunkCount);
  ThreadPool::shared().parallelFor(0, chunkCount, 1, [&](size_t begin, size_t end) {
    for (size_t c = begin; c < end; ++c)
      chunks[c] = layout ? strandArrays(strands, c, chunkCount, centroid, (*layout)[c].params, (*layout)[c].tints,
                                        (*layout)[c].lines)
                         : strandArrays(strands, c, chunkCount, centroid, strandParams(strands, c, chunkCount, shadow),
                                        strandTintArray(strands, c, chunkCount, tints));
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
    shadow = optics::hairSelfShadow(*strands, *towardLight, shading.shadowSettings());
    geometry->shadowLight = *towardLight;
  }
  geometry->chunks = strandChunks(*strands, shadow, strandTints(*strands, shading.fibre));
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
    shadow = optics::hairSelfShadow(*geometry->strands, towardLight, shading.shadowSettings());
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
  size_t nextChunk = 0;  // the first chunk not drawn in this frame yet
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
  const ViewLights lights = gatherViewLights(renderer);
  setViewLightUniforms(actor->GetShaderProperty()->GetFragmentCustomUniforms(), lights);
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
    m->MapDataArrayToVertexAttribute("hairTintMC", "hairTint", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
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
    sp->AddVertexShaderReplacement("//VTK::Normal::Dec", true, kHairVertexDec, false);
    sp->AddVertexShaderReplacement("//VTK::Light::Impl", true, kHairVertexImpl, false);
  }
  sp->ClearAllFragmentShaderReplacements();
  if (model == HairShadingModel::Physical) {
    sp->AddFragmentShaderReplacement("//VTK::Normal::Dec", true, physicalHairFragmentDec(), false);
    sp->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
                                     std::string(kHairFibreFrame) + kPhysicalHairLighting + kHairTipFade, false);
  } else {
    sp->AddFragmentShaderReplacement("//VTK::Normal::Dec", true, kKajiyaKayFragmentDec, false);
    sp->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
                                     std::string(kHairFibreFrame) + kKajiyaKayLighting + kHairTipFade, false);
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
  u->SetUniform3fv("hairResidualTable", int(table.residual.size()),
                   reinterpret_cast<const float(*)[3]>(residual.data()));
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
  declareViewLightUniforms(u);
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
  moved->chunks = strandChunks(*strands, {}, {}, &old->chunks);
  moved->strands = std::move(strands);
  impl_->show(std::move(moved));
}

void HairActor::showGeometry(std::shared_ptr<const HairGeometry> geometry) { impl_->show(std::move(geometry)); }

std::shared_ptr<const HairGeometry> HairActor::geometry() const { return impl_->geometry; }

std::optional<glm::vec3> HairActor::keyLight() const { return impl_->keyLight; }

glm::vec3 HairActor::keyLightOf(vtkRenderer* renderer) { return gatherViewLights(renderer).keyTowardLightWorld; }

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

}  // namespace mq::render
