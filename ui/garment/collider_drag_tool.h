#pragma once
// Moving the primitive colliders in the viewport, as in Blender or Maya: a
// click on a collider selects it (GarmentTool::setCurrentCollider: it is
// drawn brighter and selected in the dock; the bone selection is cleared), a
// click on nothing clears it; the selected collider shows a move gizmo
// (move_gizmo.h). Dragging an arrow moves it along that axis (world X, Y, Z;
// a plane along its normal), dragging the centre disc moves it in the screen
// plane; a capsule moves both ends, a plane its point. The collider follows
// the cursor live (the dock's numbers and a running simulation too), and
// each drag is one undo step (the steps merge by key). Camera navigation
// keeps every other drag; in vertex-select mode the tool stands aside.

#include <QObject>
#include <QPoint>

#include <glm/glm.hpp>

#include "render/gizmos/move_gizmo.h"
#include "sim/cloth/collision/primitive_collider.h"

class QMouseEvent;

namespace mq::ui {

class GarmentTool;
class MainWindow;

class ColliderDragTool : public QObject {
  Q_OBJECT

 public:
  ColliderDragTool(GarmentTool* tool, MainWindow* window);

  MoveGizmo& gizmo() { return gizmo_; }
  // Shows the gizmo on the current collider (after any collider or display change).
  void updateGizmo();
  bool dragging() const { return dragHandle_ >= 0; }

  // Where the gizmo sits: a sphere's centre, a capsule's middle, a plane's point.
  static glm::vec3 gizmoCenter(const cloth::PrimitiveCollider& collider);
  // The collider moved by `offset`: both capsule ends, a plane's point.
  static cloth::PrimitiveCollider movedBy(const cloth::PrimitiveCollider& collider, const glm::vec3& offset);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  bool onPress(QMouseEvent* event);
  bool onMove(QMouseEvent* event);
  bool onRelease(QMouseEvent* event);
  bool active() const;
  // The world offset of the collider for the cursor at `display` during a drag.
  glm::vec3 dragOffset(const QPoint& display) const;
  float axisParameter(const QPoint& display) const;
  glm::vec3 screenPlaneHit(const QPoint& display) const;

  GarmentTool* tool_;
  MainWindow* window_;
  MoveGizmo gizmo_;

  QPoint pressPosition_;
  bool pressed_ = false;  // a press that may become a click
  // Drag state
  int dragHandle_ = -1;
  int dragCollider_ = -1;
  int dragMergeKey_ = 0;
  cloth::PrimitiveCollider dragStart_;
  glm::vec3 dragOrigin_{0.0f};       // the gizmo's centre at the press
  glm::vec3 dragAxis_{0.0f};         // unit; for the screen plane its normal
  float dragStartParameter_ = 0.0f;  // along the axis, at the press
  glm::vec3 dragStartHit_{0.0f};     // on the screen plane, at the press
};

}  // namespace mq::ui
