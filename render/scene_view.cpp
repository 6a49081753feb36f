#include "render/scene_view.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellPicker.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSSAOPass.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include "core/character/character.h"
#include "core/character/posed_character.h"
#include "core/mesh/tangents.h"
#include "render/cloth_shading.h"
#include "render/ground.h"
#include "render/hair_actor.h"
#include "render/material_look.h"
#include "render/material_textures.h"
#include "render/section_cone_overlay.h"
#include "render/skeleton_overlay.h"
#include "render/skin_surface_arrays.h"
#include "render/studio.h"
#include "render/surface_shading.h"

namespace mq::render {
namespace {

// One mesh of the character: VTK arrays that updatePose() writes into, shared
// by its parts (one actor per material range).
struct MeshActor {
  std::vector<vtkSmartPointer<vtkActor>> parts;
  std::vector<int> partMaterials;  // index into the character's materials, -1: none
  vtkSmartPointer<vtkFloatArray> positions;
  vtkSmartPointer<vtkFloatArray> normals;
  vtkSmartPointer<vtkFloatArray> tangents;       // null without a normal map
  std::vector<float> restNormals, restTangents;  // tangents follow the normals' turn
  std::vector<uint32_t> triangles;               // for normals when the posed mesh has none
  glm::vec3 baseColor{0.8f};
  std::shared_ptr<SkinSurfaceArrays> skin;  // curvature, thickness, wrinkles
  vtkSmartPointer<vtkActor> heat;           // the mesh coloured by per-vertex values, made on first use
  vtkSmartPointer<vtkUnsignedCharArray> heatColors;
};

// One actor over the mesh's posed points and normals, coloured per vertex.
void makeHeatActor(MeshActor& m) {
  const vtkIdType n = m.positions->GetNumberOfTuples();
  vtkNew<vtkPoints> points;
  points->SetData(m.positions);
  vtkNew<vtkCellArray> cells;
  for (size_t t = 0; t + 2 < m.triangles.size(); t += 3) {
    const vtkIdType tri[3] = {m.triangles[t], m.triangles[t + 1], m.triangles[t + 2]};
    cells->InsertNextCell(3, tri);
  }
  m.heatColors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  m.heatColors->SetName("Heat");
  m.heatColors->SetNumberOfComponents(3);
  m.heatColors->SetNumberOfTuples(n);
  vtkNew<vtkPolyData> polyData;
  polyData->SetPoints(points);
  polyData->SetPolys(cells);
  polyData->GetPointData()->SetNormals(m.normals);
  polyData->GetPointData()->SetScalars(m.heatColors);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(polyData);
  mapper->SetColorModeToDirectScalars();
  mapper->ScalarVisibilityOn();
  m.heat = vtkSmartPointer<vtkActor>::New();
  m.heat->SetMapper(mapper);
  m.heat->GetProperty()->SetAmbient(0.25);
  m.heat->GetProperty()->SetDiffuse(0.75);
  m.heat->GetProperty()->SetSpecular(0.05);
}

// The built-in mannequin, and meshes without a colour of their own (the
// default grey), get the mannequin's wood (in the mesh's colour if it has
// one); other meshes keep their colour with plain shading.
SurfaceLook defaultLookFor(const glm::vec3& colour, bool builtInMannequin) {
  const bool defaultGrey = colour == glm::vec3(0.8f);
  if (!builtInMannequin && !defaultGrey) return SurfaceLook::plain(colour);
  SurfaceLook look = SurfaceLook::mannequin();
  if (!defaultGrey) look.albedo = colour;
  return look;
}

glm::vec3 srgbOf(const glm::vec4& linear) {
  return {linearToSrgb(linear.x), linearToSrgb(linear.y), linearToSrgb(linear.z)};
}

vtkSmartPointer<vtkFloatArray> newArray(const char* name, int components, size_t tuples) {
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  if (name) array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(tuples));
  array->FillValue(0.0f);  // read (as bounds) before the first pose fills it
  return array;
}

// VTK's texture coordinates: the uv set a material samples, through its
// texture transform, with v flipped (VTK's images start at the bottom row).
vtkSmartPointer<vtkFloatArray> textureCoordinates(const Mesh& mesh, const TextureRef& source) {
  const std::vector<float>& uvs = source.texCoord == 1 && !mesh.uvs1.empty() ? mesh.uvs1 : mesh.uvs;
  if (uvs.size() != 2 * mesh.vertexCount()) return nullptr;
  auto tcoords = newArray("TCoords", 2, mesh.vertexCount());
  float* out = tcoords->GetPointer(0);
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    const glm::vec2 uv = source.transform.apply({uvs[2 * v], uvs[2 * v + 1]});
    out[2 * v] = uv.x;
    out[2 * v + 1] = 1.0f - uv.y;
  }
  return tcoords;
}

vtkSmartPointer<vtkActor> makePart(const Mesh& mesh, const Submesh& range, const Material* material, vtkPoints* points,
                                   const MeshActor& m, vtkFloatArray* rest) {
  vtkNew<vtkCellArray> cells;
  for (uint32_t t = range.firstTriangle; t < range.firstTriangle + range.triangleCount; ++t) {
    const vtkIdType tri[3] = {mesh.triangles[3 * t], mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2]};
    cells->InsertNextCell(3, tri);
  }
  vtkNew<vtkPolyData> polyData;
  polyData->SetPoints(points);
  polyData->SetPolys(cells);
  polyData->GetPointData()->SetNormals(m.normals);
  polyData->GetPointData()->AddArray(rest);
  m.skin->addTo(polyData->GetPointData());
  vtkSmartPointer<vtkOpenGLPolyDataMapper> mapper = vtkSmartPointer<vtkOpenGLPolyDataMapper>::Take(newSurfaceMapper());
  if (material)
    if (const TextureRef* source = textureCoordinateSource(*material))
      if (auto tcoords = textureCoordinates(mesh, *source)) {
        polyData->GetPointData()->SetTCoords(tcoords);
        // The skin shader reads its albedo map through them.
        mapper->MapDataArrayToVertexAttribute("mqUVMC", "TCoords", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
      }
  if (m.tangents) polyData->GetPointData()->SetTangents(m.tangents);

  mapper->SetInputData(polyData);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

MeshActor makeMeshActor(const Mesh& mesh, const std::vector<Material>& materials) {
  MeshActor m;
  const size_t n = mesh.vertexCount();
  m.triangles = mesh.triangles;
  m.baseColor = mesh.baseColor;
  m.positions = newArray(nullptr, 3, n);
  m.normals = newArray("Normals", 3, n);
  m.restNormals = mesh.normals;
  m.skin = std::make_shared<SkinSurfaceArrays>(mesh.positions, mesh.normals, mesh.triangles);
  // Tangents only matter to normal maps: carried each frame only then.
  const auto drawnWithNormalMap = [&] {
    for (const Submesh& range : mesh.drawRanges())
      if (range.material >= 0 && range.material < static_cast<int>(materials.size()) &&
          materials[range.material].normalTexture.present())
        return true;
    return false;
  };
  if (mesh.tangents.size() == 4 * n && drawnWithNormalMap()) {
    m.restTangents = mesh.tangents;
    m.tangents = newArray("Tangents", 3, n);
  }
  vtkNew<vtkPoints> points;
  points->SetData(m.positions);
  auto rest = newArray(kRestPositionArray, 3, n);  // pattern coordinates for the surface shader
  if (!mesh.positions.empty())
    std::memcpy(rest->GetPointer(0), mesh.positions.data(), mesh.positions.size() * sizeof(float));
  for (const Submesh& range : mesh.drawRanges()) {
    const bool known = range.material >= 0 && range.material < static_cast<int>(materials.size());
    m.parts.push_back(makePart(mesh, range, known ? &materials[range.material] : nullptr, points, m, rest));
    m.partMaterials.push_back(known ? range.material : -1);
  }
  return m;
}

// VTK's 3-component tangents from ours (xyz + handedness: VTK takes the
// bitangent as cross(normal, tangent), right-handed).
void copyTangentsInto(vtkFloatArray* target, const std::vector<float>& tangents) {
  const size_t n = tangents.size() / 4;
  if (static_cast<size_t>(target->GetNumberOfTuples()) != n) return;
  float* out = target->GetPointer(0);
  for (size_t v = 0; v < n; ++v)
    for (int c = 0; c < 3; ++c) out[3 * v + c] = tangents[4 * v + c];
  target->Modified();
}

void markModified(vtkActor* part) {
  vtkPolyData* polyData = vtkPolyData::SafeDownCast(part->GetMapper()->GetInput());
  polyData->GetPoints()->Modified();
  polyData->Modified();
}

// The skin shader's per-vertex measures, made the first time a skin look
// needs them, with the wrinkles of the pose shown now.
void measureSkin(MeshActor& mesh) {
  if (mesh.skin->measured()) return;
  mesh.skin->measure();
  const float* posed = mesh.positions->GetPointer(0);
  mesh.skin->update(std::vector<float>(posed, posed + mesh.positions->GetNumberOfValues()));
}

// Copies `source` (3 floats per vertex) into `target` when the sizes agree.
bool copyInto(vtkFloatArray* target, const std::vector<float>& source) {
  if (static_cast<size_t>(target->GetNumberOfValues()) != source.size()) return false;
  if (!source.empty()) std::memcpy(target->GetPointer(0), source.data(), source.size() * sizeof(float));
  target->Modified();
  return true;
}

// Bounds of the vertices near (or below) the floor: the planted feet.
// Invalid when nothing touches the floor (a jump: no contact shadow).
Aabb footprintOf(const std::vector<MeshActor>& meshes, const Aabb& bounds, float floorHeight) {
  Aabb feet;
  const float limit = floorHeight + 0.06f * (bounds.max.y - bounds.min.y);
  for (const MeshActor& m : meshes) {
    const float* p = m.positions->GetPointer(0);
    for (vtkIdType v = 0; v < m.positions->GetNumberOfTuples(); ++v, p += 3)
      if (p[1] <= limit) feet.extend({p[0], p[1], p[2]});
  }
  return feet;
}

}  // namespace

struct SceneView::Impl {
  vtkNew<vtkRenderer> renderer;
  std::vector<MeshActor> meshes;
  std::vector<Material> materials;
  std::vector<ImageSource> images;
  std::unique_ptr<MaterialTextures> textures;
  bool builtInMannequin = false;
  LookMode lookMode = LookMode::Auto;
  SurfaceLook skinLook = SurfaceLook::skinPresetLook("skin1");
  float floorHeight = 0.0f;
  std::vector<float> computedNormals, carriedTangents;  // updatePose's scratch, kept between frames
  SkeletonOverlay skeleton;
  SectionConeOverlay cones{renderer};
  std::vector<glm::mat4> worldFromBone;  // as last posed
  Ground ground;
  Aabb bounds;
  bool skeletonVisible = false;

  // Bounds of the meshes; of the joints for a character that has only a skeleton.
  void forEachPart(const std::function<void(MeshActor&, size_t)>& visit) {
    for (MeshActor& mesh : meshes)
      for (size_t p = 0; p < mesh.parts.size(); ++p) visit(mesh, p);
  }
  void applyLooks();
  void updateBounds(const std::vector<glm::mat4>& worldFromBone) {
    bounds = Aabb{};
    for (const MeshActor& m : meshes) {
      const float* p = m.positions->GetPointer(0);
      for (vtkIdType v = 0; v < m.positions->GetNumberOfTuples(); ++v, p += 3) bounds.extend({p[0], p[1], p[2]});
    }
    if (meshes.empty())
      for (const glm::mat4& joint : worldFromBone) bounds.extend(glm::vec3(joint[3]));
  }
};

bool parseLookMode(const std::string& name, LookMode& mode) {
  for (LookMode m : {LookMode::Auto, LookMode::Skin, LookMode::Mannequin, LookMode::Plain})
    if (name == lookModeName(m)) {
      mode = m;
      return true;
    }
  return false;
}

const char* lookModeName(LookMode mode) {
  switch (mode) {
    case LookMode::Skin:
      return "skin";
    case LookMode::Mannequin:
      return "mannequin";
    case LookMode::Plain:
      return "plain";
    case LookMode::Auto:
      break;
  }
  return "auto";
}

SceneView::SceneView() : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  setStudioBackground(m.renderer);
  addThreePointLights(m.renderer);
  m.ground.addTo(m.renderer);
  m.renderer->AddActor(m.skeleton.actor());
  m.skeleton.actor()->SetVisibility(false);
}

SceneView::~SceneView() = default;

vtkRenderer* SceneView::renderer() { return impl_->renderer; }

void SceneView::setCharacter(const Character& character) {
  Impl& m = *impl_;
  m.forEachPart([&](MeshActor& mesh, size_t p) { m.renderer->RemoveActor(mesh.parts[p]); });
  for (MeshActor& mesh : m.meshes)
    if (mesh.heat) m.renderer->RemoveActor(mesh.heat);
  m.meshes.clear();
  m.cones.clear();
  m.materials = character.materials;
  m.images = character.images;
  m.textures = std::make_unique<MaterialTextures>(m.images);
  m.builtInMannequin = character.sourcePath == "default";
  for (const Mesh& mesh : character.meshes) m.meshes.push_back(makeMeshActor(mesh, m.materials));
  m.forEachPart([&](MeshActor& mesh, size_t p) { m.renderer->AddActor(mesh.parts[p]); });
  m.applyLooks();
  PosedCharacter rest;
  rest.evaluate(character, -1, 0.0f, nullptr, nullptr);
  m.updateBounds(rest.worldFromBone());  // rest bounds set the size of the bones
  updatePose(rest);
  // The floor goes under the rest pose's lowest point, wherever the file put its origin.
  m.floorHeight = m.bounds.valid() ? m.bounds.min.y : 0.0f;
  m.ground.setHeight(m.floorHeight);
  const float height = m.bounds.valid() ? m.bounds.max.y - m.bounds.min.y : 1.75f;
  m.skeleton.setSkeleton(character.skeleton, std::max(0.008f * std::max(height, m.bounds.diagonal() * 0.5f), 1e-4f));
  m.skeleton.update(rest.worldFromBone());
  m.ground.fit(m.bounds, footprintOf(m.meshes, m.bounds, m.floorHeight));
}

void SceneView::Impl::applyLooks() {
  bool physicallyBased = false;
  forEachPart([&](MeshActor& mesh, size_t p) {
    vtkActor* actor = mesh.parts[p];
    const int index = mesh.partMaterials[p];
    const Material* material = index >= 0 ? &materials[index] : nullptr;
    const glm::vec3 colour = material ? srgbOf(material->baseColorFactor) : mesh.baseColor;
    // Skin: the view's skin look, in a material's colour and base colour map
    // when there is one.
    auto applySkin = [&] {
      measureSkin(mesh);
      SurfaceLook look = skinLook;
      if (material) look.albedo = colour;
      applySurfaceLook(actor, look, material ? textures->colour(material->baseColorTexture) : nullptr);
    };
    switch (lookMode) {
      case LookMode::Mannequin:
        applySurfaceLook(actor, SurfaceLook::mannequin());
        return;
      case LookMode::Plain:
        applySurfaceLook(actor, SurfaceLook::plain(colour));
        return;
      case LookMode::Skin:
        applySkin();
        return;
      case LookMode::Auto:
        break;
    }
    if (!material) {
      applySurfaceLook(actor, defaultLookFor(colour, builtInMannequin));
    } else if (material->skin) {
      applySkin();
    } else {
      applyMaterial(actor, *material, *textures);
      physicallyBased = true;
    }
  });
  useStudioEnvironment(renderer, physicallyBased);
}

void SceneView::setLookMode(LookMode mode) {
  impl_->lookMode = mode;
  impl_->applyLooks();
}

LookMode SceneView::lookMode() const { return impl_->lookMode; }

void SceneView::setSkinLook(const SurfaceLook& look) {
  impl_->skinLook = look;
  impl_->skinLook.skinShading = true;
  impl_->applyLooks();
}

const SurfaceLook& SceneView::skinLook() const { return impl_->skinLook; }

void SceneView::setMaterial(int index, const Material& material) {
  Impl& m = *impl_;
  if (index < 0 || index >= static_cast<int>(m.materials.size())) return;
  m.materials[index] = material;
  m.applyLooks();
}

const std::vector<Material>& SceneView::materials() const { return impl_->materials; }

std::vector<std::string> SceneView::warnings() const {
  return impl_->textures ? impl_->textures->warnings() : std::vector<std::string>{};
}

void SceneView::setSurfaceLook(const SurfaceLook& look) {
  impl_->forEachPart([&](MeshActor& mesh, size_t p) {
    if (look.skinShading) measureSkin(mesh);
    applySurfaceLook(mesh.parts[p], look);
  });
  useStudioEnvironment(impl_->renderer, false);
}

void SceneView::updatePose(const PosedCharacter& posed) {
  Impl& m = *impl_;
  const auto& posedMeshes = posed.meshes();
  std::vector<float>& computedNormals = m.computedNormals;
  std::vector<float>& carriedTangents = m.carriedTangents;
  for (size_t i = 0; i < m.meshes.size() && i < posedMeshes.size(); ++i) {
    MeshActor& mesh = m.meshes[i];
    if (!copyInto(mesh.positions, posedMeshes[i].positions)) continue;
    if (posedMeshes[i].normals.empty()) {
      computeVertexNormals(posedMeshes[i].positions, mesh.triangles, computedNormals);
      copyInto(mesh.normals, computedNormals);
    } else {
      copyInto(mesh.normals, posedMeshes[i].normals);
    }
    if (mesh.tangents) {
      const std::vector<float>& posedNormals =
          posedMeshes[i].normals.empty() ? computedNormals : posedMeshes[i].normals;
      carryTangents(mesh.restNormals, mesh.restTangents, posedNormals, carriedTangents);
      copyTangentsInto(mesh.tangents, carriedTangents);
    }
    mesh.skin->update(posedMeshes[i].positions);  // wrinkles, once a skin look measured the mesh
    for (vtkActor* part : mesh.parts) markModified(part);
    if (mesh.heat) markModified(mesh.heat);
  }
  m.updateBounds(posed.worldFromBone());
  m.skeleton.update(posed.worldFromBone());
  m.worldFromBone = posed.worldFromBone();
  m.cones.update(m.worldFromBone);
  m.ground.placeShadow(footprintOf(m.meshes, m.bounds, m.floorHeight));
}

void heatColor(float value, unsigned char rgb[3]) {
  // Blue, cyan, green, yellow, red: the ramp of weight painting in DCC tools.
  static const float stops[5][3] = {
      {0.05f, 0.1f, 0.75f}, {0.0f, 0.7f, 0.9f}, {0.1f, 0.85f, 0.2f}, {0.95f, 0.9f, 0.1f}, {0.9f, 0.1f, 0.05f}};
  const float t = std::clamp(std::isfinite(value) ? value : 0.0f, 0.0f, 1.0f) * 4.0f;
  const int i = std::min(int(t), 3);
  const float f = t - float(i);
  for (int c = 0; c < 3; ++c)
    rgb[c] = static_cast<unsigned char>(std::lround(255.0f * ((1.0f - f) * stops[i][c] + f * stops[i + 1][c])));
}

void SceneView::setVertexHeat(const std::vector<std::vector<float>>& perMesh) {
  Impl& m = *impl_;
  for (size_t i = 0; i < m.meshes.size(); ++i) {
    MeshActor& mesh = m.meshes[i];
    const bool show = i < perMesh.size() && perMesh[i].size() == size_t(mesh.positions->GetNumberOfTuples());
    if (show && !mesh.heat) {
      makeHeatActor(mesh);
      m.renderer->AddActor(mesh.heat);
    }
    if (mesh.heat) mesh.heat->SetVisibility(show);
    for (vtkActor* part : mesh.parts) part->SetVisibility(!show);
    if (!show) continue;
    unsigned char* out = mesh.heatColors->GetPointer(0);
    for (size_t v = 0; v < perMesh[i].size(); ++v) heatColor(perMesh[i][v], out + 3 * v);
    mesh.heatColors->Modified();
  }
}

void SceneView::showSectionCones(const Character& character) {
  impl_->cones.build(character);
  impl_->cones.update(impl_->worldFromBone);
}

void SceneView::hideSectionCones() { impl_->cones.clear(); }

int SceneView::sectionConeCount() const { return impl_->cones.coneCount(); }

Aabb SceneView::characterBounds() const { return impl_->bounds; }

float SceneView::floorHeight() const { return impl_->floorHeight; }

vtkActor* SceneView::meshActor(int index) {
  vtkActor* found = nullptr;
  int part = 0;
  impl_->forEachPart([&](MeshActor& mesh, size_t p) {
    if (part++ == index) found = mesh.parts[p];
  });
  return found;
}

void SceneView::setSkeletonVisible(bool visible) {
  impl_->skeletonVisible = visible;
  impl_->skeleton.actor()->SetVisibility(visible);
}

bool SceneView::skeletonVisible() const { return impl_->skeletonVisible; }

void SceneView::setHighlightedBone(int bone) { impl_->skeleton.setHighlightedBone(bone); }

int SceneView::highlightedBone() const { return impl_->skeleton.highlightedBone(); }

void SceneView::setGridVisible(bool visible) { impl_->ground.setVisible(visible); }

void SceneView::setAmbientOcclusion(bool enabled) {
  Impl& m = *impl_;
  if (!enabled) {
    m.renderer->SetPass(nullptr);
    return;
  }
  const float size = m.bounds.valid() ? std::max(m.bounds.max.y - m.bounds.min.y, 0.01f) : 1.75f;
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkSSAOPass> ssao;
  ssao->SetDelegatePass(steps);
  ssao->SetRadius(0.05 * size);  // the reach of the occlusion: about a limb's thickness
  ssao->SetBias(0.002 * size);
  ssao->SetKernelSize(64);
  ssao->BlurOn();
  m.renderer->SetPass(ssao);
}

void SceneView::frameAll(double aspect) {
  Impl& m = *impl_;
  const Aabb box = m.bounds.valid() ? m.bounds : Aabb{{-0.3f, 0.0f, -0.2f}, {0.3f, 1.75f, 0.2f}};
  if (aspect <= 0.0) {
    vtkRenderWindow* window = m.renderer->GetRenderWindow();
    const int* size = window ? window->GetSize() : nullptr;
    aspect = size && size[0] > 0 && size[1] > 0 ? static_cast<double>(size[0]) / size[1] : 4.0 / 3.0;
  }
  // Front three-quarter view (the character faces +z), from slightly above.
  constexpr double kAzimuth = 30.0 * M_PI / 180.0, kElevation = 10.0 * M_PI / 180.0;
  const glm::dvec3 back(std::sin(kAzimuth) * std::cos(kElevation), std::sin(kElevation),
                        std::cos(kAzimuth) * std::cos(kElevation));  // from the target to the camera
  const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), back));
  const glm::dvec3 up = glm::cross(back, right);
  const glm::dvec3 target = glm::dvec3(box.center());

  vtkCamera* camera = m.renderer->GetActiveCamera();
  const double tanHalfV = std::tan(0.5 * camera->GetViewAngle() * M_PI / 180.0);
  const double tanHalfH = tanHalfV * aspect;
  constexpr double kFill = 0.86;  // fraction of the half-frame the character may use
  // Distance at which every corner of the box is inside the frame.
  double distance = 0.0;
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 corner((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                            (c & 4) ? box.max.z : box.min.z);
    const glm::dvec3 d = corner - target;
    const double towardCamera = glm::dot(d, back);
    distance = std::max({distance, towardCamera + std::abs(glm::dot(d, up)) / (kFill * tanHalfV),
                         towardCamera + std::abs(glm::dot(d, right)) / (kFill * tanHalfH)});
  }
  const glm::dvec3 eye = target + distance * back;
  camera->SetFocalPoint(target.x, target.y, target.z);
  camera->SetPosition(eye.x, eye.y, eye.z);
  camera->SetViewUp(0.0, 1.0, 0.0);
  m.renderer->ResetCameraClippingRange();
}

void SceneView::setCamera(const glm::vec3& position, const glm::vec3& focus) {
  vtkCamera* camera = impl_->renderer->GetActiveCamera();
  camera->SetPosition(position.x, position.y, position.z);
  camera->SetFocalPoint(focus.x, focus.y, focus.z);
  camera->SetViewUp(0.0, 1.0, 0.0);
  impl_->renderer->ResetCameraClippingRange();
}

glm::vec3 SceneView::cameraPosition() const {
  const double* p = impl_->renderer->GetActiveCamera()->GetPosition();
  return glm::vec3(p[0], p[1], p[2]);
}

glm::vec3 SceneView::cameraFocus() const {
  const double* p = impl_->renderer->GetActiveCamera()->GetFocalPoint();
  return glm::vec3(p[0], p[1], p[2]);
}

int SceneView::pickBone(int x, int y) {
  Impl& m = *impl_;
  if (!m.renderer->GetRenderWindow()) return -1;
  constexpr double kSkeletonTolerance = 8.0;  // pixels
  if (m.skeletonVisible) {
    const int bone = m.skeleton.nearestBoneOnScreen(m.renderer, x, y, kSkeletonTolerance);
    if (bone >= 0) return bone;
  }
  const std::optional<glm::vec3> hit = pickSurface(x, y);
  return hit ? m.skeleton.nearestBoneTo(*hit) : -1;
}

std::optional<glm::vec3> SceneView::pickSurface(int x, int y) {
  Impl& m = *impl_;
  if (!m.renderer->GetRenderWindow()) return std::nullopt;
  vtkNew<vtkCellPicker> picker;
  picker->SetTolerance(0.0005);
  picker->PickFromListOn();
  m.forEachPart([&](MeshActor& mesh, size_t p) { picker->AddPickList(mesh.parts[p]); });
  if (!picker->Pick(x, y, 0.0, m.renderer) || picker->GetCellId() < 0) return std::nullopt;
  const double* p = picker->GetPickPosition();
  return glm::vec3(p[0], p[1], p[2]);
}

void SceneView::add(ClothActor& cloth) { addProp(cloth.actor()); }

void SceneView::add(HairActor& hair) { addProp(hair.actor()); }

void SceneView::addProp(vtkProp* prop) { impl_->renderer->AddViewProp(prop); }

void SceneView::removeProp(vtkProp* prop) { impl_->renderer->RemoveViewProp(prop); }

}  // namespace mq::render
