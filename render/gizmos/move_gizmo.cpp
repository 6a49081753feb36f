#include "render/gizmos/move_gizmo.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/quaternion.hpp>

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkMatrix4x4.h>
#include <vtkProperty.h>
#include <vtkRegularPolygonSource.h>

namespace mq::ui {
namespace {

const double kColors[MoveGizmo::kHandleCount][3] = {
    {0.93, 0.26, 0.26}, {0.45, 0.83, 0.24}, {0.27, 0.52, 0.98}, {0.92, 0.92, 0.92}};
// Arrow length as a fraction of the view's half height at the centre.
const double kScreenFraction = 0.22;
// The arrows start this far out (of their length) so the centre disc stays free.
const double kArrowStart = 0.22;
const double kDiscRadius = 0.09;

// A unit arrow along local +X (placeHandles moves its start out to kArrowStart).
vtkSmartPointer<vtkActor> makeArrow() {
  auto arrow = vtkSmartPointer<vtkArrowSource>::New();
  arrow->SetShaftRadius(0.035);
  arrow->SetTipRadius(0.1);
  arrow->SetTipLength(0.28);
  arrow->SetShaftResolution(12);
  arrow->SetTipResolution(24);
  return handleActor(arrow);
}

// A unit disc in the XY plane (turned towards the camera by its matrix).
vtkSmartPointer<vtkActor> makeDisc() {
  auto disc = vtkSmartPointer<vtkRegularPolygonSource>::New();
  disc->SetNumberOfSides(32);
  disc->SetRadius(1.0);
  disc->GeneratePolygonOn();
  disc->GeneratePolylineOff();
  auto actor = handleActor(disc);
  actor->GetProperty()->SetOpacity(0.8);
  return actor;
}

}  // namespace

MoveGizmo::MoveGizmo() : ViewportGizmo(kScreenFraction) {
  for (int a = 0; a < 3; ++a) addHandle(makeArrow(), kColors[a]);
  addHandle(makeDisc(), kColors[kScreenPlane]);
}

glm::vec3 MoveGizmo::axis(int handle) const { return handle == kScreenPlane ? toCamera() : frameAxis(handle); }

void MoveGizmo::placeHandles() {
  const glm::mat4 place = glm::translate(glm::mat4(1.0f), center());
  const glm::mat4 scale = glm::scale(glm::mat4(1.0f), glm::vec3(size())) *
                          glm::translate(glm::mat4(1.0f), glm::vec3(float(kArrowStart), 0, 0)) *
                          glm::scale(glm::mat4(1.0f), glm::vec3(1.0f - float(kArrowStart), 1, 1));
  for (int a = 0; a < 3; ++a) {
    const glm::quat alongAxis = glm::rotation(glm::vec3(1, 0, 0), axis(a));
    handle(a)->SetUserMatrix(toVtkMatrix(place * glm::mat4_cast(alongAxis) * scale));
  }
  const glm::quat facing = glm::rotation(glm::vec3(0, 0, 1), toCamera());
  handle(kScreenPlane)
      ->SetUserMatrix(toVtkMatrix(place * glm::mat4_cast(facing) *
                                  glm::scale(glm::mat4(1.0f), glm::vec3(float(kDiscRadius) * size()))));
}

}  // namespace mq::ui
