#include "render/brush_cursor.h"

#include <cmath>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace mq::render {

BrushCursor::BrushCursor(vtkRenderer* renderer) : renderer_(renderer) {
  points_ = vtkSmartPointer<vtkPoints>::New();
  points_->SetNumberOfPoints(kSegments);
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(kSegments + 1);
  for (int i = 0; i <= kSegments; ++i) lines->InsertCellPoint(i % kSegments);
  vtkNew<vtkPolyData> circle;
  circle->SetPoints(points_);
  circle->SetLines(lines);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(circle);
  // Over the hair, as the handles are.
  mapper->SetResolveCoincidentTopologyToPolygonOffset();
  mapper->SetRelativeCoincidentTopologyLineOffsetParameters(0.0, -66000.0);
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper);
  actor_->GetProperty()->SetColor(1.0, 0.85, 0.3);
  actor_->GetProperty()->SetLineWidth(2.0f);
  actor_->GetProperty()->LightingOff();
  actor_->PickableOff();
  actor_->VisibilityOff();
  renderer_->AddActor(actor_);
}

BrushCursor::~BrushCursor() { renderer_->RemoveActor(actor_); }

void BrushCursor::show(const glm::vec3& center, const glm::vec3& facing, float radius) {
  const glm::vec3 n = glm::normalize(facing);
  const glm::vec3 helper = std::abs(n.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 u = glm::normalize(glm::cross(helper, n)), v = glm::cross(n, u);
  for (int i = 0; i < kSegments; ++i) {
    const float a = 6.28318530718f * float(i) / float(kSegments);
    const glm::vec3 p = center + radius * (std::cos(a) * u + std::sin(a) * v);
    points_->SetPoint(i, p.x, p.y, p.z);
  }
  points_->Modified();
  actor_->VisibilityOn();
}

void BrushCursor::hide() { actor_->VisibilityOff(); }

bool BrushCursor::visible() const { return actor_->GetVisibility() != 0; }

glm::vec3 BrushCursor::point(int index) const {
  double p[3];
  points_->GetPoint(index, p);
  return {float(p[0]), float(p[1]), float(p[2])};
}

}  // namespace mq::render
