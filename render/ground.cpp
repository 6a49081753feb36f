#include "render/ground.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

namespace mq::render {
namespace {

using Rgba = std::array<unsigned char, 4>;

// Grid lines every `spacing` metres over [-half, half]^2; every fifth line
// and the axes slightly brighter. Colours fade towards the rim.
vtkSmartPointer<vtkPolyData> makeGrid(double half, double spacing) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  const int n = static_cast<int>(std::round(half / spacing));
  auto shade = [&](double x, double z, int index) {
    const double fade = std::clamp(1.0 - std::hypot(x, z) / (1.05 * half), 0.0, 1.0);
    const double strength = index == 0 ? 1.0 : index % 5 == 0 ? 0.75 : 0.45;
    const double grey = 38.0 + 62.0 * strength * fade;
    const unsigned char c[3] = {static_cast<unsigned char>(grey), static_cast<unsigned char>(grey + 3),
                                static_cast<unsigned char>(grey + 8)};
    colours->InsertNextTypedTuple(c);
  };
  // Each line is a polyline so the fade is sampled along it.
  constexpr int kSamples = 24;
  for (int axis = 0; axis < 2; ++axis)
    for (int i = -n; i <= n; ++i) {
      const double offset = i * spacing;
      lines->InsertNextCell(kSamples + 1);
      for (int s = 0; s <= kSamples; ++s) {
        const double along = -half + 2.0 * half * s / kSamples;
        const double x = axis == 0 ? offset : along, z = axis == 0 ? along : offset;
        lines->InsertCellPoint(points->InsertNextPoint(x, 0.0, z));
        shade(x, z, std::abs(i));
      }
    }
  auto grid = vtkSmartPointer<vtkPolyData>::New();
  grid->SetPoints(points);
  grid->SetLines(lines);
  grid->GetPointData()->SetScalars(colours);
  return grid;
}

// A disc (triangle fan of rings) in the plane y = height with colour
// `centre` fading to `rim`; the ellipse radii are rx, rz.
vtkSmartPointer<vtkPolyData> makeDisc(double cx, double cz, double rx, double rz, double height, const Rgba& centre,
                                      const Rgba& rim, double falloffPower) {
  constexpr int kRings = 12, kSegments = 48;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(4);
  points->InsertNextPoint(cx, height, cz);
  colours->InsertNextTypedTuple(centre.data());
  for (int r = 1; r <= kRings; ++r) {
    const double t = static_cast<double>(r) / kRings;
    const double w = std::pow(t, falloffPower);
    Rgba c;
    for (int k = 0; k < 4; ++k) c[k] = static_cast<unsigned char>(std::lround(centre[k] + w * (rim[k] - centre[k])));
    for (int s = 0; s < kSegments; ++s) {
      const double a = 2.0 * M_PI * s / kSegments;
      points->InsertNextPoint(cx + t * rx * std::cos(a), height, cz + t * rz * std::sin(a));
      colours->InsertNextTypedTuple(c.data());
    }
  }
  auto ringPoint = [](int ring, int s) -> vtkIdType { return 1 + (ring - 1) * kSegments + (s % kSegments); };
  for (int s = 0; s < kSegments; ++s) {
    const vtkIdType tri[3] = {0, ringPoint(1, s + 1), ringPoint(1, s)};
    triangles->InsertNextCell(3, tri);
  }
  for (int r = 1; r < kRings; ++r)
    for (int s = 0; s < kSegments; ++s) {
      const vtkIdType a = ringPoint(r, s), b = ringPoint(r, s + 1), c = ringPoint(r + 1, s),
                      d = ringPoint(r + 1, s + 1);
      const vtkIdType t1[3] = {a, b, d}, t2[3] = {a, d, c};
      triangles->InsertNextCell(3, t1);
      triangles->InsertNextCell(3, t2);
    }
  auto disc = vtkSmartPointer<vtkPolyData>::New();
  disc->SetPoints(points);
  disc->SetPolys(triangles);
  disc->GetPointData()->SetScalars(colours);
  return disc;
}

void setUnlit(vtkActor* actor) {
  actor->GetProperty()->LightingOff();
  actor->PickableOff();
}

}  // namespace

struct Ground::Impl {
  vtkNew<vtkActor> grid, floor, shadow;
  vtkNew<vtkPolyDataMapper> gridMapper, floorMapper, shadowMapper;
  double extent = 1.75;  // the character's size, metres
  bool visible = true;
  bool shadowHasContact = true;
};

Ground::Ground() : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  for (auto [actor, mapper] : {std::pair<vtkActor*, vtkPolyDataMapper*>{m.grid, m.gridMapper},
                               {m.floor, m.floorMapper},
                               {m.shadow, m.shadowMapper}}) {
    mapper->SetColorModeToDirectScalars();
    actor->SetMapper(mapper);
    setUnlit(actor);
  }
  m.grid->GetProperty()->SetLineWidth(1.0);
  fit(Aabb{{-0.3f, 0.0f, -0.2f}, {0.3f, 1.75f, 0.2f}}, Aabb{{-0.2f, 0.0f, -0.1f}, {0.2f, 0.1f, 0.1f}});
}

Ground::~Ground() = default;

void Ground::addTo(vtkRenderer* renderer) {
  renderer->AddActor(impl_->floor);
  renderer->AddActor(impl_->grid);
  renderer->AddActor(impl_->shadow);
}

void Ground::fit(const Aabb& bounds, const Aabb& footprint) {
  const glm::vec3 size = bounds.valid() ? bounds.max - bounds.min : glm::vec3(1.0f, 1.75f, 1.0f);
  const double extent = std::max({size.x, size.y, size.z, 0.01f});
  // Spacing: a round number near a seventh of the character's size.
  const double raw = extent / 7.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  const double spacing = raw / decade < 2.0 ? decade : raw / decade < 5.0 ? 2.5 * decade : 5.0 * decade;
  const double half = spacing * std::ceil(1.1 * extent / spacing);
  impl_->gridMapper->SetInputData(makeGrid(half, spacing));

  // The floor disc: slightly below the grid so the lines stay crisp on it.
  const double below = -1e-3 * extent;
  impl_->floorMapper->SetInputData(
      makeDisc(0.0, 0.0, 1.15 * half, 1.15 * half, below, Rgba{70, 76, 86, 150}, Rgba{70, 76, 86, 0}, 2.0));

  impl_->extent = extent;
  placeShadow(footprint);
}

void Ground::placeShadow(const Aabb& footprint) {
  impl_->shadowHasContact = footprint.valid();
  impl_->shadow->SetVisibility(impl_->visible && impl_->shadowHasContact);
  if (!footprint.valid()) return;
  // A soft dark ellipse around the feet, just above the grid.
  const double extent = impl_->extent;
  const glm::vec3 centre = footprint.center();
  const double rx = 0.5 * (footprint.max.x - footprint.min.x) + 0.08 * extent;
  const double rz = 0.5 * (footprint.max.z - footprint.min.z) + 0.08 * extent;
  impl_->shadowMapper->SetInputData(
      makeDisc(centre.x, centre.z, rx, rz, 1e-3 * extent, Rgba{8, 8, 10, 170}, Rgba{8, 8, 10, 0}, 1.4));
}

void Ground::setHeight(double y) {
  for (vtkActor* actor : {impl_->grid.Get(), impl_->floor.Get(), impl_->shadow.Get()}) actor->SetPosition(0.0, y, 0.0);
}

void Ground::setVisible(bool visible) {
  impl_->grid->SetVisibility(visible);
  impl_->floor->SetVisibility(visible);
  impl_->visible = visible;
  impl_->shadow->SetVisibility(visible && impl_->shadowHasContact);
}

}  // namespace mq::render
