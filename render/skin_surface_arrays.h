#pragma once
// Per-vertex inputs of the skin shader, as point arrays the surface mapper
// maps to vertex attributes (render/skin_shader.cpp):
//   mqCurvature  |mean curvature| of the rest mesh, mm^-1: the pre-integrated
//                table's row (core/mesh/mean_curvature.h);
//   mqThickness  inward thickness of the rest mesh, mm: translucency
//                (core/mesh/inward_thickness.h);
//   mqWrinkle    the posed surface's compression: rest-frame direction (xyz)
//                and l/L (w), Volino's wrinkle input, updated every pose
//                (core/mesh/surface_compression.h);
//   mqWrinklePhase  distance along those directions (m), for the folds' sine.
// The arrays exist from the start (flat, thick, uncompressed) so every
// shader finds its attributes; measure() fills them the first time a skin
// look is applied, so meshes never shown as skin cost nothing.

#include <cstdint>
#include <vector>

#include <vtkSmartPointer.h>

#include "core/mesh/surface_compression.h"

class vtkFloatArray;
class vtkPointData;

namespace mq::render {

inline constexpr const char* kCurvatureArray = "mqCurvature";
inline constexpr const char* kThicknessArray = "mqThickness";
inline constexpr const char* kWrinkleArray = "mqWrinkle";
inline constexpr const char* kWrinklePhaseArray = "mqWrinklePhase";

class SkinSurfaceArrays {
 public:
  // The rest mesh in metres (3 floats per vertex; normals may be empty).
  SkinSurfaceArrays(std::vector<float> restPositions, std::vector<float> restNormals, std::vector<uint32_t> triangles);

  void addTo(vtkPointData* pointData) const;
  // Curvature and thickness of the rest mesh, and the compression's rest
  // data; once (later calls return at once).
  void measure();
  bool measured() const { return measured_; }
  // The wrinkle array for a pose (same vertex order); nothing until measured.
  void update(const std::vector<float>& posedPositions);

 private:
  std::vector<float> restPositions_, restNormals_;
  std::vector<uint32_t> triangles_;
  bool measured_ = false;
  SurfaceCompression compression_;
  std::vector<float> wrinkle_, phase_;  // scratch
  vtkSmartPointer<vtkFloatArray> curvature_, thickness_, wrinkleArray_, phaseArray_;
};

}  // namespace mq::render
