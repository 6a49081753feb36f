#include "render/cloth_shading.h"

#include <algorithm>
#include <cmath>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkShaderProperty.h>
#include <vtkTexture.h>
#include <vtkUniforms.h>
#include <vtkUnsignedCharArray.h>

#include "core/garment/fabric_color.h"
#include "core/mesh/mesh.h"
#include "render/surface_mapper.h"

namespace mq::render {

namespace {

// ---- Shader replacements ----

const char* kVertexDec = R"(//VTK::Normal::Dec
in vec2 clothUVMC;
out vec2 clothUV;
)";

const char* kVertexImpl = R"(//VTK::Light::Impl
  clothUV = clothUVMC;
)";

const char* kFragmentDec = R"(//VTK::Normal::Dec
in vec2 clothUV;  // pattern coordinates, metres
)";

// Runs after VTK's own lighting and replaces its result. PRINT_TEXTURE is
// defined when the actor has the print texture (VTK names it actortexture).
const char* kFragmentImpl = R"(//VTK::Light::Impl
  {
    vec3 V = normalize(-vertexVC.xyz);
    vec3 N = normalize(normalVCVSOutput);
    if (dot(N, V) < 0.0) N = -N;  // two-sided: the inside of a garment shows at openings
    vec2 uv = clothUV;
    if (clothRibbed != 0) {
      // Pattern-space tangent along u from screen-space derivatives
      // (Schueler's cotangent frame), then cosine ribs across u.
      vec3 dp1 = dFdx(vertexVC.xyz), dp2 = dFdy(vertexVC.xyz);
      vec2 duv1 = dFdx(uv), duv2 = dFdy(uv);
      vec3 T = cross(dp2, N) * duv1.x + cross(N, dp1) * duv2.x;
      T -= dot(T, N) * N;
      float tl = length(T);
      if (tl > 1e-12) {
        T /= tl;
        float slope = -sin(6.2831853 * uv.x / clothRibSpacing);
        // Ribs narrower than about two pixels fade out instead of aliasing.
        float ribsPerPixel = length(vec2(duv1.x, duv2.x)) / clothRibSpacing;
        float fade = clamp(2.0 - 4.0 * ribsPerPixel, 0.0, 1.0);
        N = normalize(N - clothRibDepth * fade * slope * T);
      }
    }
    vec3 base = clothColor;
#ifdef PRINT_TEXTURE
    base *= texture(actortexture, uv * clothPrintRepeat).rgb;
#endif
    float NV = max(dot(N, V), 0.05);
    vec3 color = clothAmbient * base;
    for (int i = 0; i < mqLightCount; ++i) {
      vec3 L = mqLightDirVC[i];
      float NL = dot(N, L);
      if (NL <= 0.0) continue;
      vec3 lit;
      if (clothModel == 0) {
        // Minnaert: (N.L)^k (N.V)^(k-1).
        lit = base * pow(NL, clothMinnaertK) * pow(NV, clothMinnaertK - 1.0);
      } else {
        // Ashikhmin's velvet distribution over 4 (N.L + N.V - N.L N.V); the
        // factor pi matches VTK's unnormalised Lambert term.
        vec3 H = normalize(L + V);
        float c = clamp(dot(N, H), 0.0, 1.0);
        float s2 = max(1.0 - c * c, 1e-4);
        float sigma2 = clothSheenRoughness * clothSheenRoughness;
        float D = (1.0 + 4.0 * exp(-(c * c / s2) / sigma2) / (s2 * s2)) / (3.14159265 * (1.0 + 4.0 * sigma2));
        float sheen = D / (4.0 * (NL + NV - NL * NV));
        lit = base * NL + 3.14159265 * clothSheen * sheen * NL * clothSheenColor;
      }
      color += mqLightColour[i] * lit;
    }
    gl_FragData[0] = vec4(color, 1.0);
  }
)";

}  // namespace

// ---- ClothShading presets ----

ClothShading clothShadingForFabric(const std::string& fabric) {
  ClothShading s;
  s.color = fabricColor(fabric);
  if (fabric == "velvet") {
    s.minnaertK = 0.55f;
  } else if (fabric == "satin") {
    s.minnaertK = 0.7f;
  } else if (fabric == "silk") {
    s.minnaertK = 0.75f;
  } else if (fabric == "wool") {
    s.minnaertK = 0.9f;
  } else if (fabric == "denim") {
    s.ribbed = true;  // twill lines
    s.ribSpacing = 0.004f;
    s.ribDepth = 0.35f;
  } else if (fabric == "leather") {
    s.minnaertK = 1.15f;
  } else if (fabric == "rib-knit") {
    s.ribbed = true;
  }
  return s;
}

// ---- ClothActor ----

struct ClothActor::Impl {
  ClothShading shading;
  vtkNew<vtkPolyData> polyData;
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals, uvs;
  vtkNew<SurfaceMapper> mapper;
  vtkNew<vtkActor> actor;
  vtkNew<vtkTexture> print;
  std::vector<uint32_t> triangles;
  std::vector<float> normalScratch;
  bool hasPrint = false;

  Impl();
  void installShaders();
  void updateUniforms();
};

ClothActor::Impl::Impl() {
  points->SetDataTypeToFloat();
  normals->SetNumberOfComponents(3);
  uvs->SetName("clothUV");
  uvs->SetNumberOfComponents(2);
  polyData->SetPoints(points);
  polyData->GetPointData()->SetNormals(normals);
  polyData->GetPointData()->AddArray(uvs);
  mapper->SetInputData(polyData);
  mapper->ScalarVisibilityOff();
  mapper->MapDataArrayToVertexAttribute("clothUVMC", "clothUV", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  print->InterpolateOn();
  print->RepeatOn();
  print->MipmapOn();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOn();
  actor->GetProperty()->BackfaceCullingOff();
  installShaders();
  updateUniforms();
}

void ClothActor::Impl::installShaders() {
  vtkShaderProperty* sp = actor->GetShaderProperty();
  sp->ClearAllShaderReplacements();
  sp->AddVertexShaderReplacement("//VTK::Normal::Dec", true, kVertexDec, false);
  sp->AddVertexShaderReplacement("//VTK::Light::Impl", true, kVertexImpl, false);
  bool usePrint = shading.printed && hasPrint;
  std::string dec = usePrint ? std::string(kFragmentDec) + "#define PRINT_TEXTURE\n" : kFragmentDec;
  sp->AddFragmentShaderReplacement("//VTK::Normal::Dec", true, dec, false);
  sp->AddFragmentShaderReplacement("//VTK::Light::Impl", true, kFragmentImpl, false);
  // The print is applied in the lighting above, at the pattern UVs: keep VTK
  // from multiplying the texture in again.
  sp->AddFragmentShaderReplacement("//VTK::TCoord::Impl", true, "", false);
  actor->SetTexture(usePrint ? print.Get() : nullptr);
}

void ClothActor::Impl::updateUniforms() {
  vtkUniforms* u = actor->GetShaderProperty()->GetFragmentCustomUniforms();
  u->SetUniformi("clothModel", shading.model == ClothModel::Minnaert ? 0 : 1);
  const float color[3] = {shading.color.x, shading.color.y, shading.color.z};
  const float sheenColor[3] = {shading.sheenColor.x, shading.sheenColor.y, shading.sheenColor.z};
  u->SetUniform3f("clothColor", color);
  u->SetUniformf("clothAmbient", shading.ambient);
  u->SetUniformf("clothMinnaertK", shading.minnaertK);
  u->SetUniform3f("clothSheenColor", sheenColor);
  u->SetUniformf("clothSheen", shading.sheen);
  u->SetUniformf("clothSheenRoughness", std::max(shading.sheenRoughness, 0.02f));
  u->SetUniformi("clothRibbed", shading.ribbed ? 1 : 0);
  u->SetUniformf("clothRibSpacing", std::max(shading.ribSpacing, 1e-4f));
  u->SetUniformf("clothRibDepth", shading.ribDepth);
  u->SetUniformf("clothPrintRepeat", shading.printRepeatPerMetre);
  declareViewLightUniforms(u);
}

ClothActor::ClothActor() : impl_(std::make_unique<Impl>()) {}
ClothActor::~ClothActor() = default;

vtkActor* ClothActor::actor() { return impl_->actor; }

void ClothActor::setMesh(const std::vector<float>& positions, const std::vector<uint32_t>& triangles,
                         const std::vector<float>& uvs) {
  impl_->triangles = triangles;
  vtkNew<vtkCellArray> cells;
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const vtkIdType ids[3] = {vtkIdType(triangles[t]), vtkIdType(triangles[t + 1]), vtkIdType(triangles[t + 2])};
    cells->InsertNextCell(3, ids);
  }
  impl_->polyData->SetPolys(cells);
  const size_t n = positions.size() / 3;
  impl_->uvs->SetNumberOfTuples(vtkIdType(n));
  for (size_t i = 0; i < n; ++i) {
    float uv[2] = {2 * i + 1 < uvs.size() ? uvs[2 * i] : 0.0f, 2 * i + 1 < uvs.size() ? uvs[2 * i + 1] : 0.0f};
    impl_->uvs->SetTypedTuple(vtkIdType(i), uv);
  }
  impl_->uvs->Modified();
  updatePositions(positions);
}

void ClothActor::updatePositions(const std::vector<float>& positions) {
  const size_t n = positions.size() / 3;
  if (vtkIdType(n) != impl_->uvs->GetNumberOfTuples()) return;
  impl_->points->SetNumberOfPoints(vtkIdType(n));
  float* p = static_cast<vtkFloatArray*>(impl_->points->GetData())->GetPointer(0);
  std::copy(positions.begin(), positions.end(), p);
  computeVertexNormals(positions, impl_->triangles, impl_->normalScratch);
  impl_->normals->SetNumberOfTuples(vtkIdType(n));
  std::copy(impl_->normalScratch.begin(), impl_->normalScratch.end(), impl_->normals->GetPointer(0));
  impl_->points->Modified();
  impl_->normals->Modified();
  impl_->polyData->Modified();
}

void ClothActor::setShading(const ClothShading& shading) {
  bool reinstall = shading.printed != impl_->shading.printed;
  impl_->shading = shading;
  if (reinstall) impl_->installShaders();
  impl_->updateUniforms();
}

const ClothShading& ClothActor::shading() const { return impl_->shading; }

void ClothActor::setPrint(const RgbImage& image) {
  vtkNew<vtkImageData> data;
  data->SetDimensions(image.width, image.height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* dst = static_cast<unsigned char*>(data->GetScalarPointer());
  for (int y = 0; y < image.height; ++y)  // VTK images start at the bottom row
    std::copy_n(image.at(0, image.height - 1 - y), 3 * image.width, dst + 3 * size_t(y) * image.width);
  impl_->print->SetInputData(data);
  impl_->hasPrint = true;
  impl_->installShaders();
}

void ClothActor::setVisible(bool visible) { impl_->actor->SetVisibility(visible ? 1 : 0); }

RgbImage ClothActor::defaultPrint(int size) {
  RgbImage image;
  image.width = image.height = size;
  image.pixels.resize(3 * size_t(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      // Navy stripes on cream with red dots between them; seamless when tiled.
      float u = (x + 0.5f) / size, v = (y + 0.5f) / size;
      bool stripe = std::fmod(u * 4.0f, 1.0f) < 0.25f;
      float du = std::fmod(u * 4.0f, 1.0f) - 0.625f, dv = std::fmod(v * 4.0f, 1.0f) - 0.5f;
      bool dot = du * du + dv * dv < 0.03f;
      uint8_t* p = &image.pixels[3 * (size_t(y) * size + x)];
      glm::vec3 c = stripe ? glm::vec3(30, 40, 90) : dot ? glm::vec3(190, 40, 45) : glm::vec3(240, 232, 210);
      p[0] = uint8_t(c.x), p[1] = uint8_t(c.y), p[2] = uint8_t(c.z);
    }
  return image;
}

}  // namespace mq::render
