#include "ui/viewport/pose_tool.h"

#include <cmath>

#include <QMouseEvent>
#include <QUndoStack>

#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>

#include "render/scene_view.h"
#include "ui/document/editor_document.h"
#include "ui/document/pose_commands.h"
#include "ui/viewport/mouse_routing.h"
#include "ui/viewport/viewport_geometry.h"
#include "ui/viewport/vtk_viewport_widget.h"

namespace mq::ui {
namespace {

// Below this |cos| between ring axis and view direction the ring is seen
// nearly edge-on and drags follow its tangent instead of circling it.
constexpr float kFacingThreshold = 0.35f;

float wrapAngle(float a) {
  while (a > float(M_PI)) a -= 2.0f * float(M_PI);
  while (a < -float(M_PI)) a += 2.0f * float(M_PI);
  return a;
}

}  // namespace

PoseTool::PoseTool(EditorDocument* document, render::SceneView* scene, VtkViewportWidget* viewport, QObject* parent)
    : QObject(parent), document_(document), scene_(scene), viewport_(viewport) {
  gizmo_.attach(viewport_->renderWindow(), scene_->renderer());
  viewport_->installEventFilter(this);
  connect(document_, &EditorDocument::poseChanged, this, &PoseTool::updateGizmo);
  connect(document_, &EditorDocument::selectionChanged, this, &PoseTool::updateGizmo);
  connect(document_, &EditorDocument::characterReplaced, this, &PoseTool::updateGizmo);
  connect(document_, &EditorDocument::skeletonChanged, this, &PoseTool::updateGizmo);
}

glm::quat PoseTool::boneWorldRotation(int bone) const {
  const glm::mat4& m = document_->posed().worldFromBone()[bone];
  const glm::mat3 r(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])), glm::normalize(glm::vec3(m[2])));
  return glm::normalize(glm::quat_cast(r));
}

void PoseTool::updateGizmo() {
  const int bone = document_->selectedBone();
  const auto& world = document_->posed().worldFromBone();
  const bool show = bone >= 0 && bone < static_cast<int>(world.size());
  if (show) gizmo_.setFrame(glm::vec3(world[bone][3]), boneWorldRotation(bone));
  gizmo_.setVisible(show);
  viewport_->requestRender();
}

glm::vec2 PoseTool::projectToDisplay(const glm::vec3& world) const { return worldToDisplay(scene_->renderer(), world); }

bool PoseTool::eventFilter(QObject* watched, QEvent* event) {
  if (watched != viewport_) return false;
  return routeMouseEvent(this, event, &PoseTool::onPress, &PoseTool::onMove, &PoseTool::onRelease);
}

bool PoseTool::onPress(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return false;
  pressPosition_ = event->position().toPoint();
  pressed_ = true;
  const int bone = document_->selectedBone();
  if (bone < 0 || event->modifiers() != Qt::NoModifier) return false;
  const QPoint display = widgetToDisplay(viewport_, event->position());
  const int axis = gizmo_.pickAxis(display.x(), display.y());
  if (axis < 0) return false;

  // Start a gizmo drag: remember everything about the bone before it.
  pressed_ = false;
  dragAxis_ = axis;
  dragId_ = SetBoneRotationCommand::nextDragId();
  dragBone_ = bone;
  dragEditBefore_ = document_->boneRotation(bone).value_or(glm::quat(1, 0, 0, 0));
  dragWorldBefore_ = boneWorldRotation(bone);
  dragAxisWorld_ = gizmo_.axis(axis);
  dragStart_ = display;
  dragCenter_ = projectToDisplay(gizmo_.center());

  double cameraPosition[3];
  scene_->renderer()->GetActiveCamera()->GetPosition(cameraPosition);
  const glm::vec3 toCamera =
      glm::normalize(glm::vec3(cameraPosition[0], cameraPosition[1], cameraPosition[2]) - gizmo_.center());
  const float facing = glm::dot(dragAxisWorld_, toCamera);
  dragFacing_ = std::abs(facing) > kFacingThreshold;
  // Seen from the tip of the axis, positive rotation is counter-clockwise.
  if (dragFacing_) dragPixelsPerRadian_ = facing > 0 ? 1.0f : -1.0f;

  const glm::vec3 onRing = gizmo_.lastPickPosition();
  const glm::vec3 tangent = glm::normalize(glm::cross(dragAxisWorld_, onRing - gizmo_.center()));
  const float step = 0.01f * gizmo_.radius();  // world distance moved by 0.01 rad
  const glm::vec2 moved = projectToDisplay(onRing + step * tangent) - projectToDisplay(onRing);
  if (!dragFacing_) {
    const float pixelsPerRadian = glm::length(moved) / 0.01f;
    dragTangent_ = pixelsPerRadian > 1e-3f ? moved / glm::length(moved) : glm::vec2(1, 0);
    dragPixelsPerRadian_ = std::max(pixelsPerRadian, 40.0f);
  }
  gizmo_.setHighlightedAxis(axis);
  viewport_->requestRender();
  return true;
}

float PoseTool::dragAngle(const QPoint& display) const {
  const glm::vec2 current(display.x(), display.y());
  const glm::vec2 start(dragStart_.x(), dragStart_.y());
  if (dragFacing_) {
    const glm::vec2 a = start - dragCenter_, b = current - dragCenter_;
    const float screenAngle = wrapAngle(std::atan2(b.y, b.x) - std::atan2(a.y, a.x));
    return dragPixelsPerRadian_ * screenAngle;  // holds the sign here
  }
  return glm::dot(current - start, dragTangent_) / dragPixelsPerRadian_;
}

bool PoseTool::onMove(QMouseEvent* event) {
  const QPoint display = widgetToDisplay(viewport_, event->position());
  if (dragAxis_ >= 0) {
    const float angle = dragAngle(display);
    const glm::quat edit = editAfterWorldRotation(dragEditBefore_, dragWorldBefore_, dragAxisWorld_, angle);
    document_->undoStack()->push(new SetBoneRotationCommand(document_, dragBone_, edit, dragId_));
    return true;
  }
  if (event->buttons() == Qt::NoButton && gizmo_.visible()) {
    const int hover = gizmo_.pickAxis(display.x(), display.y());
    if (hover != gizmo_.highlightedAxis()) {
      gizmo_.setHighlightedAxis(hover);
      viewport_->requestRender();
    }
  }
  return false;
}

bool PoseTool::onRelease(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return false;
  if (dragAxis_ >= 0) {
    dragAxis_ = -1;
    gizmo_.setHighlightedAxis(-1);
    viewport_->requestRender();
    return true;
  }
  const QPoint moved = event->position().toPoint() - pressPosition_;
  if (pressed_ && moved.manhattanLength() <= kClickTolerancePixels) {
    const QPoint display = widgetToDisplay(viewport_, event->position());
    const int bone = scene_->pickBone(display.x(), display.y());
    document_->selectBone(bone);
    emit bonePicked(bone);
  }
  pressed_ = false;
  return false;
}

}  // namespace mq::ui
