#pragma once
// The on-screen rotation gizmo: three rings around the selected joint, red,
// green and blue for its local X, Y and Z axes, and a larger white ring
// facing the viewer for turns about the view axis (as in Blender). They are
// drawn in an overlay renderer layer so the body never hides them, and keep a
// constant size on screen. Pure VTK; the pose tool (pose_tool.h) turns drags into rotations.

#include <array>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <vtkSmartPointer.h>

class vtkActor;
class vtkCellPicker;
class vtkRenderWindow;
class vtkRenderer;

namespace mq::ui {

class RotationGizmo {
 public:
  RotationGizmo();
  ~RotationGizmo();

  // Puts the overlay renderer on layer 1 of `window`, sharing the camera of
  // `sceneRenderer` (re-read before every frame).
  void attach(vtkRenderWindow* window, vtkRenderer* sceneRenderer);
  vtkRenderer* overlayRenderer() const;

  void setVisible(bool visible);
  bool visible() const { return visible_; }
  // Centre and orientation (the ring normals are the rotated X, Y, Z axes).
  void setFrame(const glm::vec3& center, const glm::quat& orientation);
  glm::vec3 center() const { return center_; }
  static constexpr int kViewAxis = 3;  // the ring facing the viewer
  static constexpr int kRingCount = 4;
  // World space, unit; kViewAxis points from the centre towards the camera.
  glm::vec3 axis(int index) const;
  // Ring radius in world units at the current camera distance.
  float radius() const { return radius_; }

  // The ring under display position (x, y) (pixels, origin bottom left), or -1.
  int pickAxis(int x, int y);
  // World position of the last successful pick (a point on the ring).
  glm::vec3 lastPickPosition() const { return lastPick_; }
  void setHighlightedAxis(int axis);
  int highlightedAxis() const { return highlighted_; }

 private:
  void syncWithCamera();
  void updateActors();

  vtkSmartPointer<vtkRenderer> overlay_;
  vtkSmartPointer<vtkRenderer> scene_;
  std::array<vtkSmartPointer<vtkActor>, kRingCount> rings_;
  vtkSmartPointer<vtkCellPicker> picker_;
  glm::vec3 center_{0.0f};
  glm::vec3 lastPick_{0.0f};
  glm::quat orientation_{1.0f, 0.0f, 0.0f, 0.0f};
  float radius_ = 0.1f;
  glm::vec3 toCamera_{0.0f, 0.0f, 1.0f};
  int highlighted_ = -1;
  bool visible_ = false;
  unsigned long observer_ = 0;
};

}  // namespace mq::ui
