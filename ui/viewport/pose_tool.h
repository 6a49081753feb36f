#pragma once
// The pose tool in the viewport: a click (press and release without moving)
// picks the bone under the cursor; dragging a gizmo ring rotates the
// selected bone about that ring's axis. Camera navigation keeps every other
// drag. Each drag becomes one undo command (steps merge by drag id).

#include <optional>

#include <QObject>
#include <QPoint>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "render/gizmos/rotation_gizmo.h"

class QMouseEvent;

namespace mq::render {
class SceneView;
}

namespace mq::ui {

class EditorDocument;
class VtkViewportWidget;

class PoseTool : public QObject {
  Q_OBJECT

 public:
  PoseTool(EditorDocument* document, render::SceneView* scene, VtkViewportWidget* viewport, QObject* parent = nullptr);

  RotationGizmo& gizmo() { return gizmo_; }
  // Places the gizmo on the selected bone's joint (after pose or selection changes).
  void updateGizmo();

 signals:
  void bonePicked(int bone);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  bool onPress(QMouseEvent* event);
  bool onMove(QMouseEvent* event);
  bool onRelease(QMouseEvent* event);
  glm::vec2 projectToDisplay(const glm::vec3& world) const;
  float dragAngle(const QPoint& display) const;
  glm::quat boneWorldRotation(int bone) const;

  EditorDocument* document_;
  render::SceneView* scene_;
  VtkViewportWidget* viewport_;
  RotationGizmo gizmo_;

  QPoint pressPosition_;
  bool pressed_ = false;
  // Gizmo drag state
  int dragAxis_ = -1;
  int dragId_ = 0;
  int dragBone_ = -1;
  glm::quat dragEditBefore_{1, 0, 0, 0};
  glm::quat dragWorldBefore_{1, 0, 0, 0};
  glm::vec3 dragAxisWorld_{0.0f};
  glm::vec2 dragCenter_{0.0f};
  glm::vec2 dragTangent_{0.0f};  // screen direction of positive rotation at the press point
  float dragPixelsPerRadian_ = 100.0f;
  bool dragFacing_ = false;  // ring faces the viewer: follow the cursor around the centre
  QPoint dragStart_;
};

}  // namespace mq::ui
