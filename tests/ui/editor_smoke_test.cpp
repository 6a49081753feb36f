// GUI smoke test of the editor (needs X: run under xvfb-run). Drives the real
// main window through the same code paths the user's clicks take: picking in
// the viewport, the scene tree, the typed angles, the gizmo, undo/redo, the
// timeline, failed opens and save/reopen.
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QMimeData>
#include <QMouseEvent>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>
#include <QUndoStack>
#include <QWheelEvent>

#include <vtkRenderer.h>

#include "core/character/character.h"
#include "core/math/transform.h"
#include "render/scene_view.h"
#include "test_window.h"
#include "ui/document/editor_document.h"
#include "ui/document/pose_commands.h"
#include "ui/garment/garment_tool.h"
#include "ui/hair/hair_tool.h"
#include "ui/main_window.h"
#include "ui/panels/material_page.h"
#include "ui/panels/properties_panel.h"
#include "ui/panels/scene_tree_panel.h"
#include "ui/panels/timeline_panel.h"
#include "ui/viewport/pose_tool.h"
#include "ui/viewport/vtk_viewport_widget.h"

using namespace mq;
using namespace mq::ui;

namespace {

std::vector<float> allPositions(const EditorDocument& doc) {
  std::vector<float> out;
  for (const PosedMesh& m : doc.posed().meshes()) out.insert(out.end(), m.positions.begin(), m.positions.end());
  return out;
}

float maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return INFINITY;
  float d = 0.0f;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

}  // namespace

class EditorSmokeTest : public QObject {
  Q_OBJECT

 private:
  MainWindow* window_ = nullptr;
  EditorDocument* doc() { return window_->document(); }

  int bone(const char* name) { return doc()->character().skeleton.findBone(name); }

  QPoint toWidget(const glm::vec3& world) { return mq::ui::toWidget(window_, world); }

  glm::vec3 jointOf(int b) { return glm::vec3(doc()->posed().worldFromBone()[b][3]); }

  void renderNow() { mq::ui::renderNow(window_); }

  // Clicks Count on the character page and waits for the number (-1 when
  // none came within 20 s).
  long countCrossings() {
    QLabel* label = window_->properties()->crossingsLabel();
    window_->properties()->countCrossingsButton()->click();
    if (!QTest::qWaitFor([&] { return label->text().contains("pair"); }, 20000)) return -1;
    return label->text().section(' ', 0, 0).toLong();
  }

 private slots:
  void initTestCase() {
    window_ = makeTestWindow();
    QVERIFY(QTest::qWaitForWindowExposed(window_));
    QString error;
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    QVERIFY(doc()->character().skeleton.boneCount() > 10);
  }

  void cleanupTestCase() {
    delete window_;
    window_ = nullptr;
  }

  void titleStartsWithMannequin() {
    QVERIFY2(window_->windowTitle().startsWith("Mannequin"), qPrintable(window_->windowTitle()));
  }

  void viewportRendersTheCharacter() {
    const QImage image = window_->viewport()->grabFramebuffer();
    QVERIFY(image.width() > 100 && image.height() > 100);
    // Compare with the same view without the character's meshes: the
    // character must cover a good part of the frame.
    vtkActor* body = window_->sceneView()->meshActor(0);
    QVERIFY(body != nullptr);
    body->SetVisibility(false);
    const QImage empty = window_->viewport()->grabFramebuffer();
    body->SetVisibility(true);
    int differing = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const QColor a = image.pixelColor(x, y), b = empty.pixelColor(x, y);
        if (std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue()) > 30)
          ++differing;
      }
    const double fraction = double(differing) / (image.width() * image.height());
    QVERIFY2(fraction > 0.03, qPrintable(QString("character covers only %1 of the viewport").arg(fraction)));
    QVERIFY2(fraction < 0.9, qPrintable(QString("character covers %1 of the viewport").arg(fraction)));
  }

  void clickPicksTheBoneUnderTheCursor() {
    doc()->setClip(-1);  // rest pose: limbs apart
    window_->frameAll();
    renderNow();
    const int forearm = bone("forearm_l"), hand = bone("hand_l");
    QVERIFY(forearm >= 0 && hand >= 0);
    const QPoint at = toWidget(0.5f * (jointOf(forearm) + jointOf(hand)));
    QTest::mouseClick(window_->viewport(), Qt::LeftButton, Qt::NoModifier, at);
    QCOMPARE(doc()->selectedBone(), forearm);
    // The scene tree follows the selection.
    QCOMPARE(window_->sceneTree()->tree()->currentItem(), window_->sceneTree()->boneItem(forearm));
    // A click on empty background clears it.
    QTest::mouseClick(window_->viewport(), Qt::LeftButton, Qt::NoModifier, QPoint(5, 5));
    QCOMPARE(doc()->selectedBone(), -1);
  }

  void typedRotationIsUndoable() {
    const int upperarm = bone("upperarm_l");
    window_->sceneTree()->tree()->setCurrentItem(window_->sceneTree()->boneItem(upperarm));
    QCOMPARE(doc()->selectedBone(), upperarm);
    const std::vector<float> before = allPositions(*doc());
    const int commands = doc()->undoStack()->index();

    window_->properties()->angleBox(0)->setValue(40.0);  // as if typed + Enter
    QCOMPARE(doc()->undoStack()->index(), commands + 1);
    const std::vector<float> after = allPositions(*doc());
    QVERIFY2(maxDifference(before, after) > 0.05f, "rotating the upper arm 40 degrees barely moved the mesh");
    QVERIFY(window_->isWindowModified());

    doc()->undoStack()->undo();
    QCOMPARE(allPositions(*doc()), before);  // exactly
    QVERIFY(!doc()->boneRotation(upperarm).has_value());
    QCOMPARE(window_->properties()->angleBox(0)->value(), 0.0);

    doc()->undoStack()->redo();
    QCOMPARE(allPositions(*doc()), after);
    QVERIFY(std::abs(eulerDegreesFromQuat(*doc()->boneRotation(upperarm)).x - 40.0f) < 0.01f);
    doc()->undoStack()->undo();
  }

  void gizmoDragRotatesAsOneCommand() {
    const int forearm = bone("forearm_l");
    doc()->selectBone(forearm);
    renderNow();
    RotationGizmo& gizmo = window_->poseTool()->gizmo();
    QVERIFY(gizmo.visible());
    // Find a pixel on a ring: walk around each ring until the gizmo picks it.
    QPoint onRing;
    int axis = -1;
    const double ratio = window_->viewport()->devicePixelRatioF();
    for (int a = 0; a < 3 && axis < 0; ++a) {
      const glm::vec3 u = gizmo.axis((a + 1) % 3), v = gizmo.axis((a + 2) % 3);
      for (int step = 0; step < 24 && axis < 0; ++step) {
        const float t = float(step) * 2.0f * float(M_PI) / 24.0f;
        const QPoint p = toWidget(gizmo.center() + gizmo.radius() * (std::cos(t) * u + std::sin(t) * v));
        const int display_y = int(window_->viewport()->height() * ratio) - 1 - int(p.y() * ratio);
        if (gizmo.pickAxis(int(p.x() * ratio), display_y) == a) {
          axis = a;
          onRing = p;
        }
      }
    }
    QVERIFY2(axis >= 0, "no ring of the gizmo could be picked");
    const std::vector<float> before = allPositions(*doc());
    const int commands = doc()->undoStack()->index();
    QWidget* viewport = window_->viewport();
    sendMouse(viewport, QEvent::MouseButtonPress, onRing, Qt::LeftButton, Qt::LeftButton);
    // Drag along the ring's tangent on screen, as a user follows the ring.
    const QPointF radial = QPointF(onRing - toWidget(gizmo.center()));
    const double length = std::hypot(radial.x(), radial.y());
    QVERIFY(length > 5.0);
    const QPointF tangent(-radial.y() / length, radial.x() / length);
    QPoint end = onRing;
    for (int i = 1; i <= 6; ++i) {
      end = onRing + (tangent * (8.0 * i)).toPoint();
      sendMouse(viewport, QEvent::MouseMove, end, Qt::NoButton, Qt::LeftButton);
    }
    sendMouse(viewport, QEvent::MouseButtonRelease, end, Qt::LeftButton, Qt::NoButton);

    QCOMPARE(doc()->selectedBone(), forearm);             // the drag did not re-pick
    QCOMPARE(doc()->undoStack()->index(), commands + 1);  // the drag steps merged
    QVERIFY(doc()->boneRotation(forearm).has_value());
    const float angle = 2.0f * std::acos(std::min(1.0f, std::abs(doc()->boneRotation(forearm)->w)));
    QVERIFY2(angle > 0.05f, qPrintable(QString("gizmo drag turned the bone by only %1 rad").arg(angle)));
    QVERIFY(maxDifference(before, allPositions(*doc())) > 0.01f);
    doc()->undoStack()->undo();
    QCOMPARE(allPositions(*doc()), before);
  }

  void viewRingTurnsAboutTheViewAxis() {
    const int forearm = bone("forearm_l");
    doc()->selectBone(forearm);
    renderNow();
    RotationGizmo& gizmo = window_->poseTool()->gizmo();
    const glm::vec3 toCamera = gizmo.axis(RotationGizmo::kViewAxis);
    // Two directions across the view ring's plane.
    const glm::vec3 u = glm::normalize(glm::cross(toCamera, glm::vec3(0, 1, 0)));
    const glm::vec3 v = glm::cross(toCamera, u);
    const double ratio = window_->viewport()->devicePixelRatioF();
    QPoint onRing;
    bool found = false;
    for (int step = 0; step < 36 && !found; ++step) {
      const float t = float(step) * 2.0f * float(M_PI) / 36.0f;
      const QPoint p = toWidget(gizmo.center() + 1.25f * gizmo.radius() * (std::cos(t) * u + std::sin(t) * v));
      const int displayY = int(window_->viewport()->height() * ratio) - 1 - int(p.y() * ratio);
      if (gizmo.pickAxis(int(p.x() * ratio), displayY) == RotationGizmo::kViewAxis) {
        found = true;
        onRing = p;
      }
    }
    QVERIFY2(found, "the view ring could not be picked");
    auto worldRotation = [&] {
      const glm::mat4& m = doc()->posed().worldFromBone()[forearm];
      return glm::normalize(glm::quat_cast(glm::mat3(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])),
                                                     glm::normalize(glm::vec3(m[2])))));
    };
    const glm::quat before = worldRotation();
    const QPointF radial = QPointF(onRing - toWidget(gizmo.center()));
    const QPointF tangent = QPointF(-radial.y(), radial.x()) / std::hypot(radial.x(), radial.y());
    QWidget* viewport = window_->viewport();
    sendMouse(viewport, QEvent::MouseButtonPress, onRing, Qt::LeftButton, Qt::LeftButton);
    const QPoint end = onRing + (tangent * 40.0).toPoint();
    sendMouse(viewport, QEvent::MouseMove, end, Qt::NoButton, Qt::LeftButton);
    sendMouse(viewport, QEvent::MouseButtonRelease, end, Qt::LeftButton, Qt::NoButton);
    const glm::quat turn = worldRotation() * glm::inverse(before);
    const float angle = 2.0f * std::acos(std::min(1.0f, std::abs(turn.w)));
    QVERIFY2(angle > 0.05f, qPrintable(QString("view ring turned the bone by only %1 rad").arg(angle)));
    const glm::vec3 turnAxis = glm::normalize(glm::vec3(turn.x, turn.y, turn.z));
    QVERIFY2(std::abs(glm::dot(turnAxis, toCamera)) > 0.999f, "the turn is not about the view axis");
    doc()->undoStack()->undo();
  }

  void dragOrbitsAndWheelZooms() {
    doc()->selectBone(-1);
    window_->frameAll();
    renderNow();
    const glm::vec3 eye = window_->sceneView()->cameraPosition();
    QWidget* viewport = window_->viewport();
    const QPoint start(40, viewport->height() / 2);
    sendMouse(viewport, QEvent::MouseButtonPress, start, Qt::LeftButton, Qt::LeftButton);
    for (int i = 1; i <= 5; ++i)
      sendMouse(viewport, QEvent::MouseMove, start + QPoint(20 * i, 0), Qt::NoButton, Qt::LeftButton);
    sendMouse(viewport, QEvent::MouseButtonRelease, start + QPoint(100, 0), Qt::LeftButton, Qt::NoButton);
    const glm::vec3 orbited = window_->sceneView()->cameraPosition();
    const glm::vec3 focus = window_->sceneView()->cameraFocus();
    QVERIFY2(glm::length(orbited - eye) > 0.05f, "a left drag did not orbit the camera");
    QVERIFY(std::abs(glm::length(orbited - focus) - glm::length(eye - focus)) < 0.02f);  // orbit keeps the distance
    QCOMPARE(doc()->selectedBone(), -1);                                                 // a drag is not a click

    QWheelEvent wheel(QPointF(viewport->width() / 2, viewport->height() / 2),
                      viewport->mapToGlobal(QPointF(viewport->width() / 2, viewport->height() / 2)), QPoint(),
                      QPoint(0, 120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport, &wheel);
    const glm::vec3 zoomed = window_->sceneView()->cameraPosition();
    QVERIFY2(glm::length(zoomed - focus) < glm::length(orbited - focus) - 0.01f, "the wheel did not zoom in");
    window_->frameAll();
  }

  void droppingAFileOpensIt() {
    const QString glb = QString(MANNEQUIN_SHARED_DIR) + "/assets/characters/CesiumMan/glTF-Binary/CesiumMan.glb";
    if (!QFile::exists(glb)) QSKIP("CesiumMan.glb not in the shared assets");
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(glb)});
    QDragEnterEvent enter(QPoint(200, 200), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_, &enter);
    QVERIFY(enter.isAccepted());
    QSignalSpy finished(window_, &MainWindow::loadFinished);
    QDropEvent drop(QPointF(200, 200), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_, &drop);
    QVERIFY(finished.wait(20000));
    QCOMPARE(finished.first().first().toBool(), true);
    QVERIFY(window_->windowTitle().contains("CesiumMan.glb"));
    QCOMPARE(doc()->character().vertexCount(), size_t(3273));
    QString error;
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
  }

  void timelineScrubsTheClip() {
    const int walk = doc()->character().findClip("walk");
    QVERIFY(walk >= 0);
    window_->timeline()->clipBox()->setCurrentIndex(walk + 1);
    QCOMPARE(doc()->clipIndex(), walk);
    const std::vector<float> start = allPositions(*doc());
    QSlider* slider = window_->timeline()->slider();
    QVERIFY(slider->isEnabled() && slider->maximum() > 4);
    slider->setValue(slider->maximum() / 2);
    QVERIFY(doc()->time() > doc()->clipStart());
    QVERIFY(maxDifference(start, allPositions(*doc())) > 0.02f);
    // Playback advances time on its own.
    slider->setValue(0);
    window_->timeline()->setPlaying(true);
    QTRY_VERIFY_WITH_TIMEOUT(doc()->time() > doc()->clipStart(), 3000);
    window_->timeline()->setPlaying(false);
  }

  void failedOpenKeepsTheDocument() {
    QTemporaryDir dir;
    const QString broken = dir.filePath("broken.glb");
    QFile file(broken);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("this is not a binary glTF file at all");
    file.close();

    const int upperarm = bone("upperarm_l");
    doc()->setBoneRotation(upperarm, quatFromEulerDegrees({0, 0, 25}));
    const std::vector<float> before = allPositions(*doc());
    const QString title = window_->windowTitle();

    QString reported;
    auto previous = window_->reportError;
    window_->reportError = [&reported](const QString&, const QString& message) { reported = message; };
    QSignalSpy finished(window_, &MainWindow::loadFinished);
    window_->openFile(broken);
    QVERIFY(window_->isBusy());
    QVERIFY(finished.wait(20000));
    window_->reportError = previous;

    QCOMPARE(finished.first().first().toBool(), false);
    QVERIFY2(reported.contains("broken.glb"), qPrintable("error does not name the file: " + reported));
    QCOMPARE(allPositions(*doc()), before);
    QCOMPARE(window_->windowTitle(), title);
    QVERIFY(doc()->boneRotation(upperarm).has_value());
    doc()->setBoneRotation(upperarm, std::nullopt);
  }

  void unsavedChangesAreAskedAboutOnlyOnceTheNewFileIsRead() {
    QTemporaryDir dir;
    const QString broken = dir.filePath("broken.glb");
    QFile file(broken);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("not a glTF");
    file.close();
    const int upperarm = bone("upperarm_l");
    doc()->undoStack()->push(new SetBoneRotationCommand(doc(), upperarm, quatFromEulerDegrees({0, 0, 25})));
    QVERIFY(doc()->isModified());
    const std::vector<float> before = allPositions(*doc());

    int asked = 0;
    auto previousConfirm = window_->confirmDiscardChanges;
    auto previousReport = window_->reportError;
    window_->confirmDiscardChanges = [&asked] { return ++asked, false; };
    window_->reportError = [](const QString&, const QString&) {};
    QSignalSpy finished(window_, &MainWindow::loadFinished);
    window_->openFile(broken);  // fails: nothing to ask
    QVERIFY(finished.wait(20000));
    QCOMPARE(asked, 0);
    window_->openFile("default");  // read, then the user keeps the open document
    QVERIFY(finished.wait(20000));
    QCOMPARE(asked, 1);
    QCOMPARE(finished.last().first().toBool(), false);
    QVERIFY(doc()->isModified());
    QCOMPARE(allPositions(*doc()), before);
    window_->confirmDiscardChanges = previousConfirm;
    window_->reportError = previousReport;
    QString error;
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
  }

  void saveAsProposesTheDocumentsFolderForExamples() {
    QTemporaryDir dir;
    const QString documents = dir.filePath("Documents");
    // An example scene: its name, in the user's documents.
    QCOMPARE(MainWindow::saveAsProposal("/opt/mannequin/resources/scenes/hair_bob.json", "Mannequin", documents),
             QDir(documents).filePath("hair_bob.mqscene"));
    // A character file that is not a scene yet: the character's name.
    QCOMPARE(MainWindow::saveAsProposal("", "CesiumMan", documents), QDir(documents).filePath("CesiumMan.mqscene"));
    // The user's own scene, in a folder they can write: where it is.
    const QString own = dir.filePath("mine.mqscene");
    QCOMPARE(MainWindow::saveAsProposal(own, "Mannequin", documents), own);
  }

  void windowStaysResponsiveWhileLoading() {
    // The default mannequin is polygonised on a worker thread: the event
    // loop keeps running meanwhile. Only the worker's part is measured:
    // installing the loaded document (new actors, a first render) is the UI
    // thread's own work and blocks the loop by design.
    int ticksWhileReading = 0;
    QElapsedTimer clock;
    qint64 readingMs = -1;
    QTimer ticker;
    connect(&ticker, &QTimer::timeout, [&] {
      if (window_->isBusy()) ++ticksWhileReading;
    });
    // The renders the earlier tests queued run first, so that they are not
    // counted against the load.
    QTest::qWait(500);
    QSignalSpy finished(window_, &MainWindow::loadFinished);
    connect(window_, &MainWindow::busyChanged, this, [&](bool busy) {
      if (!busy) readingMs = clock.elapsed();
    });
    ticker.start(5);
    clock.start();
    window_->openFile("default");
    QVERIFY(window_->isBusy());
    QVERIFY(finished.wait(30000));
    disconnect(window_, &MainWindow::busyChanged, this, nullptr);
    QCOMPARE(finished.first().first().toBool(), true);
    QVERIFY(!window_->isBusy());
    QVERIFY(readingMs >= 0);
    // A read on the UI thread would block the timer for its whole length
    // (missed ticks coalesce into one). Each tick may wait for a repaint of
    // the busy bar (software GL composes the whole window: about 45 ms
    // here, twice that when other tests share the cores), so ask for one
    // tick per 150 ms of reading, at least two: the loop ran while the
    // worker did.
    const qint64 expected = std::max<qint64>(2, readingMs / 150);
    qInfo("%d ticks in %lld ms of reading", ticksWhileReading, readingMs);
    QVERIFY2(ticksWhileReading >= expected,
             qPrintable(QString("%1 ticks in %2 ms of reading").arg(ticksWhileReading).arg(readingMs)));
  }

  // File > New after a scene with garments, colliders and hair: every dock
  // starts empty again, with nothing left of the old scene.
  void newClearsEveryDock() {
    auto* garments = window_->findChild<GarmentTool*>();
    auto* hair = window_->findChild<HairTool*>();
    QVERIFY(garments && hair);
    QString error;
    QVERIFY2(window_->openFileNow(MANNEQUIN_SOURCE_DIR "/resources/scenes/garment_tshirt_walk.json", &error),
             qPrintable(error));
    QVERIFY(garments->garmentCount() > 0);
    garments->setSelectedVertices({0, 1, 2});
    garments->addCollider(cloth::PrimitiveCollider::Shape::Sphere);
    QVERIFY(garments->colliderCount() > 0);
    const auto previousConfirm = window_->confirmDiscardChanges;
    window_->confirmDiscardChanges = [] { return true; };
    QSignalSpy finished(window_, &MainWindow::loadFinished);
    QAction* newAction = nullptr;
    for (QAction* action : window_->findChildren<QAction*>())
      if (action->shortcut() == QKeySequence(QKeySequence::New)) newAction = action;
    QVERIFY(newAction != nullptr);
    newAction->trigger();  // File > New, as the user chooses it
    QVERIFY(finished.wait(30000));
    QCOMPARE(garments->garmentCount(), 0);
    QCOMPARE(garments->colliderCount(), 0);
    QVERIFY(garments->selectedVertices().empty());
    QVERIFY(!garments->hasBake() && garments->bakeOutOfDate().isEmpty());
    QVERIFY(!garments->hasSheet());

    QVERIFY2(window_->openFileNow(MANNEQUIN_SOURCE_DIR "/resources/scenes/hair_bob.json", &error), qPrintable(error));
    QVERIFY(hair->hasHair());
    newAction->trigger();
    QVERIFY(finished.wait(30000));
    QVERIFY(!hair->hasHair());
    QVERIFY(!hair->hasBake());
    QVERIFY(doc()->documentPath().isEmpty());
    QVERIFY(!doc()->isModified());
    QVERIFY(doc()->undoStack()->count() == 0);
    window_->confirmDiscardChanges = previousConfirm;
  }

  void saveAndReopenKeepsThePose() {
    QTemporaryDir dir;
    const QString path = dir.filePath("pose.mqscene");
    const int forearm = bone("forearm_r");
    doc()->undoStack()->push(new SetBoneRotationCommand(doc(), forearm, quatFromEulerDegrees({-35, 10, 5})));
    const glm::quat edit = *doc()->boneRotation(forearm);
    QString error;
    QVERIFY2(window_->saveDocument(path, &error), qPrintable(error));
    QVERIFY(!window_->isWindowModified());
    QVERIFY(window_->windowTitle().contains("pose.mqscene"));

    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    QVERIFY(!doc()->boneRotation(forearm).has_value());
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QVERIFY(doc()->boneRotation(forearm).has_value());
    QVERIFY(std::abs(std::abs(glm::dot(*doc()->boneRotation(forearm), edit)) - 1.0f) < 1e-5f);
  }

  void materialEditsAreUndoableAndSavedAsOverrides() {
    QString error;
    const QString cesium = QString(MANNEQUIN_SHARED_DIR) + "/assets/characters/CesiumMan/glTF/CesiumMan.gltf";
    QVERIFY2(window_->openFileNow(cesium, &error), qPrintable(error));
    QCOMPARE(doc()->character().materials.size(), size_t(1));
    // The scene tree lists the material; clicking it shows the Material page.
    const auto items = window_->sceneTree()->tree()->findItems("Cesium_Man-effect", Qt::MatchRecursive);
    QCOMPARE(items.size(), 1);
    window_->sceneTree()->tree()->setCurrentItem(items[0]);
    QCOMPARE(doc()->selectedMaterial(), 0);
    MaterialPage* page = window_->properties()->materialPage();
    QVERIFY(page->isVisible());
    QCOMPARE(page->roughnessBox()->value(), 1.0);
    QVERIFY2(!page->thumbnailLabel()->pixmap().isNull(), "the base colour texture's thumbnail");

    const int commands = doc()->undoStack()->index();
    page->roughnessBox()->setValue(0.35);
    QCOMPARE(doc()->undoStack()->index(), commands + 1);
    QCOMPARE(doc()->character().materials[0].roughnessFactor, 0.35f);
    QCOMPARE(window_->sceneView()->materials()[0].roughnessFactor, 0.35f);
    page->skinBox()->setChecked(true);
    QCOMPARE(doc()->undoStack()->index(), commands + 2);
    QVERIFY(doc()->character().materials[0].skin);
    QVERIFY(page->resetButton()->isEnabled());
    SceneDocument saved = doc()->sceneDocument();
    QCOMPARE(saved.materials.size(), size_t(1));
    QCOMPARE(*saved.materials.at("Cesium_Man-effect").roughness, 0.35f);
    QVERIFY(saved.materials.at("Cesium_Man-effect").skin.value_or(false));
    QVERIFY(!saved.materials.at("Cesium_Man-effect").metallic);  // untouched fields stay the file's

    doc()->undoStack()->undo();
    QVERIFY(!doc()->character().materials[0].skin);
    QVERIFY(!page->skinBox()->isChecked());

    // Saved and reopened: the file's material with the user's roughness.
    QTemporaryDir dir;
    const QString path = dir.filePath("materials.mqscene");
    QVERIFY2(window_->saveDocument(path, &error), qPrintable(error));
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QCOMPARE(doc()->character().materials[0].roughnessFactor, 0.35f);
    QCOMPARE(doc()->fileMaterial(0)->roughnessFactor, 1.0f);
    // Reset to the file: one undo step, and nothing left to save.
    doc()->selectMaterial(0);
    page->resetButton()->click();
    QCOMPARE(doc()->character().materials[0].roughnessFactor, 1.0f);
    QVERIFY(doc()->sceneDocument().materials.empty());
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
  }

  void skinningChoiceIsUndoableAndSaved() {
    // Bend the left elbow 120 degrees (local +X flexes it), then switch the
    // skinning on the character page as a user would.
    const int forearm = bone("forearm_l");
    doc()->undoStack()->push(new SetBoneRotationCommand(doc(), forearm, quatFromEulerDegrees({120, 0, 0})));
    doc()->selectBone(-1);
    QComboBox* box = window_->properties()->skinningBox();
    QCOMPARE(doc()->skinning(), SkinningMethod::Lbs);
    const std::vector<float> lbs = allPositions(*doc());
    const int commands = doc()->undoStack()->index();
    const int cones = box->findData(int(SkinningMethod::Cones));
    box->setCurrentIndex(cones);
    emit box->activated(cones);
    QCOMPARE(doc()->skinning(), SkinningMethod::Cones);
    QCOMPARE(doc()->undoStack()->index(), commands + 1);
    const std::vector<float> corrected = allPositions(*doc());
    QVERIFY2(maxDifference(lbs, corrected) > 0.01f, "switching from LBS to cones at a 120-degree elbow moved nothing");

    doc()->undoStack()->undo();
    QCOMPARE(doc()->skinning(), SkinningMethod::Lbs);
    QCOMPARE(allPositions(*doc()), lbs);
    QCOMPARE(box->currentData().toInt(), int(SkinningMethod::Lbs));
    doc()->undoStack()->redo();
    QCOMPARE(allPositions(*doc()), corrected);

    // The crossings count (on a worker): the creases remove most of the
    // bent elbow's crossings.
    const long withCones = countCrossings();
    doc()->undoStack()->undo();
    const long withLbs = countCrossings();
    doc()->undoStack()->redo();
    QVERIFY2(withCones >= 0 && withLbs >= 0 && withCones < withLbs,
             qPrintable(QString("crossings: cones %1, lbs %2").arg(withCones).arg(withLbs)));

    QTemporaryDir dir;
    const QString path = dir.filePath("skin.mqscene");
    QString error;
    QVERIFY2(window_->saveDocument(path, &error), qPrintable(error));
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    QCOMPARE(doc()->skinning(), SkinningMethod::Lbs);
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QCOMPARE(doc()->skinning(), SkinningMethod::Cones);
    QCOMPARE(allPositions(*doc()), corrected);
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
  }

  void helperBonesAreUndoableAndSaved() {
    // Bend the left elbow 120 degrees, then tick Helper bones as a user would.
    const int forearm = bone("forearm_l");
    doc()->undoStack()->push(new SetBoneRotationCommand(doc(), forearm, quatFromEulerDegrees({120, 0, 0})));
    QCheckBox* box = window_->properties()->helperBonesBox();
    QVERIFY(!box->isChecked());
    const int bones = doc()->character().skeleton.boneCount();
    const std::vector<float> plain = allPositions(*doc());
    const int commands = doc()->undoStack()->index();
    box->click();
    QVERIFY(doc()->helperBones());
    QCOMPARE(doc()->undoStack()->index(), commands + 1);
    QCOMPARE(doc()->character().skeleton.boneCount(), bones + 14);
    const std::vector<float> helped = allPositions(*doc());
    QVERIFY2(maxDifference(plain, helped) > 0.005f, "helper bones at a 120-degree elbow moved nothing");
    QVERIFY(doc()->poseEdits().rotations.count(forearm) == 1);  // the pose is kept

    doc()->undoStack()->undo();
    QVERIFY(!doc()->helperBones());
    QVERIFY(!box->isChecked());
    QCOMPARE(doc()->character().skeleton.boneCount(), bones);
    QVERIFY2(maxDifference(plain, allPositions(*doc())) < 1e-5f, "removing the helpers did not restore the skin");
    doc()->undoStack()->redo();

    QTemporaryDir dir;
    const QString path = dir.filePath("helpers.mqscene");
    QString error;
    QVERIFY2(window_->saveDocument(path, &error), qPrintable(error));
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    QVERIFY(!doc()->helperBones());
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QVERIFY(doc()->helperBones());
    QVERIFY(box->isChecked());
    QVERIFY2(maxDifference(helped, allPositions(*doc())) < 1e-5f, "the reopened document poses differently");
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
  }

  void weightRebuildShowsProgressAndCanBeCancelled() {
    QCheckBox* box = window_->properties()->regenerateWeightsBox();
    QVERIFY(!box->isChecked());
    const std::vector<float> fileSkin = doc()->character().meshes[0].skin.weights;
    const int commands = doc()->undoStack()->index();
    // Cancel the rebuild as soon as its progress dialog shows (the rebuild
    // runs events between its steps).
    bool shown = false;
    int largestValue = 0;
    QTimer poll;
    poll.setInterval(10);
    connect(&poll, &QTimer::timeout, [&] {
      auto* dialog = window_->properties()->findChild<QProgressDialog*>("weightsProgress");
      if (!dialog || !dialog->isVisible()) return;
      largestValue = std::max(largestValue, dialog->value());
      if (largestValue > 0) shown = true, dialog->cancel();
    });
    poll.start();
    box->click();
    poll.stop();
    QVERIFY2(shown, "no progress was shown during the rebuild");
    QVERIFY(!box->isChecked());
    QVERIFY(!doc()->weightSettings().active());
    QCOMPARE(doc()->undoStack()->index(), commands);
    QCOMPARE(doc()->character().meshes[0].skin.weights, fileSkin);
  }

  void regeneratedWeightsAreUndoableAndSaved() {
    // Bend the left knee and add helper bones, then tick Regenerate.
    const int shin = bone("shin_l");
    doc()->undoStack()->push(new SetBoneRotationCommand(doc(), shin, quatFromEulerDegrees({-120, 0, 0})));
    window_->properties()->helperBonesBox()->click();
    QVERIFY(doc()->helperBones());
    QCheckBox* box = window_->properties()->regenerateWeightsBox();
    QVERIFY(!box->isChecked());
    const std::vector<float> filePose = allPositions(*doc());
    const std::vector<float> fileSkin = doc()->character().meshes[0].skin.weights;
    const int commands = doc()->undoStack()->index();
    box->click();
    QCOMPARE(doc()->undoStack()->index(), commands + 1);
    QVERIFY(doc()->weightSettings().regenerate);
    QVERIFY(doc()->helperBones());
    QVERIFY2(doc()->weightReport().vertices > 0, "no report of the rebuild");
    QVERIFY(window_->properties()->weightsLabel()->text().contains("blended"));
    const std::vector<float> rebuilt = allPositions(*doc());
    QVERIFY2(maxDifference(filePose, rebuilt) > 0.002f, "regenerated weights moved nothing at a bent knee");

    doc()->undoStack()->undo();
    QVERIFY(!box->isChecked());
    QCOMPARE(doc()->character().meshes[0].skin.weights, fileSkin);
    QVERIFY2(maxDifference(filePose, allPositions(*doc())) < 1e-6f, "undo did not give the file's weights back");
    doc()->undoStack()->redo();

    QTemporaryDir dir;
    const QString path = dir.filePath("weights.mqscene");
    QString error;
    QVERIFY2(window_->saveDocument(path, &error), qPrintable(error));
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    QVERIFY(!doc()->weightSettings().active());
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QVERIFY(doc()->weightSettings().regenerate);
    QVERIFY(box->isChecked());
    QVERIFY2(maxDifference(rebuilt, allPositions(*doc())) < 1e-5f, "the reopened document poses differently");
    // Unticking there gives back the file's weights, which the open kept.
    box->click();
    QVERIFY2(maxDifference(filePose, allPositions(*doc())) < 1e-5f, "the reopened scene lost the file's weights");
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
  }

  void weightViewFollowsTheSelectedBone() {
    QAction* action = window_->showWeightsAction();
    QVERIFY(!action->isChecked());
    vtkActor* surface = window_->sceneView()->meshActor(0);
    QVERIFY(surface->GetVisibility());
    action->trigger();
    QVERIFY(doc()->viewSettings().showWeights);
    QVERIFY2(!surface->GetVisibility(), "the weight view did not replace the shaded skin");
    doc()->selectBone(bone("forearm_l"));
    QTemporaryDir dir;
    const QString path = dir.filePath("weights-view.mqscene");
    QString error;
    QVERIFY2(window_->saveDocument(path, &error), qPrintable(error));
    action->trigger();
    QVERIFY(!doc()->viewSettings().showWeights);
    QVERIFY(window_->sceneView()->meshActor(0)->GetVisibility());
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QVERIFY(doc()->viewSettings().showWeights);
    QVERIFY(action->isChecked());
    QVERIFY(!window_->sceneView()->meshActor(0)->GetVisibility());
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    QVERIFY(window_->sceneView()->meshActor(0)->GetVisibility());
  }

  void sectionConesShowAndHide() {
    QAction* action = window_->showConesAction();
    QVERIFY(!action->isChecked());
    QCOMPARE(window_->sceneView()->sectionConeCount(), 0);
    action->trigger();
    QVERIFY(doc()->viewSettings().showCones);
    QCOMPARE(window_->sceneView()->sectionConeCount(), 15);
    window_->properties()->helperBonesBox()->click();  // rebuilds the scene: the cones come back
    QCOMPARE(window_->sceneView()->sectionConeCount(), 15);
    doc()->undoStack()->undo();
    action->trigger();
    QCOMPARE(window_->sceneView()->sectionConeCount(), 0);
  }

  // A static body (the mannequin's surface as an OBJ) gets a skeleton from
  // the Auto-rig box: one undo step, saved with the scene, and gone again on undo.
  void autoRigGivesAStaticBodyBones() {
    QTemporaryDir dir;
    const QString obj = dir.filePath("body.obj");
    QString error;
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    QVERIFY2(window_->exportPosedMesh(obj, &error), qPrintable(error));
    QVERIFY2(window_->openFileNow(obj, &error), qPrintable(error));
    QCOMPARE(doc()->character().skeleton.boneCount(), 0);
    doc()->selectBone(-1);  // the character page
    QCheckBox* box = window_->properties()->autoRigBox();
    QVERIFY(box->isVisibleTo(window_->properties()));
    QVERIFY(!box->isChecked());
    const int commands = doc()->undoStack()->index();
    box->click();
    QCOMPARE(doc()->character().skeleton.boneCount(), 21);
    QVERIFY(doc()->autoRigged() && box->isChecked());
    QCOMPARE(doc()->undoStack()->index(), commands + 1);
    QVERIFY(doc()->character().maxInfluences() > 1);  // blended across the joints
    const QString scene = dir.filePath("rigged.mqscene");
    QVERIFY2(window_->saveDocument(scene, &error), qPrintable(error));
    doc()->undoStack()->undo();
    QCOMPARE(doc()->character().skeleton.boneCount(), 0);
    QVERIFY(!box->isChecked());
    doc()->undoStack()->redo();
    QCOMPARE(doc()->character().skeleton.boneCount(), 21);
    QVERIFY2(window_->openFileNow(scene, &error), qPrintable(error));
    QCOMPARE(doc()->character().skeleton.boneCount(), 21);  // "auto_rig": true
    QVERIFY(doc()->autoRigged());
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    QVERIFY(!window_->properties()->autoRigBox()->isVisibleTo(window_->properties()));  // it has its bones
  }

  void exportWritesTheMesh() {
    QTemporaryDir dir;
    const QString path = dir.filePath("posed.obj");
    QString error;
    QVERIFY2(window_->exportPosedMesh(path, &error), qPrintable(error));
    // The file holds the posed character: one position line per vertex.
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
    size_t positions = 0;
    while (!file.atEnd()) positions += file.readLine().startsWith("v ");
    QCOMPARE(positions, doc()->character().vertexCount());
  }
};

int runHairToolTest(int argc, char** argv);     // hair_tool_test.cpp
int runApplyMotionTest(int argc, char** argv);  // apply_motion_test.cpp
int runHairStallTest(int argc, char** argv);    // hair_stall_test.cpp
int runRecoveryTest(int argc, char** argv);     // recovery_test.cpp
int runMonkeyTest(int argc, char** argv);       // monkey_test.cpp

int main(int argc, char** argv) {
  // The viewport bridge needs its GL format before QApplication exists.
  QSurfaceFormat::setDefaultFormat(VtkViewportWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("MannequinTests");  // keep the user's settings (recent files) apart
  QApplication::setApplicationName("gui_smoke");
  // `mannequin_gui_tests hair [qtest options]`: the hair tool's test.
  if (argc > 1 && std::string(argv[1]) == "hair") return runHairToolTest(argc - 1, argv + 1);
  // `mannequin_gui_tests hair-stall`: the event loop's worst stall during hair edits and an orbit.
  if (argc > 1 && std::string(argv[1]) == "hair-stall") return runHairStallTest(argc - 1, argv + 1);
  // `mannequin_gui_tests motion`: the Apply Motion dialog and its undo.
  if (argc > 1 && std::string(argv[1]) == "motion") return runApplyMotionTest(argc - 1, argv + 1);
  // `mannequin_gui_tests recovery`: a killed editor's edit restored at the next start.
  if (argc > 1 && std::string(argv[1]) == "recovery") return runRecoveryTest(argc - 1, argv + 1);
  // `mannequin_gui_tests monkey [ACTIONS [SEED]]`: random user actions, no crash.
  if (argc > 1 && std::string(argv[1]) == "monkey") return runMonkeyTest(argc - 1, argv + 1);
  mq::ui::exitAfter(120, "gui_smoke");  // never hang
  EditorSmokeTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "editor_smoke_test.moc"
