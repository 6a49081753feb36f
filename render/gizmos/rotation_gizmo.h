#pragma once
// The on-screen rotation gizmo: three rings around the selected joint, red,
// green and blue for its local X, Y and Z axes, and a larger white ring
// facing the viewer for turns about the view axis (as in Blender). An
// overlay gizmo of constant size on screen (viewport_gizmo.h); the pose tool
// (pose_tool.h) turns drags into rotations.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "render/gizmos/viewport_gizmo.h"

namespace mq::ui {

class RotationGizmo : public ViewportGizmo {
 public:
  RotationGizmo();

  static constexpr int kViewAxis = 3;  // the ring facing the viewer
  static constexpr int kRingCount = 4;
  // World space, unit; kViewAxis points from the centre towards the camera.
  glm::vec3 axis(int index) const;
  // Ring radius in world units at the current camera distance.
  float radius() const { return size(); }

  // The ring under display position (x, y) (pixels, origin bottom left), or -1.
  int pickAxis(int x, int y) { return pickHandle(x, y); }
  void setHighlightedAxis(int axis) { setHighlightedHandle(axis); }
  int highlightedAxis() const { return highlightedHandle(); }

 private:
  void placeHandles() override;
};

}  // namespace mq::ui
