#include "render/collider_actors.h"

#include <cmath>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellPicker.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "render/scene_view.h"

namespace mq::render {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Two unit vectors perpendicular to `axis` (unit) and to each other.
void perpendiculars(const glm::dvec3& axis, glm::dvec3& u, glm::dvec3& v) {
  const glm::dvec3 other = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  u = glm::normalize(glm::cross(axis, other));
  v = glm::cross(axis, u);
}

// A capsule from a to b (a sphere when they coincide) as latitude rings:
// the lower half sphere around a, the upper one around b.
vtkSmartPointer<vtkPolyData> capsuleSurface(glm::dvec3 a, glm::dvec3 b, double radius) {
  constexpr int kSegments = 32, kHalfRings = 12;
  glm::dvec3 axis = b - a;
  const double length = glm::length(axis);
  axis = length > 1e-9 ? axis / length : glm::dvec3(0, 1, 0);
  glm::dvec3 u, v;
  perpendiculars(axis, u, v);
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  const int rings = 2 * (kHalfRings + 1);  // pole to equator around a, equator to pole around b
  for (int r = 0; r < rings; ++r) {
    const bool upper = r > kHalfRings;
    const int k = upper ? r - 1 : r;  // latitude step 0..2*kHalfRings
    const double latitude = -0.5 * kPi + kPi * double(k) / double(2 * kHalfRings);
    const glm::dvec3 centre = upper ? b : a;
    for (int s = 0; s < kSegments; ++s) {
      const double longitude = 2.0 * kPi * s / kSegments;
      const glm::dvec3 dir =
          std::cos(latitude) * (std::cos(longitude) * u + std::sin(longitude) * v) + std::sin(latitude) * axis;
      const glm::dvec3 p = centre + radius * dir;
      points->InsertNextPoint(p.x, p.y, p.z);
    }
  }
  for (int r = 0; r + 1 < rings; ++r)
    for (int s = 0; s < kSegments; ++s) {
      const vtkIdType i0 = r * kSegments + s, i1 = r * kSegments + (s + 1) % kSegments;
      const vtkIdType quad[4] = {i0, i1, i1 + kSegments, i0 + kSegments};
      cells->InsertNextCell(4, quad);
    }
  vtkNew<vtkPolyData> out;
  out->SetPoints(points);
  out->SetPolys(cells);
  return out;
}

// A square of the plane around its point, with a short normal arrow (a thin quad strip).
vtkSmartPointer<vtkPolyData> planeSurface(glm::dvec3 point, glm::dvec3 normal, double size) {
  normal = glm::length(normal) > 0 ? glm::normalize(normal) : glm::dvec3(0, 1, 0);
  glm::dvec3 u, v;
  perpendiculars(normal, u, v);
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  const double h = 0.5 * size;
  for (const auto& [su, sv] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
    const glm::dvec3 p = point + h * (su * u + sv * v);
    points->InsertNextPoint(p.x, p.y, p.z);
  }
  const vtkIdType square[4] = {0, 1, 2, 3};
  cells->InsertNextCell(4, square);
  // The normal: two crossed thin quads 15 cm long, so the solid side is obvious.
  const double arrow = 0.15, width = 0.006;
  for (const glm::dvec3& side : {u, v}) {
    const vtkIdType first = points->GetNumberOfPoints();
    for (const glm::dvec3& p : {point - width * side, point + width * side, point + width * side + arrow * normal,
                                point - width * side + arrow * normal})
      points->InsertNextPoint(p.x, p.y, p.z);
    const vtkIdType quad[4] = {first, first + 1, first + 2, first + 3};
    cells->InsertNextCell(4, quad);
  }
  vtkNew<vtkPolyData> out;
  out->SetPoints(points);
  out->SetPolys(cells);
  return out;
}

}  // namespace

vtkSmartPointer<vtkPolyData> colliderSurface(const SolidPrimitive& c, double planeSize) {
  switch (c.shape) {
    case SolidPrimitive::Shape::Sphere:
      return capsuleSurface(c.a, c.a, c.radius);
    case SolidPrimitive::Shape::Capsule:
      return capsuleSurface(c.a, c.b, c.radius);
    case SolidPrimitive::Shape::Plane:
      return planeSurface(c.a, c.b, planeSize);
  }
  return vtkSmartPointer<vtkPolyData>::New();
}

ColliderActors::ColliderActors(SceneView* view) : view_(view) {}

ColliderActors::~ColliderActors() {
  for (auto& actor : actors_) view_->removeProp(actor);
}

void ColliderActors::set(const std::vector<SolidPrimitive>& colliders, int selected) {
  for (auto& actor : actors_) view_->removeProp(actor);
  actors_.clear();
  for (size_t i = 0; i < colliders.size(); ++i) {
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(colliderSurface(colliders[i]));
    normals->SplittingOff();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(normals->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    vtkProperty* property = actor->GetProperty();
    const bool isSelected = int(i) == selected;
    // Teal, translucent: the cloth stays visible through it; the selected one warmer and more opaque.
    if (isSelected)
      property->SetColor(0.95, 0.62, 0.25);
    else
      property->SetColor(0.25, 0.7, 0.75);
    property->SetOpacity(isSelected ? 0.5 : 0.32);
    property->SetSpecular(0.2);
    property->BackfaceCullingOff();
    actor->SetVisibility(visible_);
    view_->addProp(actor);
    actors_.push_back(actor);
  }
}

int ColliderActors::pick(int x, int y, const std::vector<vtkActor*>& occluders) const {
  if (!visible_ || actors_.empty() || !view_->renderer()->GetRenderWindow()) return -1;
  vtkNew<vtkCellPicker> picker;
  picker->SetTolerance(0.0005);
  picker->PickFromListOn();
  for (const auto& actor : actors_) picker->AddPickList(actor);
  for (int mesh = 0; vtkActor* body = view_->meshActor(mesh); ++mesh) picker->AddPickList(body);
  for (vtkActor* occluder : occluders)
    if (occluder->GetVisibility()) picker->AddPickList(occluder);
  if (!picker->Pick(x, y, 0.0, view_->renderer())) return -1;
  for (size_t i = 0; i < actors_.size(); ++i)
    if (actors_[i] == picker->GetActor()) return int(i);
  return -1;  // the character or the cloth
}

void ColliderActors::setVisible(bool visible) {
  visible_ = visible;
  for (auto& actor : actors_) actor->SetVisibility(visible);
}

}  // namespace mq::render
