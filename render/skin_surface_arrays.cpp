#include "render/skin_surface_arrays.h"

#include <cmath>
#include <cstring>

#include <vtkFloatArray.h>
#include <vtkPointData.h>

#include "core/mesh/inward_thickness.h"
#include "core/mesh/mean_curvature.h"
#include "core/mesh/mesh.h"

namespace mq::render {
namespace {

constexpr float kMillimetresPerMetre = 1000.0f;
constexpr float kThickMillimetres = 1000.0f;  // where an inward ray finds no way out
constexpr int kCurvatureSmoothing = 2;        // ring averages after the median (see mean_curvature.h)

vtkSmartPointer<vtkFloatArray> filledArray(const char* name, int components, size_t tuples, float value) {
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(tuples));
  array->FillValue(value);
  return array;
}

}  // namespace

SkinSurfaceArrays::SkinSurfaceArrays(std::vector<float> restPositions, std::vector<float> restNormals,
                                     std::vector<uint32_t> triangles)
    : restPositions_(std::move(restPositions)), restNormals_(std::move(restNormals)), triangles_(std::move(triangles)) {
  const size_t n = restPositions_.size() / 3;
  curvature_ = filledArray(kCurvatureArray, 1, n, 0.0f);
  thickness_ = filledArray(kThicknessArray, 1, n, kThickMillimetres);
  wrinkleArray_ = filledArray(kWrinkleArray, 4, n, 0.0f);
  phaseArray_ = filledArray(kWrinklePhaseArray, 1, n, 0.0f);
  for (size_t v = 0; v < n; ++v) wrinkleArray_->SetComponent(vtkIdType(v), 3, 1.0f);
}

void SkinSurfaceArrays::addTo(vtkPointData* pointData) const {
  pointData->AddArray(curvature_);
  pointData->AddArray(thickness_);
  pointData->AddArray(wrinkleArray_);
  pointData->AddArray(phaseArray_);
}

void SkinSurfaceArrays::measure() {
  if (measured_) return;
  measured_ = true;
  if (restNormals_.size() != restPositions_.size()) computeVertexNormals(restPositions_, triangles_, restNormals_);
  const std::vector<float> h = vertexMeanCurvature(restPositions_, restNormals_, triangles_, kCurvatureSmoothing);
  const std::vector<float> d =
      inwardThickness(restPositions_, restNormals_, triangles_, kThickMillimetres / kMillimetresPerMetre);
  float* curvature = curvature_->GetPointer(0);
  float* thickness = thickness_->GetPointer(0);
  for (size_t v = 0; v < h.size(); ++v) {
    curvature[v] = std::abs(h[v]) / kMillimetresPerMetre;  // a dent blurs the light as a bump does
    thickness[v] = d[v] * kMillimetresPerMetre;
  }
  curvature_->Modified();
  thickness_->Modified();
  compression_ = SurfaceCompression(restPositions_, triangles_);
}

void SkinSurfaceArrays::update(const std::vector<float>& posedPositions) {
  if (!measured_ || posedPositions.size() != restPositions_.size()) return;
  compression_.evaluate(posedPositions, wrinkle_, &phase_);
  if (wrinkle_.size() != static_cast<size_t>(wrinkleArray_->GetNumberOfValues())) return;
  std::memcpy(wrinkleArray_->GetPointer(0), wrinkle_.data(), wrinkle_.size() * sizeof(float));
  std::memcpy(phaseArray_->GetPointer(0), phase_.data(), phase_.size() * sizeof(float));
  wrinkleArray_->Modified();
  phaseArray_->Modified();
}

}  // namespace mq::render
