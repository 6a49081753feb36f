#include "render/gizmos/rotation_gizmo.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/quaternion.hpp>

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkProperty.h>
#include <vtkRegularPolygonSource.h>
#include <vtkTubeFilter.h>

namespace mq::ui {
namespace {

const double kAxisColors[4][3] = {{0.93, 0.26, 0.26}, {0.45, 0.83, 0.24}, {0.27, 0.52, 0.98}, {0.85, 0.85, 0.85}};
// The view ring sits outside the axis rings.
const double kViewRingScale = 1.25;
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
  return handleActor(tube);
}

}  // namespace

RotationGizmo::RotationGizmo() : ViewportGizmo(kScreenFraction) {
  for (int axis = 0; axis < kRingCount; ++axis) addHandle(makeRing(axis), kAxisColors[axis]);
}

glm::vec3 RotationGizmo::axis(int index) const { return index == kViewAxis ? toCamera() : frameAxis(index); }

void RotationGizmo::placeHandles() {
  const glm::mat4 place = glm::translate(glm::mat4(1.0f), center());
  const glm::mat4 axes = place * glm::mat4_cast(orientation()) * glm::scale(glm::mat4(1.0f), glm::vec3(size()));
  const vtkSmartPointer<vtkMatrix4x4> axesMatrix = toVtkMatrix(axes);
  for (int a = 0; a < 3; ++a) handle(a)->SetUserMatrix(axesMatrix);
  // The view ring's local Z is the direction to the camera.
  const glm::quat facing = glm::rotation(glm::vec3(0, 0, 1), toCamera());
  const glm::mat4 view =
      place * glm::mat4_cast(facing) * glm::scale(glm::mat4(1.0f), glm::vec3(float(kViewRingScale) * size()));
  handle(kViewAxis)->SetUserMatrix(toVtkMatrix(view));
}

}  // namespace mq::ui
