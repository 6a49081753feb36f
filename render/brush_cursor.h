#pragma once
// The circle that shows a brush in the viewport (hair grooming, scalp
// painting): centred on the point the brush would act on, facing the
// camera, of the brush's radius; drawn over the hair.

#include <vtkSmartPointer.h>
#include <glm/glm.hpp>

class vtkActor;
class vtkPoints;
class vtkRenderer;

namespace mq::render {

class BrushCursor {
 public:
  explicit BrushCursor(vtkRenderer* renderer);
  ~BrushCursor();
  BrushCursor(const BrushCursor&) = delete;
  BrushCursor& operator=(const BrushCursor&) = delete;

  // `facing`: towards the camera (any length but zero).
  void show(const glm::vec3& center, const glm::vec3& facing, float radius);
  void hide();
  bool visible() const;
  // The circle's points (world), for tests.
  glm::vec3 point(int index) const;
  static constexpr int kSegments = 64;

 private:
  vtkRenderer* renderer_;
  vtkSmartPointer<vtkPoints> points_;
  vtkSmartPointer<vtkActor> actor_;
};

}  // namespace mq::render
