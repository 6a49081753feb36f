#pragma once
// The on-screen move gizmo (as in Blender and Maya): three arrows from the
// centre, red, green and blue along the frame's X, Y and Z, for moves along
// one axis, and a white disc at the centre facing the viewer for moves in
// the screen plane. An overlay gizmo of constant size on screen
// (viewport_gizmo.h); arrows a shape cannot move along can be hidden
// (a plane shows only its normal). The collider drag tool
// (ui/garment/collider_drag_tool.h) turns drags into moves.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "render/gizmos/viewport_gizmo.h"

namespace mq::ui {

class MoveGizmo : public ViewportGizmo {
 public:
  static constexpr int kScreenPlane = 3;  // the centre disc
  static constexpr int kHandleCount = 4;

  MoveGizmo();

  // World space, unit: an arrow's direction; kScreenPlane: towards the camera.
  glm::vec3 axis(int handle) const;

 private:
  void placeHandles() override;
};

}  // namespace mq::ui
