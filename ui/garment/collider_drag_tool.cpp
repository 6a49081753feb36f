#include "ui/garment/collider_drag_tool.h"

#include <cmath>

#include <QMouseEvent>

#include <glm/gtx/quaternion.hpp>

#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>

#include "render/collider_actors.h"
#include "render/scene_view.h"
#include "ui/document/editor_document.h"
#include "ui/garment/garment_edit_command.h"
#include "ui/garment/garment_tool.h"
#include "ui/main_window.h"
#include "ui/viewport/mouse_routing.h"
#include "ui/viewport/viewport_geometry.h"
#include "ui/viewport/vtk_viewport_widget.h"

namespace mq::ui {
namespace {

using Shape = cloth::PrimitiveCollider::Shape;

// Below this sine between an arrow and the line of sight the arrow points at
// the viewer and a drag along it is ill-defined: the collider stays.
constexpr float kMinAxisSine = 0.05f;

}  // namespace

ColliderDragTool::ColliderDragTool(GarmentTool* tool, MainWindow* window)
    : QObject(tool), tool_(tool), window_(window) {
  gizmo_.attach(window->viewport()->renderWindow(), window->sceneView()->renderer());
  window->viewport()->installEventFilter(this);
  // One selection at a time: picking a bone clears the collider's.
  connect(window->document(), &EditorDocument::selectionChanged, this, [this] {
    if (window_->document()->selectedBone() >= 0) tool_->setCurrentCollider(-1);
  });
}

glm::vec3 ColliderDragTool::gizmoCenter(const cloth::PrimitiveCollider& c) {
  return c.shape == Shape::Capsule ? 0.5f * (c.a + c.b) : c.a;
}

cloth::PrimitiveCollider ColliderDragTool::movedBy(const cloth::PrimitiveCollider& c, const glm::vec3& offset) {
  cloth::PrimitiveCollider moved = c;
  moved.a += offset;
  if (c.shape == Shape::Capsule) moved.b += offset;  // a plane's b is its normal
  return moved;
}

bool ColliderDragTool::active() const { return !tool_->selectMode(); }

void ColliderDragTool::updateGizmo() {
  const int index = tool_->currentCollider();
  const bool show = active() && tool_->collidersVisible() && index >= 0 && index < tool_->colliderCount();
  if (show) {
    const cloth::PrimitiveCollider& c = tool_->scene().cloth.colliders[index];
    const bool plane = c.shape == Shape::Plane;
    // World axes; a plane moves along its normal (the green arrow) or in the screen plane.
    const glm::quat orientation =
        plane ? glm::rotation(glm::vec3(0, 1, 0), glm::normalize(c.b)) : glm::quat(1, 0, 0, 0);
    gizmo_.setFrame(gizmoCenter(c), orientation);
    gizmo_.setHandleShown(0, !plane);
    gizmo_.setHandleShown(2, !plane);
  }
  gizmo_.setVisible(show);
  window_->viewport()->requestRender();
}

bool ColliderDragTool::eventFilter(QObject* watched, QEvent* event) {
  if (watched != window_->viewport()) return false;
  return routeMouseEvent(this, event, &ColliderDragTool::onPress, &ColliderDragTool::onMove,
                         &ColliderDragTool::onRelease);
}

// The parameter along the dragged arrow's line of the point nearest the line of sight.
float ColliderDragTool::axisParameter(const QPoint& display) const {
  const ViewRay ray = displayRay(window_->sceneView()->renderer(), display);
  const float along = glm::dot(dragAxis_, ray.direction);
  const float sine2 = 1.0f - along * along;
  if (sine2 < kMinAxisSine * kMinAxisSine) return dragStartParameter_;
  const glm::vec3 w = dragOrigin_ - ray.origin;
  return (along * glm::dot(ray.direction, w) - glm::dot(dragAxis_, w)) / sine2;
}

// Where the line of sight meets the plane through the drag's origin facing the camera.
glm::vec3 ColliderDragTool::screenPlaneHit(const QPoint& display) const {
  const ViewRay ray = displayRay(window_->sceneView()->renderer(), display);
  const float facing = glm::dot(ray.direction, dragAxis_);
  if (std::abs(facing) < 1e-6f) return dragStartHit_;
  return ray.origin + (glm::dot(dragOrigin_ - ray.origin, dragAxis_) / facing) * ray.direction;
}

glm::vec3 ColliderDragTool::dragOffset(const QPoint& display) const {
  if (dragHandle_ == MoveGizmo::kScreenPlane) return screenPlaneHit(display) - dragStartHit_;
  return (axisParameter(display) - dragStartParameter_) * dragAxis_;
}

bool ColliderDragTool::onPress(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton || !active()) return false;
  pressPosition_ = event->position().toPoint();
  pressed_ = event->modifiers() == Qt::NoModifier;
  if (!pressed_ || !gizmo_.visible()) return false;
  const QPoint display = widgetToDisplay(window_->viewport(), event->position());
  const int handle = gizmo_.pickHandle(display.x(), display.y());
  if (handle < 0) return false;

  // Start a drag: remember the collider and where the cursor grabbed the gizmo.
  pressed_ = false;
  dragHandle_ = handle;
  dragCollider_ = tool_->currentCollider();
  dragMergeKey_ = GarmentEditCommand::nextMergeKey();
  dragStart_ = tool_->scene().cloth.colliders[dragCollider_];
  dragOrigin_ = gizmo_.center();
  if (handle == MoveGizmo::kScreenPlane) {
    double direction[3];
    window_->sceneView()->renderer()->GetActiveCamera()->GetDirectionOfProjection(direction);
    dragAxis_ = glm::normalize(glm::vec3(direction[0], direction[1], direction[2]));
    dragStartHit_ = screenPlaneHit(display);
  } else {
    dragAxis_ = gizmo_.axis(handle);
    dragStartParameter_ = axisParameter(display);
  }
  gizmo_.setHighlightedHandle(handle);
  window_->viewport()->requestRender();
  return true;
}

bool ColliderDragTool::onMove(QMouseEvent* event) {
  const QPoint display = widgetToDisplay(window_->viewport(), event->position());
  if (dragging()) {
    if (dragCollider_ < tool_->colliderCount())
      tool_->setCollider(dragCollider_, movedBy(dragStart_, dragOffset(display)), dragMergeKey_,
                         tr("Move %1 collider").arg(cloth::shapeName(dragStart_.shape)));
    return true;
  }
  if (event->buttons() == Qt::NoButton && gizmo_.visible()) {
    const int hover = gizmo_.pickHandle(display.x(), display.y());
    if (hover != gizmo_.highlightedHandle()) {
      gizmo_.setHighlightedHandle(hover);
      window_->viewport()->requestRender();
    }
  }
  return false;
}

bool ColliderDragTool::onRelease(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return false;
  if (dragging()) {
    dragHandle_ = -1;
    gizmo_.setHighlightedHandle(-1);
    window_->viewport()->requestRender();
    return true;
  }
  const QPoint moved = event->position().toPoint() - pressPosition_;
  const bool click = pressed_ && moved.manhattanLength() <= kClickTolerancePixels;
  pressed_ = false;
  if (!click) return false;
  const QPoint display = widgetToDisplay(window_->viewport(), event->position());
  const int picked = tool_->pickCollider(display.x(), display.y());
  tool_->setCurrentCollider(picked);
  if (picked < 0) return false;  // the pose tool picks a bone or clears its selection
  window_->document()->selectBone(-1);
  return true;
}

}  // namespace mq::ui
