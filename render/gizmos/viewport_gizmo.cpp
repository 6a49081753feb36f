#include "render/gizmos/viewport_gizmo.h"

#include <cmath>

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

namespace mq::ui {
namespace {

const double kHighlightColor[3] = {1.0, 0.85, 0.2};

}  // namespace

vtkSmartPointer<vtkMatrix4x4> toVtkMatrix(const glm::mat4& m) {
  auto out = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out->SetElement(r, c, m[c][r]);
  return out;
}

ViewportGizmo::ViewportGizmo(double screenFraction)
    : overlay_(vtkSmartPointer<vtkRenderer>::New()),
      picker_(vtkSmartPointer<vtkCellPicker>::New()),
      screenFraction_(screenFraction) {
  overlay_->SetLayer(1);
  overlay_->InteractiveOff();
  overlay_->SetPreserveDepthBuffer(false);
  picker_->PickFromListOn();
  picker_->SetTolerance(0.004);
}

ViewportGizmo::~ViewportGizmo() {
  if (scene_ && observer_) scene_->RemoveObserver(observer_);
}

void ViewportGizmo::addHandle(vtkSmartPointer<vtkActor> actor, const double color[3]) {
  Handle handle{actor, {color[0], color[1], color[2]}, true};
  actor->GetProperty()->SetColor(handle.color);
  actor->SetVisibility(visible_);
  overlay_->AddActor(actor);
  picker_->AddPickList(actor);
  handles_.push_back(handle);
}

void ViewportGizmo::attach(vtkRenderWindow* window, vtkRenderer* sceneRenderer) {
  if (scene_ && observer_) scene_->RemoveObserver(observer_);
  scene_ = sceneRenderer;
  if (window->GetNumberOfLayers() < 2) window->SetNumberOfLayers(2);
  window->AddRenderer(overlay_);
  overlay_->SetActiveCamera(sceneRenderer->GetActiveCamera());
  vtkNew<vtkCallbackCommand> beforeRender;
  beforeRender->SetClientData(this);
  beforeRender->SetCallback(
      [](vtkObject*, unsigned long, void* self, void*) { static_cast<ViewportGizmo*>(self)->syncWithCamera(); });
  observer_ = sceneRenderer->AddObserver(vtkCommand::StartEvent, beforeRender);
}

void ViewportGizmo::setVisible(bool visible) {
  visible_ = visible;
  showHandles();
}

void ViewportGizmo::setHandleShown(int handle, bool shown) {
  handles_[handle].shown = shown;
  showHandles();
}

void ViewportGizmo::showHandles() {
  for (Handle& h : handles_) h.actor->SetVisibility(visible_ && h.shown);
}

void ViewportGizmo::setCenter(const glm::vec3& center) {
  center_ = center;
  placeHandles();
}

void ViewportGizmo::setFrame(const glm::vec3& center, const glm::quat& orientation) {
  orientation_ = glm::normalize(orientation);
  setCenter(center);
}

glm::vec3 ViewportGizmo::frameAxis(int index) const {
  glm::vec3 a(0.0f);
  a[index] = 1.0f;
  return glm::normalize(orientation_ * a);
}

void ViewportGizmo::syncWithCamera() {
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
  size_ = float(screenFraction_ * halfHeight);
  placeHandles();
}

int ViewportGizmo::pickHandle(int x, int y) {
  if (!visible_) return -1;
  syncWithCamera();
  if (!picker_->Pick(x, y, 0.0, overlay_)) return -1;
  vtkActor* hit = picker_->GetActor();
  double* p = picker_->GetPickPosition();
  lastPick_ = glm::vec3(p[0], p[1], p[2]);
  for (int i = 0; i < handleCount(); ++i)
    if (handles_[i].actor == hit) return i;
  return -1;
}

void ViewportGizmo::setHighlightedHandle(int handle) {
  highlighted_ = handle;
  for (int i = 0; i < handleCount(); ++i)
    handles_[i].actor->GetProperty()->SetColor(const_cast<double*>(i == handle ? kHighlightColor : handles_[i].color));
}

vtkSmartPointer<vtkActor> handleActor(vtkAlgorithm* source) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(0.6);
  actor->GetProperty()->SetDiffuse(0.5);
  actor->GetProperty()->SetSpecular(0.0);
  return actor;
}

}  // namespace mq::ui
