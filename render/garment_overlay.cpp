#include "render/garment_overlay.h"

#include <algorithm>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkShaderProperty.h>
#include <vtkUnsignedCharArray.h>

namespace mq::render {

void stretchColor(float stretch, unsigned char rgb[3], float redAt) {
  const float t = std::clamp((stretch - 1.0f) / std::max(redAt - 1.0f, 1e-6f), 0.0f, 1.0f);
  // neutral (0.82 grey) -> yellow at t = 0.5 -> red at t = 1
  const float neutral = 0.82f;
  float r, g, b;
  if (t < 0.5f) {
    const float s = 2.0f * t;
    r = neutral + (1.0f - neutral) * s;
    g = neutral + (0.9f - neutral) * s;
    b = neutral * (1.0f - s);
  } else {
    const float s = 2.0f * t - 1.0f;
    r = 1.0f;
    g = 0.9f * (1.0f - s);
    b = 0.0f;
  }
  rgb[0] = static_cast<unsigned char>(255.0f * r);
  rgb[1] = static_cast<unsigned char>(255.0f * g);
  rgb[2] = static_cast<unsigned char>(255.0f * b);
}

namespace {

struct Dots {
  vtkNew<vtkPolyData> data;
  vtkNew<vtkPolyDataMapper> mapper;
  vtkNew<vtkActor> actor;
  std::vector<uint32_t> vertices;

  Dots(double r, double g, double b, float size) {
    data->SetPoints(vtkNew<vtkPoints>());
    data->SetVerts(vtkNew<vtkCellArray>());
    mapper->SetInputData(data);
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(r, g, b);
    actor->GetProperty()->SetPointSize(size);
    actor->GetProperty()->LightingOff();
    actor->PickableOff();
    // Always on top: squeeze the dots' depth towards the near plane.
    actor->GetShaderProperty()->AddFragmentShaderReplacement("//VTK::Depth::Impl", true,
                                                             "gl_FragDepth = 0.02 * gl_FragCoord.z;\n", false);
    actor->GetShaderProperty()->AddFragmentShaderReplacement("//VTK::Coincident::Impl", true, "", false);
  }

  void update(const std::vector<float>& positions) {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> cells;
    const size_t count = positions.size() / 3;
    for (uint32_t v : vertices) {
      if (v >= count) continue;
      const vtkIdType id = points->InsertNextPoint(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
      cells->InsertNextCell(1, &id);
    }
    data->SetPoints(points);
    data->SetVerts(cells);
    data->Modified();
  }
};

}  // namespace

struct GarmentOverlay::Impl {
  vtkNew<vtkPolyData> mesh;
  vtkNew<vtkPolyDataMapper> mapper;
  vtkNew<vtkActor> actor;
  vtkNew<vtkUnsignedCharArray> colors;
  std::vector<float> positions;
  std::vector<float> stretch;
  Dots pins{0.9, 0.1, 0.6, 9.0f};
  Dots selection{1.0, 0.85, 0.1, 6.0f};

  void paint() {
    const size_t count = positions.size() / 3;
    colors->SetNumberOfTuples(vtkIdType(count));
    unsigned char rgb[3];
    for (size_t v = 0; v < count; ++v) {
      stretchColor(v < stretch.size() ? stretch[v] : 1.0f, rgb);
      colors->SetTypedTuple(vtkIdType(v), rgb);
    }
    colors->Modified();
  }
};

GarmentOverlay::GarmentOverlay() : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.colors->SetNumberOfComponents(3);
  m.colors->SetName("stretch");
  m.mesh->SetPoints(vtkNew<vtkPoints>());
  m.mesh->SetPolys(vtkNew<vtkCellArray>());
  m.mesh->GetPointData()->SetScalars(m.colors);
  m.mapper->SetInputData(m.mesh);
  m.mapper->SetScalarModeToUsePointData();
  m.mapper->SetColorModeToDirectScalars();
  m.actor->SetMapper(m.mapper);
  m.actor->GetProperty()->SetAmbient(0.25);
  m.actor->GetProperty()->SetDiffuse(0.8);
  m.actor->GetProperty()->BackfaceCullingOff();
  m.actor->SetVisibility(false);
  m.pins.actor->SetVisibility(false);
  m.selection.actor->SetVisibility(false);
}

GarmentOverlay::~GarmentOverlay() = default;

vtkActor* GarmentOverlay::stretchActor() { return impl_->actor; }
vtkActor* GarmentOverlay::pinActor() { return impl_->pins.actor; }
vtkActor* GarmentOverlay::selectionActor() { return impl_->selection.actor; }

void GarmentOverlay::setTriangles(const std::vector<uint32_t>& triangles) {
  vtkNew<vtkCellArray> polys;
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const vtkIdType ids[3] = {vtkIdType(triangles[t]), vtkIdType(triangles[t + 1]), vtkIdType(triangles[t + 2])};
    polys->InsertNextCell(3, ids);
  }
  impl_->mesh->SetPolys(polys);
  impl_->mesh->Modified();
}

void GarmentOverlay::setPositions(const std::vector<float>& positions) {
  Impl& m = *impl_;
  m.positions = positions;
  vtkNew<vtkPoints> points;
  const vtkIdType count = vtkIdType(positions.size() / 3);
  points->SetNumberOfPoints(count);
  for (vtkIdType v = 0; v < count; ++v)
    points->SetPoint(v, positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
  m.mesh->SetPoints(points);
  m.paint();
  m.mesh->Modified();
  m.pins.update(positions);
  m.selection.update(positions);
}

void GarmentOverlay::setStretch(const std::vector<float>& stretch) {
  impl_->stretch = stretch;
  impl_->paint();
  impl_->mesh->Modified();
}

void GarmentOverlay::setPinned(const std::vector<uint32_t>& vertices) {
  impl_->pins.vertices = vertices;
  impl_->pins.update(impl_->positions);
}

void GarmentOverlay::setSelected(const std::vector<uint32_t>& vertices) {
  impl_->selection.vertices = vertices;
  impl_->selection.update(impl_->positions);
}

void GarmentOverlay::setStretchVisible(bool visible) { impl_->actor->SetVisibility(visible); }

void GarmentOverlay::setDotsVisible(bool visible) {
  impl_->pins.actor->SetVisibility(visible);
  impl_->selection.actor->SetVisibility(visible);
}

}  // namespace mq::render
