// GUI test of dragging colliders in the viewport and of baking a scene with
// no character (needs X: run under xvfb-run). Opens the sheet-and-colliders
// scene, drags the sphere by an arrow of its move gizmo and by the centre
// disc with synthetic mouse events (checks where it lands, the dock's
// numbers, the saved section, one undo step per drag), picks the capsule and
// the plane with clicks and drags them, drags the sphere under the falling
// sheet while it simulates, and bakes the scene's own length of frames and
// scrubs them on the timeline.
#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include <QApplication>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLineF>
#include <QListWidget>
#include <QSlider>
#include <QSpinBox>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <vtkActor.h>
#include <vtkCamera.h>

#include "render/collider_actors.h"
#include "render/gizmos/move_gizmo.h"
#include "render/scene_view.h"
#include "test_window.h"
#include "ui/document/editor_document.h"
#include "ui/garment/collider_drag_tool.h"
#include "ui/garment/garment_panel.h"
#include "ui/garment/garment_tool.h"
#include "ui/main_window.h"
#include "ui/panels/timeline_panel.h"
#include "ui/viewport/viewport_geometry.h"

using namespace mq;
using namespace mq::ui;

namespace {

const char* kScene = MANNEQUIN_SOURCE_DIR "/resources/scenes/cloth_sheet_colliders.json";
const glm::vec3 kSphereCentre(0.0f, 0.35f, 0.0f);  // as the scene has it

glm::vec3 vertex(const std::vector<float>& p, size_t v) { return {p[3 * v], p[3 * v + 1], p[3 * v + 2]}; }

}  // namespace

class ColliderDragTest : public QObject {
  Q_OBJECT

 private:
  MainWindow* window_ = nullptr;
  GarmentTool* tool_ = nullptr;
  EditorDocument* doc() { return window_->document(); }
  QUndoStack* undo() { return doc()->undoStack(); }
  QWidget* viewport() { return window_->viewport(); }
  MoveGizmo& gizmo() { return tool_->colliderDragTool()->gizmo(); }
  const cloth::PrimitiveCollider& collider(int i) { return tool_->scene().cloth.colliders[i]; }

  void keepShot(const char* name) {
    const QString dir = qEnvironmentVariable("MANNEQUIN_TEST_SHOTS");
    if (!dir.isEmpty()) window_->grab().save(dir + "/" + name + ".png");
  }

  void openScene() {
    QString error;
    QVERIFY2(window_->openFileNow(kScene, &error), qPrintable(error));
    tool_->dock()->raise();
    renderNow(window_);
  }

  // A left drag from `from` to `to` in small steps, as a hand would.
  void drag(QPoint from, QPoint to, int steps = 8) {
    sendMouse(viewport(), QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    for (int s = 1; s <= steps; ++s) {
      const QPoint p = from + (to - from) * s / steps;
      sendMouse(viewport(), QEvent::MouseMove, p, Qt::NoButton, Qt::LeftButton);
    }
    sendMouse(viewport(), QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
    renderNow(window_);
  }

  void click(QPoint at) {
    sendMouse(viewport(), QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
    sendMouse(viewport(), QEvent::MouseButtonRelease, at, Qt::LeftButton, Qt::NoButton);
    renderNow(window_);
  }

  // The shown arrow that is longest on screen (a drag along it is well defined).
  int longestArrow() {
    int best = -1;
    double longest = 0.0;
    for (int a = 0; a < 3; ++a) {
      if (!gizmo().handle(a)->GetVisibility()) continue;
      const QPoint tip = toWidget(window_, gizmo().center() + gizmo().size() * gizmo().axis(a));
      const double length = QLineF(tip, toWidget(window_, gizmo().center())).length();
      if (length > longest) longest = length, best = a;
    }
    return best;
  }

  // Drags arrow `axis` of the gizmo so that it moves `metres` along it; returns the move.
  glm::vec3 dragArrow(int axis, float metres) {
    const glm::vec3 grab = gizmo().center() + 0.7f * gizmo().size() * gizmo().axis(axis);
    const glm::vec3 release = grab + metres * gizmo().axis(axis);
    const QPoint from = toWidget(window_, grab);
    const QPoint display = widgetToDisplay(viewport(), from);
    if (gizmo().pickHandle(display.x(), display.y()) != axis) return glm::vec3(NAN);
    drag(from, toWidget(window_, release));
    return metres * gizmo().axis(axis);
  }

 private slots:
  void initTestCase() {
    window_ = makeTestWindow();
    QVERIFY(QTest::qWaitForWindowExposed(window_));
    tool_ = window_->findChild<GarmentTool*>();
    QVERIFY(tool_ != nullptr);
    openScene();
    QVERIFY(doc()->character().meshes.empty());
    QCOMPARE(tool_->colliderCount(), 3);
  }

  void cleanupTestCase() {
    delete window_;
    window_ = nullptr;
  }

  // The opened scene's first collider is selected and carries the gizmo.
  void theSelectedColliderShowsTheGizmo() {
    QCOMPARE(tool_->currentCollider(), 0);
    QVERIFY(gizmo().visible());
    QVERIFY(glm::length(gizmo().center() - kSphereCentre) < 1e-5f);
    for (int h = 0; h < MoveGizmo::kHandleCount; ++h) QVERIFY(gizmo().handle(h)->GetVisibility());
    keepShot("collider_gizmo");
  }

  void draggingAnArrowMovesTheSphereInOneUndoStep() {
    const int commands = undo()->index();
    const int axis = longestArrow();
    QVERIFY(axis >= 0);
    const glm::vec3 moved = dragArrow(axis, 0.2f);
    QVERIFY2(std::isfinite(moved.x), "the press did not grab the arrow");
    QVERIFY(!tool_->colliderDragTool()->dragging());
    const glm::vec3 centre = collider(0).a;
    QVERIFY2(glm::length(centre - (kSphereCentre + moved)) < 0.01f,
             qPrintable(QString("centre at %1 %2 %3").arg(centre.x).arg(centre.y).arg(centre.z)));
    QCOMPARE(collider(0).radius, 0.25f);  // only moved
    // One undo step for the whole drag; the dock, the saved section and the gizmo follow.
    QCOMPARE(undo()->index(), commands + 1);
    QCOMPARE(undo()->undoText(), QString("Move sphere collider"));
    for (int a = 0; a < 3; ++a) QVERIFY(std::abs(tool_->panel()->colliderField(0, a)->value() - centre[a]) < 1e-3);
    QVERIFY(std::abs(doc()->sceneSections().colliders[0]["center"][axis].get<float>() - centre[axis]) < 1e-6f);
    QVERIFY(glm::length(gizmo().center() - centre) < 1e-5f);
    undo()->undo();
    QVERIFY(glm::length(collider(0).a - kSphereCentre) < 1e-6f);
    QVERIFY(std::abs(tool_->panel()->colliderField(0, axis)->value() - kSphereCentre[axis]) < 1e-3);
    undo()->redo();
    QVERIFY(glm::length(collider(0).a - centre) < 1e-6f);
    undo()->undo();
  }

  // The centre disc: the sphere follows the cursor in the screen plane.
  void draggingTheCentreMovesInTheScreenPlane() {
    const int commands = undo()->index();
    const QPoint from = toWidget(window_, gizmo().center());
    const QPoint display = widgetToDisplay(viewport(), from);
    QCOMPARE(gizmo().pickHandle(display.x(), display.y()), int(MoveGizmo::kScreenPlane));
    const QPoint to = from + QPoint(60, -40);
    drag(from, to);
    const glm::vec3 centre = collider(0).a;
    const QPoint landed = toWidget(window_, centre);
    QVERIFY2(
        (landed - to).manhattanLength() <= 2,
        qPrintable(
            QString("landed at %1,%2, released at %3,%4").arg(landed.x()).arg(landed.y()).arg(to.x()).arg(to.y())));
    double direction[3];
    window_->sceneView()->renderer()->GetActiveCamera()->GetDirectionOfProjection(direction);
    const float depth = glm::dot(centre - kSphereCentre, glm::vec3(direction[0], direction[1], direction[2]));
    QVERIFY(std::abs(depth) < 1e-3f);  // no nearer, no farther
    QVERIFY(glm::length(centre - kSphereCentre) > 0.05f);
    QCOMPARE(undo()->index(), commands + 1);
    undo()->undo();
    QVERIFY(glm::length(collider(0).a - kSphereCentre) < 1e-6f);
  }

  // Clicks select: the capsule (both ends move), nothing (no gizmo), the plane (its normal only).
  void clicksSelectAndEachShapeMovesItsWay() {
    const cloth::PrimitiveCollider capsule = collider(1);
    click(toWidget(window_, 0.5f * (capsule.a + capsule.b)));
    QCOMPARE(tool_->currentCollider(), 1);
    QCOMPARE(tool_->panel()->colliderList()->currentRow(), 1);
    QVERIFY(glm::length(gizmo().center() - 0.5f * (capsule.a + capsule.b)) < 1e-5f);
    const glm::vec3 moved = dragArrow(longestArrow(), 0.15f);
    QVERIFY(std::isfinite(moved.x));
    QVERIFY(glm::length(collider(1).a - (capsule.a + moved)) < 0.01f);
    QVERIFY(glm::length((collider(1).b - collider(1).a) - (capsule.b - capsule.a)) < 1e-5f);  // both ends
    undo()->undo();
    QVERIFY(collider(1).a == capsule.a && collider(1).b == capsule.b);

    // A click where no collider is drawn clears the selection and hides the gizmo.
    QPoint empty(-1, -1);
    for (int y = 5; y < viewport()->height() && empty.x() < 0; y += 20)
      for (int x = 5; x < viewport()->width() && empty.x() < 0; x += 20) {
        const QPoint d = widgetToDisplay(viewport(), QPoint(x, y));
        if (tool_->pickCollider(d.x(), d.y()) < 0) empty = QPoint(x, y);
      }
    QVERIFY(empty.x() >= 0);
    click(empty);
    QCOMPARE(tool_->currentCollider(), -1);
    QVERIFY(!gizmo().visible());

    // The plane: only its normal arrow, and a drag along it moves the point along the normal.
    tool_->setCurrentCollider(2);
    const cloth::PrimitiveCollider plane = collider(2);
    QVERIFY(!gizmo().handle(0)->GetVisibility() && !gizmo().handle(2)->GetVisibility());
    QVERIFY(gizmo().handle(1)->GetVisibility());
    QVERIFY(glm::length(gizmo().axis(1) - glm::normalize(plane.b)) < 1e-5f);
    renderNow(window_);
    keepShot("collider_gizmo_plane");
    const glm::vec3 lifted = dragArrow(1, 0.1f);
    QVERIFY(std::isfinite(lifted.x));
    QVERIFY(std::abs(collider(2).a.y - (plane.a.y + 0.1f)) < 0.01f);
    QVERIFY(std::abs(collider(2).a.x - plane.a.x) < 1e-4f && std::abs(collider(2).a.z - plane.a.z) < 1e-4f);
    QVERIFY(collider(2).b == plane.b);
    undo()->undo();
    QVERIFY(collider(2).a == plane.a);
    tool_->setCurrentCollider(0);
  }

  // The sheet falls while the sphere is dragged sideways: the simulation goes
  // on (no restart) and the sheet drapes over the sphere where it is now.
  void theLiveSimulationSeesTheDraggedSphere() {
    tool_->setSimulating(true);
    QTRY_VERIFY_WITH_TIMEOUT(tool_->simulatedSteps() >= 2, 60000);
    // Along world X (the sheet covers x in [-0.5, 0.5]); the X arrow must be visible from this camera.
    const glm::vec3 moved = dragArrow(0, 0.25f);
    QVERIFY2(std::isfinite(moved.x), "the press did not grab the X arrow");
    const int stepsAfterDrag = tool_->simulatedSteps();
    QVERIFY2(stepsAfterDrag >= 2, "the simulation restarted");
    const cloth::PrimitiveCollider sphere = collider(0);
    QVERIFY(std::abs(sphere.a.x - 0.25f) < 0.01f);
    QTRY_VERIFY_WITH_TIMEOUT(tool_->simulatedSteps() >= stepsAfterDrag + 24, 120000);
    tool_->setSimulating(false);
    QVERIFY2(tool_->lastError().isEmpty(), qPrintable(tool_->lastError()));
    const std::vector<float>& sheet = tool_->shownSheetPositions();
    float deepest = 0.0f, onTop = -1.0f;
    for (size_t v = 0; v < sheet.size() / 3; ++v) {
      const glm::vec3 p = vertex(sheet, v);
      QVERIFY(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
      deepest = std::max(deepest, sphere.radius - glm::length(p - sphere.a));
      if (std::abs(p.x - sphere.a.x) < 0.03f && std::abs(p.z - sphere.a.z) < 0.03f) onTop = std::max(onTop, p.y);
    }
    QVERIFY2(deepest < 0.01f, qPrintable(QString("%1 m inside the moved sphere").arg(deepest)));
    // Over the moved sphere's top the sheet rests on it, not where the sphere was.
    const float top = sphere.a.y + sphere.radius;
    QVERIFY2(onTop > top - 0.01f && onTop < top + 0.05f,
             qPrintable(QString("sheet at %1 over a top at %2").arg(onTop).arg(top)));
    renderNow(window_);
    keepShot("collider_dragged_under_sheet");
    undo()->undo();
  }

  // A sphere right behind the sheet, seen from the camera: a click on the
  // sheet there clears the selection rather than selecting the sphere behind.
  void theSheetHidesTheSphereBehindIt() {
    QVERIFY(tool_->hasSheet());
    const std::vector<float>& sheet = tool_->shownSheetPositions();
    glm::vec3 centre(0.0f);
    for (size_t v = 0; v < sheet.size() / 3; ++v) centre += vertex(sheet, v);
    centre /= float(sheet.size() / 3);
    const glm::vec3 camera = window_->sceneView()->cameraPosition();
    cloth::PrimitiveCollider sphere = collider(0);
    sphere.radius = 0.05f;
    sphere.a = centre + 0.15f * glm::normalize(centre - camera);
    QVERIFY(tool_->setCollider(0, sphere));
    tool_->setCurrentCollider(1);  // the capsule's gizmo is elsewhere
    renderNow(window_);
    const QPoint at = toWidget(window_, centre);
    const QPoint d = widgetToDisplay(viewport(), at);
    QCOMPARE(tool_->colliderActors().pick(d.x(), d.y()), 0);  // the sphere is there, behind
    QCOMPARE(tool_->pickCollider(d.x(), d.y()), -1);          // the sheet is in front
    click(at);
    QCOMPARE(tool_->currentCollider(), -1);
    QVERIFY(!gizmo().visible());
    undo()->undo();
    QVERIFY(std::abs(collider(0).radius - 0.05f) > 1e-3f);
    tool_->setCurrentCollider(0);
  }

  // With a character: the body in front of a collider takes the click (a
  // bone), the sphere in front of the chest takes it back (the bone is cleared).
  void theCharacterHidesCollidersBehindIt() {
    QString error;
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    tool_->dock()->raise();
    tool_->addCollider(cloth::PrimitiveCollider::Shape::Plane);   // at the feet, 2 m wide, behind the legs
    tool_->addCollider(cloth::PrimitiveCollider::Shape::Sphere);  // in front of the chest
    renderNow(window_);
    // A point of the floor collider's square that the character hides (its feet stand on it).
    const glm::vec3 floor = collider(0).a;
    QPoint onLeg(-1, -1);
    for (float z = -0.9f; z < 0.9f && onLeg.x() < 0; z += 0.05f)
      for (float x = -0.3f; x < 0.3f && onLeg.x() < 0; x += 0.05f) {
        const QPoint at = toWidget(window_, floor + glm::vec3(x, 0.0f, z));
        const QPoint d = widgetToDisplay(viewport(), at);
        if (window_->sceneView()->pickBone(d.x(), d.y()) >= 0) onLeg = at;
      }
    QVERIFY2(onLeg.x() >= 0, "the character hides no part of the floor");
    click(onLeg);
    QVERIFY(doc()->selectedBone() >= 0);
    QCOMPARE(tool_->currentCollider(), -1);
    QVERIFY(!gizmo().visible());
    click(toWidget(window_, collider(1).a));
    QCOMPARE(tool_->currentCollider(), 1);
    QCOMPARE(doc()->selectedBone(), -1);
    QVERIFY(gizmo().visible());
    keepShot("collider_gizmo_on_character");
  }

  // No character, so no clip: Bake makes the dock's number of frames from the
  // placed sheet and the timeline scrubs them.
  void bakeWithoutACharacterMakesItsFramesAndScrubs() {
    openScene();
    GarmentPanel* panel = tool_->panel();
    QVERIFY(tool_->bakesWithoutClip());
    QVERIFY(panel->bakeFramesField()->isVisibleTo(panel));
    QCOMPARE(panel->bakeFramesField()->value(), 120);
    QVERIFY(!window_->timeline()->slider()->isEnabled() || doc()->clipEnd() > 0.0f);
    const int commands = undo()->index();
    panel->bakeFramesField()->setValue(24);
    QCOMPARE(tool_->scene().cloth.bakeFrames, 24);
    QCOMPARE(undo()->index(), commands + 1);
    QCOMPARE(doc()->sceneSections().cloth["bake_frames"].get<int>(), 24);
    const float fps = tool_->scene().cloth.fps;
    QVERIFY(std::abs(doc()->clipEnd() - 23.0f / fps) < 1e-4f);
    QVERIFY(window_->timeline()->slider()->isEnabled());

    const std::vector<float> placed = tool_->shownSheetPositions();
    QVERIFY2(tool_->bake(), qPrintable(tool_->lastError()));
    QCOMPARE(tool_->bakedFrameCount(), 24);
    doc()->setTime(0.0f);
    QCOMPARE(tool_->shownSheetPositions(), placed);  // the first frame is the placed sheet
    // Scrub to the end on the timeline: the sheet has fallen, in one piece.
    QSlider* slider = window_->timeline()->slider();
    slider->setValue(slider->maximum());
    QVERIFY(std::abs(doc()->time() - doc()->clipEnd()) < 0.05f);
    const std::vector<float> last = tool_->shownSheetPositions();
    float lowest = INFINITY, highest = -INFINITY;
    for (size_t v = 0; v < last.size() / 3; ++v) {
      QVERIFY(std::isfinite(last[3 * v + 1]));
      lowest = std::min(lowest, last[3 * v + 1]), highest = std::max(highest, last[3 * v + 1]);
    }
    QVERIFY2(highest < 0.75f - 0.05f, qPrintable(QString("the sheet's top is at %1 after a second").arg(highest)));
    QVERIFY(lowest > -0.01f);  // above the floor
    // Halfway along it is between the two.
    slider->setValue(slider->maximum() / 2);
    const std::vector<float> middle = tool_->shownSheetPositions();
    QVERIFY(middle != placed && middle != last);
    renderNow(window_);
    keepShot("sheet_baked_without_character");

    // The length is saved with the scene.
    QTemporaryDir dir;
    const QString path = dir.filePath("sheet.mqscene");
    QString error;
    QVERIFY2(window_->saveDocument(path, &error), qPrintable(error));
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QCOMPARE(tool_->scene().cloth.bakeFrames, 24);
    QCOMPARE(panel->bakeFramesField()->value(), 24);
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(VtkViewportWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("MannequinTests");
  QApplication::setApplicationName("gui_collider_drag");
  mq::ui::exitAfter(300, "gui_collider_drag");
  ColliderDragTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "collider_drag_test.moc"
