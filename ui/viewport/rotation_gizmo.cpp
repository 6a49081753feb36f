#include "ui/viewport/rotation_gizmo.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/quaternion.hpp>

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRegularPolygonSource.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTubeFilter.h>

namespace mq::ui {
namespace {

const double kAxisColors[4][3] = {{0.93, 0.26, 0.26}, {0.45, 0.83, 0.24}, {0.27, 0.52, 0.98}, {0.85, 0.85, 0.85}};
// The view ring sits outside the axis rings.
const double kViewRingScale = 1.25;
const double kHighlightColor[3] = {1.0, 0.85, 0.2};
// Ring radius as a fraction of the view's half height at the joint.
const double kScreenFraction = 0.16;

// A unit ring about local axis `axis` (0..2); the view ring lies in the XY
// plane and is oriented towards the camera by its matrix.
vtkSmartPointer<vtkActor> makeRing(int axis) {
  auto circle = vtkSmartPointer<vtkRegularPolygonSource>::New();
  circle->SetNumberOfSides(96);
  circle->SetRadius(1.0);
  circle->SetCenter(0, 0, 0);
  double normal[3] = {0, 0, 0};
  normal[axis < 3 ? axis : 2] = 1.0;
  circle->SetNormal(normal);
  circle->GeneratePolygonOff();
  circle->GeneratePolylineOn();
  auto tube = vtkSmartPointer<vtkTubeFilter>::New();
  tube->SetInputConnection(circle->GetOutputPort());
  tube->SetRadius(axis < 3 ? 0.025 : 0.016);
  tube->SetNumberOfSides(8);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(tube->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(const_cast<double*>(kAxisColors[axis]));
  actor->GetProperty()->SetAmbient(0.6);
  actor->GetProperty()->SetDiffuse(0.5);
  actor->GetProperty()->SetSpecular(0.0);
  return actor;
}

}  // namespace

RotationGizmo::RotationGizmo()
    : overlay_(vtkSmartPointer<vtkRenderer>::New()), picker_(vtkSmartPointer<vtkCellPicker>::New()) {
  overlay_->SetLayer(1);
  overlay_->InteractiveOff();
  overlay_->SetPreserveDepthBuffer(false);
  picker_->PickFromListOn();
  picker_->SetTolerance(0.004);
  for (int axis = 0; axis < kRingCount; ++axis) {
    rings_[axis] = makeRing(axis);
    rings_[axis]->SetVisibility(false);
    overlay_->AddActor(rings_[axis]);
    picker_->AddPickList(rings_[axis]);
  }
}

RotationGizmo::~RotationGizmo() {
  if (scene_ && observer_) scene_->RemoveObserver(observer_);
}

void RotationGizmo::attach(vtkRenderWindow* window, vtkRenderer* sceneRenderer) {
  if (scene_ && observer_) scene_->RemoveObserver(observer_);
  scene_ = sceneRenderer;
  if (window->GetNumberOfLayers() < 2) window->SetNumberOfLayers(2);
  window->AddRenderer(overlay_);
  overlay_->SetActiveCamera(sceneRenderer->GetActiveCamera());
  vtkNew<vtkCallbackCommand> beforeRender;
  beforeRender->SetClientData(this);
  beforeRender->SetCallback(
      [](vtkObject*, unsigned long, void* self, void*) { static_cast<RotationGizmo*>(self)->syncWithCamera(); });
  observer_ = sceneRenderer->AddObserver(vtkCommand::StartEvent, beforeRender);
}

vtkRenderer* RotationGizmo::overlayRenderer() const { return overlay_; }

void RotationGizmo::setVisible(bool visible) {
  visible_ = visible;
  for (auto& ring : rings_) ring->SetVisibility(visible);
}

void RotationGizmo::setFrame(const glm::vec3& center, const glm::quat& orientation) {
  center_ = center;
  orientation_ = glm::normalize(orientation);
  updateActors();
}

glm::vec3 RotationGizmo::axis(int index) const {
  if (index == kViewAxis) return toCamera_;
  glm::vec3 a(0.0f);
  a[index] = 1.0f;
  return glm::normalize(orientation_ * a);
}

void RotationGizmo::syncWithCamera() {
  if (!scene_) return;
  vtkCamera* camera = scene_->GetActiveCamera();
  overlay_->SetActiveCamera(camera);
  double position[3];
  camera->GetPosition(position);
  const glm::vec3 eye(position[0], position[1], position[2]);
  const float distance = glm::length(eye - center_);
  if (distance > 0.0f) toCamera_ = (eye - center_) / distance;
  const double halfHeight = camera->GetParallelProjection()
                                ? camera->GetParallelScale()
                                : distance * std::tan(0.5 * camera->GetViewAngle() * M_PI / 180.0);
  radius_ = float(kScreenFraction * halfHeight);
  updateActors();
}

namespace {

vtkSmartPointer<vtkMatrix4x4> toVtk(const glm::mat4& m) {
  auto out = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out->SetElement(r, c, m[c][r]);
  return out;
}

}  // namespace

void RotationGizmo::updateActors() {
  const glm::mat4 place = glm::translate(glm::mat4(1.0f), center_);
  const glm::mat4 axes = place * glm::mat4_cast(orientation_) * glm::scale(glm::mat4(1.0f), glm::vec3(radius_));
  const vtkSmartPointer<vtkMatrix4x4> axesMatrix = toVtk(axes);
  for (int a = 0; a < 3; ++a) rings_[a]->SetUserMatrix(axesMatrix);
  // The view ring's local Z is the direction to the camera.
  const glm::quat facing = glm::rotation(glm::vec3(0, 0, 1), toCamera_);
  const glm::mat4 view = place * glm::mat4_cast(facing) * glm::scale(glm::mat4(1.0f), glm::vec3(float(kViewRingScale) * radius_));
  rings_[kViewAxis]->SetUserMatrix(toVtk(view));
}

int RotationGizmo::pickAxis(int x, int y) {
  if (!visible_) return -1;
  syncWithCamera();
  if (!picker_->Pick(x, y, 0.0, overlay_)) return -1;
  vtkActor* hit = picker_->GetActor();
  double* p = picker_->GetPickPosition();
  lastPick_ = glm::vec3(p[0], p[1], p[2]);
  for (int axis = 0; axis < kRingCount; ++axis)
    if (rings_[axis] == hit) return axis;
  return -1;
}

void RotationGizmo::setHighlightedAxis(int axis) {
  highlighted_ = axis;
  for (int a = 0; a < kRingCount; ++a)
    rings_[a]->GetProperty()->SetColor(const_cast<double*>(a == axis ? kHighlightColor : kAxisColors[a]));
}

}  // namespace mq::ui
