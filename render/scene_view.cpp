#include "render/scene_view.h"

#include <algorithm>
#include <cmath>
#include <cstring>

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
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>
#include <vtkSSAOPass.h>
#include <vtkSmartPointer.h>

#include "core/character/character.h"
#include "core/character/posed_character.h"
#include "render/cloth_shading.h"
#include "render/ground.h"
#include "render/hair_actor.h"
#include "render/skeleton_overlay.h"
#include "render/studio.h"
#include "render/surface_shading.h"

namespace mq::render {
namespace {

// One mesh of the character: VTK arrays that updatePose() writes into.
struct MeshActor {
  vtkSmartPointer<vtkActor> actor;
  vtkSmartPointer<vtkPolyData> polyData;
  vtkSmartPointer<vtkFloatArray> positions;
  vtkSmartPointer<vtkFloatArray> normals;
  std::vector<uint32_t> triangles;  // for normals when the posed mesh has none
};

// The built-in mannequin, and meshes without a colour of their own (the
// default grey), get the mannequin's wood (in the mesh's colour if it has
// one); other meshes keep their colour with plain shading.
SurfaceLook defaultLookFor(const Mesh& mesh, bool builtInMannequin) {
  const glm::vec3& c = mesh.baseColor;
  const bool defaultGrey = c == glm::vec3(0.8f);
  if (!builtInMannequin && !defaultGrey) return SurfaceLook::plain(c);
  SurfaceLook look = SurfaceLook::mannequin();
  if (!defaultGrey) look.albedo = c;
  return look;
}

MeshActor makeMeshActor(const Mesh& mesh, const SurfaceLook& look) {
  MeshActor m;
  m.triangles = mesh.triangles;
  m.positions = vtkSmartPointer<vtkFloatArray>::New();
  m.positions->SetNumberOfComponents(3);
  m.positions->SetNumberOfTuples(static_cast<vtkIdType>(mesh.vertexCount()));
  m.normals = vtkSmartPointer<vtkFloatArray>::New();
  m.normals->SetName("Normals");
  m.normals->SetNumberOfComponents(3);
  m.normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh.vertexCount()));
  vtkNew<vtkPoints> points;
  points->SetData(m.positions);

  vtkNew<vtkCellArray> cells;
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const vtkIdType tri[3] = {mesh.triangles[3 * t], mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2]};
    cells->InsertNextCell(3, tri);
  }
  m.polyData = vtkSmartPointer<vtkPolyData>::New();
  m.polyData->SetPoints(points);
  m.polyData->SetPolys(cells);
  m.polyData->GetPointData()->SetNormals(m.normals);
  vtkNew<vtkFloatArray> rest;  // pattern coordinates for the surface shader
  rest->SetName(kRestPositionArray);
  rest->SetNumberOfComponents(3);
  rest->SetNumberOfTuples(static_cast<vtkIdType>(mesh.vertexCount()));
  if (!mesh.positions.empty())
    std::memcpy(rest->GetPointer(0), mesh.positions.data(), mesh.positions.size() * sizeof(float));
  m.polyData->GetPointData()->AddArray(rest);

  vtkSmartPointer<vtkOpenGLPolyDataMapper> mapper = vtkSmartPointer<vtkOpenGLPolyDataMapper>::Take(newSurfaceMapper());
  mapper->SetInputData(m.polyData);
  mapper->ScalarVisibilityOff();
  m.actor = vtkSmartPointer<vtkActor>::New();
  m.actor->SetMapper(mapper);
  applySurfaceLook(m.actor, look);
  return m;
}

// Copies `source` (3 floats per vertex) into `target` when the sizes agree.
bool copyInto(vtkFloatArray* target, const std::vector<float>& source) {
  if (static_cast<size_t>(target->GetNumberOfValues()) != source.size()) return false;
  if (!source.empty()) std::memcpy(target->GetPointer(0), source.data(), source.size() * sizeof(float));
  target->Modified();
  return true;
}

// Bounds of the vertices near (or below) the floor y = 0: the planted feet.
// Invalid when nothing touches the floor (a jump: no contact shadow).
Aabb footprintOf(const std::vector<MeshActor>& meshes, const Aabb& bounds) {
  Aabb feet;
  const float limit = 0.06f * (bounds.max.y - bounds.min.y);
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
  SkeletonOverlay skeleton;
  Ground ground;
  Aabb bounds;
  bool skeletonVisible = false;

  // Bounds of the meshes; of the joints for a character that has only a skeleton.
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
  for (MeshActor& mesh : m.meshes) m.renderer->RemoveActor(mesh.actor);
  m.meshes.clear();
  for (const Mesh& mesh : character.meshes) {
    m.meshes.push_back(makeMeshActor(mesh, defaultLookFor(mesh, character.sourcePath == "default")));
    m.renderer->AddActor(m.meshes.back().actor);
  }
  PosedCharacter rest;
  rest.evaluate(character, -1, 0.0f, nullptr, nullptr);
  m.updateBounds(rest.worldFromBone());  // rest bounds set the size of the bones
  updatePose(rest);
  const float height = m.bounds.valid() ? m.bounds.max.y - m.bounds.min.y : 1.75f;
  m.skeleton.setSkeleton(character.skeleton, std::max(0.008f * std::max(height, m.bounds.diagonal() * 0.5f), 1e-4f));
  m.skeleton.update(rest.worldFromBone());
  m.ground.fit(m.bounds, footprintOf(m.meshes, m.bounds));
}

void SceneView::setSurfaceLook(const SurfaceLook& look) {
  for (MeshActor& mesh : impl_->meshes) applySurfaceLook(mesh.actor, look);
}

void SceneView::updatePose(const PosedCharacter& posed) {
  Impl& m = *impl_;
  const auto& posedMeshes = posed.meshes();
  std::vector<float> computedNormals;
  for (size_t i = 0; i < m.meshes.size() && i < posedMeshes.size(); ++i) {
    MeshActor& mesh = m.meshes[i];
    if (!copyInto(mesh.positions, posedMeshes[i].positions)) continue;
    if (posedMeshes[i].normals.empty()) {
      computeVertexNormals(posedMeshes[i].positions, mesh.triangles, computedNormals);
      copyInto(mesh.normals, computedNormals);
    } else {
      copyInto(mesh.normals, posedMeshes[i].normals);
    }
    mesh.polyData->GetPoints()->Modified();
    mesh.polyData->Modified();
  }
  m.updateBounds(posed.worldFromBone());
  m.skeleton.update(posed.worldFromBone());
  m.ground.placeShadow(footprintOf(m.meshes, m.bounds));
}

Aabb SceneView::characterBounds() const { return impl_->bounds; }

vtkActor* SceneView::meshActor(int index) {
  if (index < 0 || index >= static_cast<int>(impl_->meshes.size())) return nullptr;
  return impl_->meshes[index].actor;
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
  vtkNew<vtkCellPicker> picker;
  picker->SetTolerance(0.0005);
  picker->PickFromListOn();
  for (MeshActor& mesh : m.meshes) picker->AddPickList(mesh.actor);
  if (picker->Pick(x, y, 0.0, m.renderer) && picker->GetCellId() >= 0) {
    const double* p = picker->GetPickPosition();
    return m.skeleton.nearestBoneTo(glm::vec3(p[0], p[1], p[2]));
  }
  return -1;
}

void SceneView::add(ClothActor& cloth) { addProp(cloth.actor()); }

void SceneView::add(HairActor& hair) { addProp(hair.actor()); }

void SceneView::addProp(vtkProp* prop) { impl_->renderer->AddViewProp(prop); }

void SceneView::removeProp(vtkProp* prop) { impl_->renderer->RemoveViewProp(prop); }

}  // namespace mq::render
