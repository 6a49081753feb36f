// GUI test of the garment tool (needs X: run under xvfb-run). Drives the
// real main window: adds a T-shirt from the panel, changes a measurement and
// undoes it, edits the fabric, the integrator and the layer, pins vertices
// picked with a rubber-band drag in the viewport, keeps them through rebuilds
// of the mesh, simulates live, bakes a few frames (and cancels a bake),
// scrubs them, bakes again from the kept sewn garment, bakes trousers under
// and over the shirt, adds and edits colliders, saves and reopens the
// document, and opens a sheet-and-colliders scene with no character.
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPushButton>
#include <QRadioButton>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <vtkActor.h>

#include "core/character/posed_character.h"
#include "core/garment/fabric.h"
#include "core/garment/garment.h"
#include "core/garment/parametric_garments.h"
#include "core/garment/pattern_outline.h"
#include "core/io/character_import.h"
#include "core/mesh/mesh.h"
#include "render/collider_actors.h"
#include "render/scene_view.h"
#include "sim/cloth/point_cache.h"
#include "test_window.h"
#include "ui/document/editor_document.h"
#include "ui/export/export_animated_dialog.h"
#include "ui/garment/garment_panel.h"
#include "ui/garment/garment_tool.h"
#include "ui/garment/pattern_view.h"
#include "ui/jobs/long_job.h"
#include "ui/main_window.h"
#include "ui/viewport/vtk_viewport_widget.h"

using namespace mq;
using namespace mq::ui;

namespace {

float maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return INFINITY;
  float d = 0.0f;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

bool allFinite(const std::vector<float>& p) {
  return std::all_of(p.begin(), p.end(), [](float x) { return std::isfinite(x); });
}

bool jsonNear(const nlohmann::json& a, const nlohmann::json& b) {
  if (a.is_number() && b.is_number()) return std::abs(a.get<double>() - b.get<double>()) <= 1e-6;
  if (a.type() != b.type() || a.size() != b.size()) return false;
  if (a.is_array()) {
    for (size_t i = 0; i < a.size(); ++i)
      if (!jsonNear(a[i], b[i])) return false;
    return true;
  }
  if (a.is_object()) {
    for (auto it = a.begin(); it != a.end(); ++it)
      if (!b.contains(it.key()) || !jsonNear(it.value(), b[it.key()])) return false;
    return true;
  }
  return a == b;
}

}  // namespace

class GarmentToolTest : public QObject {
  Q_OBJECT

 private:
  MainWindow* window_ = nullptr;
  GarmentTool* tool_ = nullptr;
  EditorDocument* doc() { return window_->document(); }
  GarmentPanel* panel() { return tool_->panel(); }
  QUndoStack* undo() { return doc()->undoStack(); }

  void renderNow() { mq::ui::renderNow(window_); }

  // MANNEQUIN_TEST_SHOTS=DIR keeps pictures of the window for a person to look at.
  void keepShot(const char* name) {
    const QString dir = qEnvironmentVariable("MANNEQUIN_TEST_SHOTS");
    if (!dir.isEmpty()) window_->grab().save(dir + "/" + name + ".png");
  }

 private slots:
  void initTestCase() {
    window_ = makeTestWindow();
    QVERIFY(QTest::qWaitForWindowExposed(window_));
    QString error;
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    tool_ = window_->findChild<GarmentTool*>();
    QVERIFY(tool_ != nullptr);
    QCOMPARE(tool_->garmentCount(), 0);
    tool_->dock()->raise();
    doc()->setClip(-1);  // the rest pose: the placed panels are shown as built
  }

  void cleanupTestCase() {
    delete window_;
    window_ = nullptr;
  }

  void addTshirtFromThePanel() {
    const int tshirt = panel()->typeCombo()->findData("tshirt");
    QVERIFY(tshirt >= 0);
    panel()->typeCombo()->setCurrentIndex(tshirt);
    QTest::mouseClick(panel()->addButton(), Qt::LeftButton);
    QCOMPARE(tool_->garmentCount(), 1);
    QCOMPARE(tool_->currentGarment(), 0);
    QCOMPARE(panel()->garmentList()->count(), 1);
    const GarmentMesh* mesh = tool_->garmentMesh(0);
    QVERIFY(mesh && mesh->vertexCount() > 500);
    QCOMPARE(tool_->shownPositions(0), mesh->positions);
    // On a posed body the unsimulated panels follow the body.
    doc()->setClip(0);
    doc()->setTime(doc()->clipStart() + 0.5f);
    QVERIFY(maxDifference(tool_->shownPositions(0), mesh->positions) > 0.01f);
    doc()->setClip(-1);
    QCOMPARE(tool_->shownPositions(0), mesh->positions);
    // Stored in the document, which now has unsaved changes.
    QVERIFY(doc()->sceneSections().garments.is_array());
    QCOMPARE(doc()->sceneSections().garments.size(), size_t(1));
    QVERIFY(window_->isWindowModified());
    // The shirt is drawn: the viewport changes where it is.
    renderNow();
    const QImage with = window_->viewport()->grabFramebuffer();
    undo()->undo();
    QCOMPARE(tool_->garmentCount(), 0);
    const QImage without = window_->viewport()->grabFramebuffer();
    undo()->redo();
    QCOMPARE(tool_->garmentCount(), 1);
    int differing = 0;
    for (int y = 0; y < with.height(); y += 2)
      for (int x = 0; x < with.width(); x += 2)
        if (with.pixel(x, y) != without.pixel(x, y)) ++differing;
    QVERIFY2(differing > 500, qPrintable(QString("the shirt changed only %1 pixels").arg(differing)));
  }

  void particleDistanceSetsTheResolution() {
    // A coarser shirt also keeps the simulations below quick.
    const size_t fine = tool_->garmentMesh(0)->vertexCount();
    panel()->particleDistanceField()->setValue(45.0);
    QCOMPARE(tool_->scene().garments[0].targetEdgeLength, 0.045f);
    const size_t coarse = tool_->garmentMesh(0)->vertexCount();
    QVERIFY2(coarse * 3 < fine, qPrintable(QString("%1 -> %2 vertices").arg(fine).arg(coarse)));
    undo()->undo();
    QCOMPARE(tool_->garmentMesh(0)->vertexCount(), fine);
    undo()->redo();
    QCOMPARE(tool_->garmentMesh(0)->vertexCount(), coarse);
  }

  void measurementRebuildsAndUndoes() {
    const std::vector<GarmentParameter> parameters = garmentParameters("tshirt");
    QVERIFY(!parameters.empty());
    // The length measurement (or the first one) as typed in the panel.
    const GarmentParameter* chosen = &parameters[0];
    for (const GarmentParameter& p : parameters)
      if (p.name.find("length") != std::string::npos) chosen = &p;
    QDoubleSpinBox* field = panel()->measurementField(QString::fromStdString(chosen->name));
    QVERIFY(field != nullptr);
    QVERIFY(std::abs(field->minimum() - chosen->min) < 1e-3 && std::abs(field->maximum() - chosen->max) < 1e-3);

    const std::vector<float> before = tool_->garmentMesh(0)->positions;
    const Aabb boxBefore = boundsOf(before);
    const int commands = undo()->index();
    const double changed =
        std::clamp(field->value() + 0.1 * (chosen->max - chosen->min), double(chosen->min), double(chosen->max));
    field->setValue(changed);
    QCOMPARE(undo()->index(), commands + 1);
    const std::vector<float> after = tool_->garmentMesh(0)->positions;
    const Aabb boxAfter = boundsOf(after);
    QVERIFY2(after.size() != before.size() ||
                 glm::length(boxAfter.max - boxBefore.max) + glm::length(boxAfter.min - boxBefore.min) > 0.01f,
             "changing a measurement did not change the garment");
    QCOMPARE(tool_->scene().garments[0].recipe.parameters.at(chosen->name), float(changed));

    undo()->undo();
    QCOMPARE(tool_->garmentMesh(0)->positions, before);  // exactly the old panels
    const auto& parameters0 = tool_->scene().garments[0].recipe.parameters;
    const float shown = parameters0.count(chosen->name) ? parameters0.at(chosen->name) : chosen->value;
    QVERIFY(std::abs(field->value() - shown) < 1e-4);
    undo()->redo();
    QCOMPARE(tool_->garmentMesh(0)->positions, after);
    undo()->undo();
  }

  void patternExportsTheCurrentGarment() {
    QVERIFY(panel()->patternButton()->isEnabled());
    for (QAction* action : panel()->patternExportActions()) QVERIFY(action->isEnabled());
    QTemporaryDir dir;
    const QString path = dir.filePath("tshirt.svg");
    QVERIFY2(tool_->exportPattern(0, path, 0.01f), qPrintable(tool_->lastError()));
    auto read = [](const QString& file) {
      QFile f(file);
      return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
    };
    const QString svg = read(path);
    QCOMPARE(svg.count("class=\"sew\""), 4);  // front, back, two sleeves
    QCOMPARE(svg.count("class=\"cut\""), 4);
    // The pattern is the garment as edited now: a measurement changes it, undo brings it back.
    const std::vector<GarmentParameter> parameters = garmentParameters("tshirt");
    QDoubleSpinBox* field = panel()->measurementField(QString::fromStdString(parameters[0].name));
    QVERIFY(field != nullptr);
    field->setValue(field->value() + 0.1 * (parameters[0].max - parameters[0].min) *
                                         (field->value() < 0.5 * (parameters[0].max + parameters[0].min) ? 1 : -1));
    QVERIFY(tool_->exportPattern(0, path, 0.01f));
    QVERIFY(read(path) != svg);
    undo()->undo();
    QVERIFY(tool_->exportPattern(0, path, 0.01f));
    QCOMPARE(read(path), svg);
    // Refused without a garment, or where no file can be written, saying why.
    QVERIFY(!tool_->exportPattern(-1, path));
    QVERIFY(!tool_->exportPattern(0, dir.filePath("tshirt.svg/inside.svg")));
    QVERIFY2(tool_->lastError().contains("inside.svg"), qPrintable(tool_->lastError()));
  }

  void thePatternDockShowsTheCurrentGarmentAtTrueSize() {
    // The dock's view follows the current garment (it opens on request, in the last test:
    // opening it resizes the viewport, which the live-simulation tests time themselves by).
    PatternView* view = tool_->patternView();
    QVERIFY(!view->isVisible());
    QVERIFY(view->garment().has_value());
    const Garment& shown = *view->garment();
    QCOMPARE(shown.name, tool_->scene().garments[size_t(tool_->currentGarment())].name);
    QCOMPARE(shown.panels.size(), tool_->scene().garments[size_t(tool_->currentGarment())].panels.size());
    // True size: two corners a panel's width apart are that many metres times the scale apart on screen.
    const Panel& first = shown.panels[0];
    const glm::vec2 a = first.corners[0], b = first.corners[1];
    const QPointF pa = view->toWidget(0, a), pb = view->toWidget(0, b);
    QVERIFY(std::abs(std::hypot(pa.x() - pb.x(), pa.y() - pb.y()) - view->scale() * glm::length(b - a)) < 0.01);
    // The built-in T-shirt's sleeve caps are longer than its armholes: those seams are flagged.
    QVERIFY(!view->unevenSeams().empty());
    // Drawn: the first seam's colour is on screen.
    PatternView drawn;  // a view of its own: the dock's stays closed (see the last test)
    drawn.setGarment(shown);
    drawn.resize(900, 300);
    drawn.fit();
    const QImage image = drawn.grab().toImage();
    const QColor seam(seamColour(0));
    int seamPixels = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) seamPixels += image.pixelColor(x, y) == seam;
    QVERIFY2(seamPixels > 20, qPrintable(QString::number(seamPixels)));
    // Another garment chosen: its pattern (edits reach the view the same way, by sceneChanged).
    if (tool_->garmentCount() > 1) {
      const int current = tool_->currentGarment();
      tool_->setCurrentGarment(current == 0 ? 1 : 0);
      QCOMPARE(view->garment()->name, tool_->scene().garments[size_t(tool_->currentGarment())].name);
      tool_->setCurrentGarment(current);
    }
  }

  void aDxfPatternComesInAsAGarmentOneUndoStep() {
    QTemporaryDir dir;
    const QString path = dir.filePath("shirt.dxf");
    QVERIFY2(tool_->exportPattern(0, path, 0.01f), qPrintable(tool_->lastError()));
    const int before = tool_->garmentCount();
    QVERIFY2(tool_->importPattern(path), qPrintable(tool_->lastError()));
    QCOMPARE(tool_->garmentCount(), before + 1);
    const Garment& original = tool_->scene().garments[0];
    const Garment& imported = tool_->scene().garments.back();
    QCOMPARE(imported.panels.size(), original.panels.size());
    QCOMPARE(imported.seams.size(), original.seams.size());
    QVERIFY(imported.name != original.name);  // a second T-shirt is told apart
    QCOMPARE(tool_->currentGarment(), before);
    undo()->undo();
    QCOMPARE(tool_->garmentCount(), before);
    // A broken file: refused, naming it, the scene untouched.
    QFile broken(dir.filePath("broken.dxf"));
    QVERIFY(broken.open(QIODevice::WriteOnly));
    broken.write("0\nSECTION\n2\nENTITIES\n");
    broken.close();
    QVERIFY(!tool_->importPattern(broken.fileName()));
    QVERIFY2(tool_->lastError().contains("broken.dxf") && tool_->lastError().contains("truncated"),
             qPrintable(tool_->lastError()));
    QCOMPARE(tool_->garmentCount(), before);
  }

  void fabricAndIntegratorAreUndoable() {
    QComboBox* fabric = panel()->fabricCombo();
    const int silk = fabric->findText("silk");
    QVERIFY(silk >= 0);
    emit fabric->activated(silk);  // as the user's pick
    QCOMPARE(tool_->scene().garments[0].fabric, std::string("silk"));
    QCOMPARE(tool_->scene().garments[0].solverFabric().massPerArea, fabricPreset("silk").massPerArea);
    undo()->undo();
    QCOMPARE(tool_->scene().garments[0].fabric, std::string("cotton"));

    // A typed value makes a custom fabric based on the preset.
    tool_->setFabric(0, [] {
      Fabric f = fabricPreset("cotton");
      f.bendStiffness *= 4.0f;
      return f;
    }());
    QVERIFY(!fabricIsPreset(tool_->scene().garments[0]));
    QCOMPARE(panel()->fabricCombo()->currentIndex(), panel()->fabricCombo()->count() - 1);  // "(custom)"
    undo()->undo();
    QVERIFY(fabricIsPreset(tool_->scene().garments[0]));

    panel()->clothFpsField()->setValue(30);
    QCOMPARE(tool_->scene().cloth.fps, 30.0f);
    QCOMPARE(doc()->sceneSections().cloth["fps"].get<float>(), 30.0f);
    undo()->undo();
    QCOMPARE(tool_->scene().cloth.fps, 24.0f);

    emit panel()->integratorCombo()->activated(2);  // Verlet
    QCOMPARE(tool_->scene().cloth.settings.integrator, cloth::IntegratorKind::Verlet);
    QCOMPARE(doc()->sceneSections().cloth["integrator"].get<std::string>(), std::string("verlet"));
    undo()->undo();
    QCOMPARE(tool_->scene().cloth.settings.integrator, cloth::IntegratorKind::ImplicitEuler);
    // Back at the defaults: no cloth section is written (it would describe a sheet).
    QVERIFY(doc()->sceneSections().cloth.is_null());
  }

  void layerIsShownSavedAndUndoable() {
    QCOMPARE(panel()->layerField()->value(), 0);
    QVERIFY(panel()->garmentList()->item(0)->text().contains("layer 0"));
    const GarmentMesh* mesh = tool_->garmentMesh(0);
    panel()->layerField()->setValue(2);
    QCOMPARE(tool_->scene().garments[0].layer, 2);
    QVERIFY(panel()->garmentList()->item(0)->text().contains("layer 2"));
    QCOMPARE(doc()->sceneSections().garments[0]["layer"].get<int>(), 2);
    QCOMPARE(tool_->garmentMesh(0), mesh);  // the layer is not geometry: the mesh is kept
    undo()->undo();
    QCOMPARE(tool_->scene().garments[0].layer, 0);
    QCOMPARE(panel()->layerField()->value(), 0);
    QVERIFY(!doc()->sceneSections().garments[0].contains("layer"));
  }

  void rubberBandSelectsAndPins() {
    window_->frameAll();
    renderNow();
    const std::vector<float>& p = tool_->shownPositions(0);
    // A rectangle around the upper tenth of the shirt on screen (the shoulders).
    QRectF onScreen;
    float top = -INFINITY, bottom = INFINITY;
    for (size_t i = 1; i < p.size(); i += 3) top = std::max(top, p[i]), bottom = std::min(bottom, p[i]);
    const float shoulders = top - 0.1f * (top - bottom);
    for (size_t v = 0; v < p.size() / 3; ++v) {
      if (p[3 * v + 1] < shoulders) continue;
      const QPointF w = tool_->toWidget({p[3 * v], p[3 * v + 1], p[3 * v + 2]});
      onScreen = onScreen.isNull() ? QRectF(w, QSizeF(1, 1)) : onScreen.united(QRectF(w, QSizeF(1, 1)));
    }
    QVERIFY(!onScreen.isNull());
    const QRect band = onScreen.toAlignedRect().adjusted(-3, -3, 3, 3);
    QVERIFY(window_->viewport()->rect().contains(band));

    QTest::mouseClick(panel()->selectButton(), Qt::LeftButton);
    QVERIFY(tool_->selectMode());
    QWidget* vp = window_->viewport();
    const glm::vec3 cameraBefore = window_->sceneView()->cameraPosition();
    sendMouse(vp, QEvent::MouseButtonPress, band.topLeft(), Qt::LeftButton, Qt::LeftButton);
    sendMouse(vp, QEvent::MouseMove, band.center(), Qt::NoButton, Qt::LeftButton);
    sendMouse(vp, QEvent::MouseMove, band.bottomRight(), Qt::NoButton, Qt::LeftButton);
    sendMouse(vp, QEvent::MouseButtonRelease, band.bottomRight(), Qt::LeftButton, Qt::NoButton);
    QCOMPARE(window_->sceneView()->cameraPosition(), cameraBefore);  // the drag did not orbit
    const std::vector<uint32_t> selected = tool_->selectedVertices();
    QVERIFY2(selected.size() > 5, qPrintable(QString("selected %1 vertices").arg(selected.size())));
    const QRectF inside = QRectF(band).adjusted(-1, -1, 1, 1);
    for (uint32_t v : selected) QVERIFY(inside.contains(tool_->toWidget({p[3 * v], p[3 * v + 1], p[3 * v + 2]})));
    // Only the front: the back of the shoulders faces away from the camera.
    size_t upper = 0;
    for (size_t v = 0; v < p.size() / 3; ++v) upper += p[3 * v + 1] >= shoulders;
    QVERIFY2(selected.size() < upper, "the rubber band also selected vertices facing away");

    keepShot("garment_selected");
    QTest::mouseClick(panel()->pinButton(), Qt::LeftButton);
    QCOMPARE(tool_->scene().garments[0].pins.vertices, selected);
    keepShot("garment_pinned");
    QCOMPARE(doc()->sceneSections().garments[0]["pins"]["vertices"].size(), selected.size());
    undo()->undo();
    QVERIFY(tool_->scene().garments[0].pins.vertices.empty());
    undo()->redo();
    QCOMPARE(tool_->scene().garments[0].pins.vertices, selected);

    // Shift+drag over half the band adds nothing new outside it; Unpin removes a subset.
    tool_->setSelectedVertices({selected.begin(), selected.begin() + selected.size() / 2});
    QTest::mouseClick(panel()->unpinButton(), Qt::LeftButton);
    QCOMPARE(tool_->scene().garments[0].pins.vertices.size(), selected.size() - selected.size() / 2);
    undo()->undo();
    QCOMPARE(tool_->scene().garments[0].pins.vertices, selected);
    QTest::mouseClick(panel()->selectButton(), Qt::LeftButton);
    QVERIFY(!tool_->selectMode());
  }

  void pinsSurviveRebuilds() {
    const std::vector<uint32_t> pins = tool_->scene().garments[0].pins.vertices;
    QVERIFY(pins.size() > 5);
    const GarmentMesh before = *tool_->garmentMesh(0);
    // Each pin of the rebuilt mesh sits where a pin was (rest pose), within about an edge.
    auto nearOldPins = [&](const GarmentMesh& after, float within) {
      for (uint32_t v : tool_->scene().garments[0].pins.vertices) {
        if (v >= after.vertexCount()) return false;
        float nearest = INFINITY;
        for (uint32_t p : pins) nearest = std::min(nearest, glm::length(after.position(v) - before.position(p)));
        if (nearest > within) return false;
      }
      return true;
    };

    // A finer mesh: other vertex indices, the pins carried over.
    panel()->particleDistanceField()->setValue(35.0);
    const GarmentMesh& finer = *tool_->garmentMesh(0);
    QVERIFY(finer.vertexCount() != before.vertexCount());
    QVERIFY2(tool_->scene().garments[0].pins.vertices.size() >= pins.size() / 2,
             qPrintable(
                 QString("%1 of %2 pins kept").arg(tool_->scene().garments[0].pins.vertices.size()).arg(pins.size())));
    QVERIFY(nearOldPins(finer, 0.05f));
    QCOMPARE(doc()->sceneSections().garments[0]["pins"]["vertices"].size(),
             tool_->scene().garments[0].pins.vertices.size());
    undo()->undo();
    QCOMPARE(tool_->scene().garments[0].pins.vertices, pins);  // exactly the old pins
    QCOMPARE(tool_->garmentMesh(0)->vertexCount(), before.vertexCount());

    // A longer shirt: the shoulder pins stay at the shoulders.
    QDoubleSpinBox* length = panel()->measurementField("length");
    QVERIFY(length != nullptr);
    length->setValue(length->value() + 0.06);
    QVERIFY(!tool_->scene().garments[0].pins.vertices.empty());
    const GarmentMesh& longer = *tool_->garmentMesh(0);
    float top = -INFINITY;
    for (size_t v = 0; v < longer.vertexCount(); ++v) top = std::max(top, longer.position(v).y);
    for (uint32_t v : tool_->scene().garments[0].pins.vertices) QVERIFY(longer.position(v).y > top - 0.12f);
    undo()->undo();
    QCOMPARE(tool_->scene().garments[0].pins.vertices, pins);
    QCOMPARE(tool_->garmentMesh(0)->positions, before.positions);
  }

  void liveSimulationStepsWithoutBlocking() {
    const std::vector<float> rest = tool_->garmentMesh(0)->positions;
    QTest::mouseClick(panel()->simulateButton(), Qt::LeftButton);
    QVERIFY(tool_->simulating());
    // The event loop keeps running (QTRY spins it) while steps complete on the worker.
    QTRY_VERIFY_WITH_TIMEOUT(tool_->simulatedSteps() >= 3, 60000);
    // Running is plain to see, and so is whether it keeps up with the clip.
    QCOMPARE(panel()->simulateButton()->text(), QString("Stop simulating"));
    QVERIFY(tool_->simulatedFramesPerSecond() > 0.0);
    QVERIFY2(panel()->statusText().contains(QString("of %1 frames/s").arg(tool_->scene().cloth.fps, 0, 'f', 0)),
             qPrintable(panel()->statusText()));
    QTest::mouseClick(panel()->simulateButton(), Qt::LeftButton);
    QVERIFY(!tool_->simulating());
    QCOMPARE(panel()->simulateButton()->text(), QString("Simulate"));
    const std::vector<float>& shown = tool_->shownPositions(0);
    QVERIFY(allFinite(shown));
    QVERIFY2(maxDifference(shown, rest) > 1e-4f, "the live simulation did not move the cloth");
    QVERIFY(maxDifference(shown, rest) < 0.5f);
    QCOMPARE(tool_->shownStretch(0).size(), tool_->garmentMesh(0)->vertexCount());
  }

  void bakeCancelsThenBakesAndScrubs() {
    QVERIFY(doc()->character().clips.size() > 0);
    doc()->setClip(0);
    const float start = doc()->clipStart();
    // Cancel: the dialog's Cancel as the user would press it, shortly after the
    // bake starts (polled: after a fixed delay, a fast machine had finished it).
    QTimer cancelSoon;
    connect(&cancelSoon, &QTimer::timeout, tool_, [&] {
      if (!tool_->baking()) return;
      tool_->cancelBake();
      cancelSoon.stop();
    });
    cancelSoon.start(10);
    QVERIFY(!tool_->bake(start, start + 2.0f));
    QVERIFY(!tool_->hasBake());
    QVERIFY(!tool_->baking());

    QVERIFY2(tool_->bake(start, start + 0.25f), qPrintable(tool_->lastError()));
    QVERIFY(tool_->hasBake());
    const int frames = tool_->bakedFrameCount();
    QCOMPARE(frames, int(std::floor(0.25f * tool_->scene().cloth.fps + 1e-3f)) + 1);
    // A cancelled bake leaves the previous one as it was.
    doc()->setTime(start + 0.2f);
    const std::vector<float> before = tool_->shownPositions(0);
    cancelSoon.start(10);
    QVERIFY(!tool_->bake(start, start + 2.0f));
    QVERIFY(tool_->hasBake());
    QCOMPARE(tool_->bakedFrameCount(), frames);
    QCOMPARE(maxDifference(tool_->shownPositions(0), before), 0.0f);

    doc()->setTime(start);
    const std::vector<float> first = tool_->shownPositions(0);
    doc()->setTime(start + 0.25f);
    const std::vector<float> last = tool_->shownPositions(0);
    QVERIFY(allFinite(first) && allFinite(last));
    QVERIFY2(maxDifference(first, last) > 1e-5f, "scrubbing the bake shows the same frame");
    QVERIFY(maxDifference(first, tool_->garmentMesh(0)->positions) > 1e-3f);  // simulated, not the rest panels
    // Pinned vertices stay with the body: they barely move between frames.
    for (uint32_t v : tool_->scene().garments[0].pins.vertices)
      QVERIFY(std::abs(first[3 * v + 1] - last[3 * v + 1]) < 0.05f);

    // Export: one OBJ per baked frame, each with the garment's vertices.
    QVERIFY(panel()->exportBakeButton()->isEnabled());
    const QString exportDir = QDir(QDir::tempPath()).filePath("mannequin_bake_export");
    QDir(exportDir).removeRecursively();
    QVERIFY2(tool_->exportBake(exportDir), qPrintable(tool_->lastError()));
    const QStringList objs = QDir(exportDir).entryList({"garment0_*.obj"}, QDir::Files, QDir::Name);
    QCOMPARE(objs.size(), frames);
    QFile lastObj(QDir(exportDir).filePath(objs.back()));
    QVERIFY(lastObj.open(QIODevice::ReadOnly | QIODevice::Text));
    size_t objVertices = 0;
    float lastY = 0.0f;
    while (!lastObj.atEnd()) {
      const QByteArray line = lastObj.readLine();
      if (!line.startsWith("v ")) continue;
      ++objVertices;
      if (objVertices == 1) lastY = line.split(' ').at(2).toFloat();
    }
    QCOMPARE(objVertices, tool_->garmentMesh(0)->vertexCount());
    QVERIFY(std::abs(lastY - last[1]) < 1e-4f);  // the last frame as baked
    // As point caches: one .pc2 per garment with every frame, and its mesh.
    const QString cacheDir = QDir(QDir::tempPath()).filePath("mannequin_bake_pc2");
    QDir(cacheDir).removeRecursively();
    QVERIFY2(tool_->exportBake(cacheDir, true), qPrintable(tool_->lastError()));
    const QStringList caches = QDir(cacheDir).entryList({"garment0_*.pc2"}, QDir::Files);
    QCOMPARE(caches.size(), 1);
    const cloth::PointCache cache = cloth::readPointCache(QDir(cacheDir).filePath(caches[0]).toStdString());
    QCOMPARE(int(cache.samples.size()), frames);
    QCOMPARE(cache.samples.back(), last);
    QVERIFY(QFile::exists(QDir(cacheDir).filePath(QString(caches[0]).replace(".pc2", ".obj"))));
    QDir(cacheDir).removeRecursively();
    // Into a path that cannot be a folder: refused, naming it.
    QFile blocker(QDir(exportDir).filePath("not_a_folder"));
    QVERIFY(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    QVERIFY(!tool_->exportBake(blocker.fileName() + "/inside"));
    QVERIFY2(tool_->lastError().contains("not_a_folder"), qPrintable(tool_->lastError()));
    QDir(exportDir).removeRecursively();

    // File > Export Animated glTF: the character playing the baked range,
    // the garment as a morph-target surface showing each baked frame.
    QTemporaryDir gltfDir;
    const QString gltf = gltfDir.filePath("take.glb");
    QString error;
    const QString summary = window_->exportAnimatedGltf(gltf, &error);
    QVERIFY2(!summary.isEmpty(), qPrintable(error));
    QVERIFY2(summary.contains(QString("%1 frames").arg(frames)), qPrintable(summary));
    const Character take = importCharacter(gltf.toStdString());
    QCOMPARE(take.meshes.size(), doc()->character().meshes.size() + 1);
    QCOMPARE(take.clips.size(), size_t(1));
    PosedCharacter played;
    played.evaluate(take, 0, (frames - 1) / tool_->scene().cloth.fps, nullptr, nullptr);
    QVERIFY(maxDifference(played.meshes().back().positions, last) < 1e-5f);

    // The export dialog: the take is offered (a garment bake, no hair bake),
    // Export wants a glTF path, and the take's point caches land beside it.
    {
      ExportAnimatedDialog dialog(window_->exportAnimatedSources(), gltfDir.filePath("dialog.txt"));
      QVERIFY(dialog.takeButton()->isEnabled() && dialog.takeButton()->isChecked());
      QVERIFY(dialog.garmentsBox()->isEnabled() && dialog.garmentsBox()->isChecked());
      QVERIFY(!dialog.hairBox()->isEnabled());
      QVERIFY(!dialog.exportButton()->isEnabled());  // not a .glb or .gltf
      dialog.pathEdit()->setText(gltfDir.filePath("dialog.gltf"));
      QVERIFY(dialog.exportButton()->isEnabled());
      dialog.pointCacheBox()->setCurrentIndex(dialog.pointCacheBox()->findData(QString("mdd")));
      if (const QString shots = qEnvironmentVariable("MANNEQUIN_TEST_SHOTS"); !shots.isEmpty()) {
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        dialog.grab().save(shots + "/export_animated_dialog.png");
        dialog.hide();
      }
      const QString taken = window_->exportAnimated(dialog.choice(), &error);
      QVERIFY2(taken.contains("1 point cache"), qPrintable(taken + error));
      const QStringList mdd = QDir(gltfDir.path()).entryList({"dialog_*.mdd"}, QDir::Files);
      QCOMPARE(mdd.size(), 1);
      const cloth::PointCache cached = cloth::readMdd(QDir(gltfDir.path()).filePath(mdd[0]).toStdString());
      QCOMPARE(int(cached.samples.size()), frames);
      QVERIFY(maxDifference(cached.samples.back(), last) == 0.0f);
      // Every clip instead: the character alone, no surface, no cache.
      dialog.clipsButton()->setChecked(true);
      QVERIFY(!dialog.pointCacheBox()->isEnabled());
      dialog.pathEdit()->setText(gltfDir.filePath("clips.glb"));
      const ExportAnimatedChoice clips = dialog.choice();
      QVERIFY(!clips.take && clips.pointCache.isEmpty());
      QVERIFY2(!window_->exportAnimated(clips, &error).isEmpty(), qPrintable(error));
      const Character exported = importCharacter(gltfDir.filePath("clips.glb").toStdString());
      QCOMPARE(exported.meshes.size(), doc()->character().meshes.size());
      QCOMPARE(exported.clips.size(), doc()->character().clips.size());
    }

    // The stretch overlay has a value per vertex.
    QTest::mouseClick(panel()->stretchCheck(), Qt::LeftButton);
    QVERIFY(tool_->stretchVisible());
    const std::vector<float>& stretch = tool_->shownStretch(0);
    QCOMPARE(stretch.size(), tool_->garmentMesh(0)->vertexCount());
    QVERIFY(*std::max_element(stretch.begin(), stretch.end()) >= 1.0f);
    renderNow();
    keepShot("garment_stretch");
    QTest::mouseClick(panel()->stretchCheck(), Qt::LeftButton);

    // Editing the fabric invalidates the bake.
    tool_->setFabricPreset(0, "denim");
    QVERIFY(!tool_->hasBake());
    undo()->undo();
    doc()->setClip(-1);
  }

  void bakeReusesTheSewnGarment() {
    doc()->setClip(0);
    const float start = doc()->clipStart();
    QVERIFY2(tool_->bake(start, start + 0.1f), qPrintable(tool_->lastError()));
    doc()->setTime(start);
    const std::vector<float> first = tool_->shownPositions(0);
    const int runs = tool_->sewingRuns(), reused = tool_->reusedSewings();
    // The same garment, fabric, pins, settings and body: no sewing, the same first frame.
    QVERIFY2(tool_->bake(start, start + 0.1f), qPrintable(tool_->lastError()));
    QCOMPARE(tool_->sewingRuns(), runs);
    QCOMPARE(tool_->reusedSewings(), reused + 1);
    doc()->setTime(start);
    QVERIFY(maxDifference(tool_->shownPositions(0), first) < 1e-6f);
    // Simulate starts from the baked frame on screen: no sewing, no draping.
    const int warm = tool_->warmStarts();
    tool_->setSimulating(true);
    QCOMPARE(tool_->warmStarts(), warm + 1);
    QCOMPARE(tool_->sewingRuns(), runs);
    QCOMPARE(tool_->simulationPhase(), QString("Following the clip"));
    QVERIFY(maxDifference(tool_->shownPositions(0), first) < 1e-4f);
    tool_->setSimulating(false);
    QVERIFY2(tool_->bake(start, start + 0.1f), qPrintable(tool_->lastError()));
    // Another fabric: the bake is out of date and says why; the drape stays
    // on screen, and the next bake starts from it instead of sewing again.
    doc()->setTime(start);
    const std::vector<float> cotton = tool_->shownPositions(0);
    tool_->setFabricPreset(0, "silk");
    QVERIFY(!tool_->hasBake());
    QCOMPARE(tool_->bakeOutOfDate(), QString("fabric changed"));
    QVERIFY(maxDifference(tool_->shownPositions(0), cotton) < 1e-4f);
    QVERIFY2(tool_->bake(start, start + 0.1f), qPrintable(tool_->lastError()));
    QCOMPARE(tool_->sewingRuns(), runs);
    QVERIFY(tool_->bakeOutOfDate().isEmpty());
    doc()->setTime(start);
    const std::vector<float> silk = tool_->shownPositions(0);
    QVERIFY(maxDifference(silk, cotton) > 1e-5f);  // simulated again, with silk
    QVERIFY(maxDifference(silk, cotton) < 0.1f);   // from the cotton drape, not from flat panels
    // Undo: cotton again, and its drape with it.
    undo()->undo();
    QCOMPARE(tool_->scene().garments[0].fabric, std::string("cotton"));
    QVERIFY(!tool_->hasBake());
    QVERIFY(maxDifference(tool_->shownPositions(0), cotton) < 1e-4f);
    doc()->setClip(-1);
  }

  // The complaint: every edit dropped the drape (the shirt snapped
  // back to flat panels), and pins chosen on the drape pulled it back
  // towards where the panels had been placed.
  void editsKeepTheDrapeAndPinsHoldItWhereItIs() {
    const int undoIndex = undo()->index();
    // The earlier tests' pins were chosen on the flat panels and hold the
    // drape where the panels were placed: without them it relaxes.
    tool_->clearPins();
    tool_->setSimulating(true);
    QTRY_VERIFY_WITH_TIMEOUT(tool_->simulationPhase() == QString("Following the clip") && tool_->simulatedSteps() >= 30,
                             60000);
    tool_->setSimulating(false);
    const std::vector<float> drape = tool_->shownPositions(0);
    const GarmentMesh before = *tool_->garmentMesh(0);
    const int runs = tool_->sewingRuns();
    const float drapeStretch = *std::max_element(tool_->shownStretch(0).begin(), tool_->shownStretch(0).end());
    QVERIFY2(drapeStretch < 1.105f, qPrintable(QString("the drape is stretched %1 times").arg(drapeStretch)));
    QVERIFY(maxDifference(drape, before.positions) > 0.01f);  // a drape, not the placed panels

    // A finer mesh: the drape comes along instead of the flat panels.
    panel()->particleDistanceField()->setValue(1000.0 * tool_->scene().garments[0].targetEdgeLength * 0.8);
    const GarmentMesh& finer = *tool_->garmentMesh(0);
    QVERIFY(finer.vertexCount() > before.vertexCount());
    const std::vector<float> carried = tool_->shownPositions(0);
    QVERIFY(maxDifference(carried, finer.positions) > 0.01f);
    float farthest = 0.0f;  // from the old drape's surface, roughly: its nearest vertex
    for (size_t v = 0; v < finer.vertexCount(); ++v) {
      float nearest = INFINITY;
      for (size_t w = 0; w < before.vertexCount(); ++w)
        nearest = std::min(nearest, glm::distance(glm::vec3(carried[3 * v], carried[3 * v + 1], carried[3 * v + 2]),
                                                  glm::vec3(drape[3 * w], drape[3 * w + 1], drape[3 * w + 2])));
      farthest = std::max(farthest, nearest);
    }
    QVERIFY2(farthest < 0.03f, qPrintable(QString("%1 m off the old drape").arg(farthest)));
    // Simulate continues from it: no sewing, nothing torn.
    const int warm = tool_->warmStarts();
    tool_->setSimulating(true);
    QCOMPARE(tool_->warmStarts(), warm + 1);
    QVERIFY(tool_->simulationPhase() != QString("Sewing"));
    QTRY_VERIFY_WITH_TIMEOUT(tool_->simulatedSteps() >= 3, 60000);
    tool_->setSimulating(false);
    QCOMPARE(tool_->sewingRuns(), runs);
    const std::vector<float> resewn = tool_->shownStretch(0);
    QVERIFY2(*std::max_element(resewn.begin(), resewn.end()) < 1.105f, "the carried drape is torn");

    // Pins chosen on the drape hold it where it is, without stretching it.
    const std::vector<float> onScreen = tool_->shownPositions(0);
    // The shirt's shoulders, as a user pins a garment to hang it.
    float top = -INFINITY;
    for (size_t v = 0; v < finer.vertexCount(); ++v) top = std::max(top, onScreen[3 * v + 1]);
    std::vector<uint32_t> chosen;
    for (uint32_t v = 0; v < finer.vertexCount(); ++v)
      if (onScreen[3 * v + 1] > top - 0.06f) chosen.push_back(v);
    QVERIFY(chosen.size() > 10);
    tool_->setSelectedVertices(chosen);
    tool_->pinSelected();
    QVERIFY(maxDifference(tool_->shownPositions(0), onScreen) < 1e-4f);  // the edit keeps what is shown
    tool_->setSimulating(true);
    QTRY_VERIFY_WITH_TIMEOUT(tool_->simulatedSteps() >= 5, 60000);
    tool_->setSimulating(false);
    const std::vector<float> pinned = tool_->shownPositions(0);
    float moved = 0.0f;
    for (uint32_t v : tool_->scene().garments[0].pins.vertices)
      moved = std::max(moved, glm::distance(glm::vec3(pinned[3 * v], pinned[3 * v + 1], pinned[3 * v + 2]),
                                            glm::vec3(onScreen[3 * v], onScreen[3 * v + 1], onScreen[3 * v + 2])));
    QVERIFY2(moved < 0.01f, qPrintable(QString("a pin moved %1 m from where it was chosen").arg(moved)));
    const std::vector<float> stretch = tool_->shownStretch(0);
    QVERIFY2(
        *std::max_element(stretch.begin(), stretch.end()) < 1.105f,
        qPrintable(
            QString("the pins stretch the drape %1 times").arg(*std::max_element(stretch.begin(), stretch.end()))));

    // Undo, step by step: each state comes back with the drape it had.
    undo()->undo();  // the pins
    QVERIFY(maxDifference(tool_->shownPositions(0), onScreen) < 1e-4f);
    undo()->undo();  // the particle distance
    QCOMPARE(tool_->garmentMesh(0)->vertexCount(), before.vertexCount());
    QVERIFY(maxDifference(tool_->shownPositions(0), drape) < 1e-4f);
    undo()->undo();  // the cleared pins
    QCOMPARE(undo()->index(), undoIndex);
  }

  // Trousers added after the T-shirt: the T-shirt on layer 1 is worn over
  // them (the trousers as baked alone), on layer 0 under them (the T-shirt
  // as baked alone): the layer decides which garment gives way.
  void layersDecideWhichGarmentGivesWayInABake() {
    const int undoIndex = undo()->index();
    tool_->setCurrentGarment(0);
    tool_->clearPins();  // pinned where the earlier tests put them, its hem rides above the trousers
    QVERIFY(tool_->scene().garments[0].pins.vertices.empty());
    tool_->addGarment("trousers");
    QCOMPARE(tool_->garmentCount(), 2);
    tool_->setParticleDistance(1, 0.04f);  // coarse: a quick sewing
    tool_->setCurrentGarment(0);
    panel()->layerField()->setValue(1);
    QCOMPARE(tool_->scene().garments[0].layer, 1);
    QVERIFY(panel()->garmentList()->item(0)->text().contains("layer 1"));
    doc()->setClip(0);
    const float start = doc()->clipStart();
    QVERIFY2(tool_->bake(start, start + 0.1f), qPrintable(tool_->lastError()));
    doc()->setTime(start + 0.1f);
    const std::vector<float> shirtOver = tool_->shownPositions(0), trousersUnder = tool_->shownPositions(1);
    tool_->setLayer(0, 0);  // the list order: the trousers over the T-shirt
    QVERIFY(!tool_->hasBake());
    const int runs = tool_->sewingRuns();
    QVERIFY2(tool_->bake(start, start + 0.1f), qPrintable(tool_->lastError()));
    QCOMPARE(tool_->sewingRuns(), runs);  // the layer is not part of the sewn state
    doc()->setTime(start + 0.1f);
    const std::vector<float> shirtUnder = tool_->shownPositions(0), trousersOver = tool_->shownPositions(1);
    QVERIFY(allFinite(shirtOver) && allFinite(trousersOver));
    QVERIFY2(maxDifference(shirtOver, shirtUnder) > 2e-3f, "the T-shirt over the trousers did not give way");
    QVERIFY2(maxDifference(trousersOver, trousersUnder) > 2e-3f, "the trousers over the T-shirt did not give way");
    undo()->setIndex(undoIndex);
    QCOMPARE(tool_->garmentCount(), 1);
    QCOMPARE(tool_->scene().garments[0].layer, 0);
    doc()->setClip(-1);
  }

  void collidersAreEditedAndUndone() {
    QCOMPARE(tool_->colliderCount(), 0);
    const int commands = undo()->index();
    panel()->colliderShapeCombo()->setCurrentIndex(0);  // sphere
    QTest::mouseClick(panel()->addColliderButton(), Qt::LeftButton);
    QCOMPARE(tool_->colliderCount(), 1);
    QCOMPARE(undo()->index(), commands + 1);
    QCOMPARE(tool_->currentCollider(), 0);
    QCOMPARE(panel()->colliderList()->count(), 1);
    QCOMPARE(tool_->colliderActors().count(), size_t(1));
    QVERIFY(doc()->sceneSections().colliders.is_array());
    QCOMPARE(doc()->sceneSections().colliders[0]["type"].get<std::string>(), std::string("sphere"));
    QVERIFY(window_->isWindowModified());
    undo()->undo();
    QCOMPARE(tool_->colliderCount(), 0);
    QCOMPARE(tool_->colliderActors().count(), size_t(0));
    QVERIFY(doc()->sceneSections().colliders.is_null());
    undo()->redo();
    QCOMPARE(tool_->colliderCount(), 1);

    // Put the sphere on the shirt's front, below the pins: the fields as typed, one step each.
    // From the placed panels: the drape the earlier tests left is reset.
    tool_->resetDrapes();
    const GarmentMesh& mesh = *tool_->garmentMesh(0);
    QVERIFY(maxDifference(tool_->shownPositions(0), mesh.positions) < 1e-6f);
    size_t front = 0;
    float lowest = INFINITY;
    glm::vec3 centre(0.0f);
    for (size_t v = 0; v < mesh.vertexCount(); ++v) centre += mesh.position(v);
    centre /= float(mesh.vertexCount());
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
      const glm::vec3 p = mesh.position(v);
      if (mesh.panelIds[v] == 0 && std::abs(p.x - centre.x) < 0.05f && std::abs(p.y - centre.y) < lowest)
        lowest = std::abs(p.y - centre.y), front = v;
    }
    const glm::vec3 target = mesh.position(front);
    for (int axis = 0; axis < 3; ++axis) panel()->colliderField(0, axis)->setValue(target[axis]);
    panel()->colliderRadiusField()->setValue(0.08);
    panel()->colliderFrictionField()->setValue(0.5);
    const cloth::PrimitiveCollider sphere = tool_->scene().cloth.colliders[0];
    QVERIFY(glm::length(sphere.a - target) < 1e-3f);
    QCOMPARE(sphere.radius, 0.08f);
    QCOMPARE(sphere.friction, 0.5f);
    QCOMPARE(doc()->sceneSections().colliders[0]["radius"].get<float>(), 0.08f);
    // The actor follows: a sphere of that radius there.
    double bounds[6];
    tool_->colliderActors().actor(0)->GetBounds(bounds);
    QVERIFY(std::abs((bounds[1] - bounds[0]) - 0.16) < 0.01 &&
            std::abs(0.5 * (bounds[2] + bounds[3]) - target.y) < 0.01);
    // Undo goes back one field at a time: friction, then radius.
    undo()->undo();
    QVERIFY(tool_->scene().cloth.colliders[0].friction < 0.0f);
    QCOMPARE(tool_->scene().cloth.colliders[0].radius, 0.08f);
    undo()->undo();
    QVERIFY(tool_->scene().cloth.colliders[0].radius != 0.08f);
    undo()->redo();
    undo()->redo();
    QCOMPARE(tool_->scene().cloth.colliders[0].friction, 0.5f);
    // A bad value is refused and nothing changes.
    const int before = undo()->index();
    cloth::PrimitiveCollider bad = sphere;
    bad.radius = 0.0f;
    QVERIFY(!tool_->setCollider(0, bad));
    QCOMPARE(undo()->index(), before);
    QVERIFY(!tool_->lastError().isEmpty());

    // The live simulation collides with it: the shirt is pushed out of the sphere.
    auto deepest = [&](const std::vector<float>& p) {
      float inside = 0.0f;
      for (size_t v = 0; v < p.size() / 3; ++v)
        inside =
            std::max(inside, sphere.radius - glm::length(glm::vec3(p[3 * v], p[3 * v + 1], p[3 * v + 2]) - sphere.a));
      return inside;
    };
    QVERIFY(deepest(tool_->shownPositions(0)) > 0.05f);
    // Polled while it runs: how many steps one check takes depends on the machine's load.
    tool_->setSimulating(true);
    QTRY_VERIFY2_WITH_TIMEOUT(tool_->simulatedSteps() >= 2 && deepest(tool_->shownPositions(0)) < 0.01f,
                              qPrintable(QString("%1 m inside the collider").arg(deepest(tool_->shownPositions(0)))),
                              60000);
    tool_->setSimulating(false);

    // A capsule and a plane; the capsule's end B edited, then removed and the removal undone.
    panel()->colliderShapeCombo()->setCurrentIndex(1);
    QTest::mouseClick(panel()->addColliderButton(), Qt::LeftButton);
    QCOMPARE(tool_->currentCollider(), 1);
    QCOMPARE(tool_->scene().cloth.colliders[1].shape, cloth::PrimitiveCollider::Shape::Capsule);
    panel()->colliderField(1, 1)->setValue(tool_->scene().cloth.colliders[1].b.y + 0.2);
    const cloth::PrimitiveCollider capsule = tool_->scene().cloth.colliders[1];
    QVERIFY(capsule.b.y > capsule.a.y + 0.15f);
    panel()->colliderShapeCombo()->setCurrentIndex(2);
    QTest::mouseClick(panel()->addColliderButton(), Qt::LeftButton);
    QCOMPARE(tool_->scene().cloth.colliders[2].shape, cloth::PrimitiveCollider::Shape::Plane);
    QCOMPARE(tool_->colliderActors().count(), size_t(3));
    tool_->setCurrentCollider(1);
    QTest::mouseClick(panel()->removeColliderButton(), Qt::LeftButton);
    QCOMPARE(tool_->colliderCount(), 2);
    QCOMPARE(tool_->scene().cloth.colliders[1].shape, cloth::PrimitiveCollider::Shape::Plane);
    undo()->undo();
    QCOMPARE(tool_->colliderCount(), 3);
    QVERIFY(tool_->scene().cloth.colliders[1].b == capsule.b);
    renderNow();
    keepShot("garment_colliders");
  }

  void savedDocumentReopensIntact() {
    const GarmentScene saved = tool_->scene();
    QVERIFY(!saved.garments.empty() && !saved.garments[0].pins.vertices.empty());
    const size_t vertices = tool_->garmentMesh(0)->vertexCount();
    QTemporaryDir dir;
    const QString path = dir.filePath("garments.mqscene");
    QString error;
    QVERIFY2(window_->saveDocument(path, &error), qPrintable(error));
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    QCOMPARE(tool_->garmentCount(), 0);
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QCOMPARE(tool_->garmentCount(), 1);
    nlohmann::json ga, ca, la, gb, cb, lb;
    garmentSceneToSections(tool_->scene(), ga, ca, la);
    garmentSceneToSections(saved, gb, cb, lb);
    // Equal up to float rounding (the reader normalises placement directions).
    if (!jsonNear(ga, gb) || !jsonNear(ca, cb) || !jsonNear(la, lb)) {
      QFAIL(qPrintable(QString::fromStdString("reopened differs:\n" + nlohmann::json::diff(gb, ga).dump() + "\n" +
                                              nlohmann::json::diff(cb, ca).dump() + "\n" +
                                              nlohmann::json::diff(lb, la).dump())));
    }
    QCOMPARE(tool_->scene().garments[0].pins.vertices, saved.garments[0].pins.vertices);
    QCOMPARE(tool_->garmentMesh(0)->vertexCount(), vertices);
    QCOMPARE(panel()->garmentList()->count(), 1);
    QCOMPARE(tool_->colliderCount(), 3);
    QCOMPARE(panel()->colliderList()->count(), 3);
    QCOMPARE(tool_->colliderActors().count(), size_t(3));
    QCOMPARE(tool_->scene().cloth.colliders[0].friction, 0.5f);
    // Reopening pushes no edit and leaves the document unmodified.
    QVERIFY(doc()->undoStack()->isClean() && doc()->undoStack()->count() == 0);
    QVERIFY(!window_->isWindowModified());
  }

  // The bake is saved beside the document and reopens without simulating
  // again, only while it matches the scene; a damaged one is reported.
  void bakeIsSavedBesideTheDocument() {
    doc()->setClip(0);
    const float start = doc()->clipStart();
    QVERIFY2(tool_->bake(start, start + 0.2f), qPrintable(tool_->lastError()));
    const int frames = tool_->bakedFrameCount();
    doc()->setTime(start + 0.1f);
    const std::vector<float> shown = tool_->shownPositions(0);
    QTemporaryDir dir;
    const QString path = dir.filePath("baked.mqscene");
    const QString cache = dir.filePath("baked.mqbake");
    QString error;
    QVERIFY2(window_->saveDocument(path, &error), qPrintable(error));
    QVERIFY(QFile::exists(cache));

    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    QVERIFY(!tool_->hasBake());
    const int runs = tool_->sewingRuns(), reused = tool_->reusedSewings();
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QVERIFY2(tool_->hasBake(), qPrintable(tool_->lastError() + tool_->bakeOutOfDate()));
    QCOMPARE(tool_->bakedFrameCount(), frames);
    QCOMPARE(tool_->sewingRuns(), runs);  // nothing simulated
    QCOMPARE(tool_->reusedSewings(), reused);
    doc()->setClip(0);
    doc()->setTime(start + 0.1f);
    QCOMPARE(tool_->shownPositions(0), shown);

    // The scene edited outside the editor: the cache is of another state.
    QFile scene(path);
    QVERIFY(scene.open(QIODevice::ReadOnly));
    nlohmann::json json = nlohmann::json::parse(scene.readAll().toStdString());
    scene.close();
    json["garments"][0]["fabric"] = "denim";
    QVERIFY(scene.open(QIODevice::WriteOnly | QIODevice::Truncate));
    scene.write(QByteArray::fromStdString(json.dump(2)));
    scene.close();
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QVERIFY(!tool_->hasBake());
    QVERIFY(tool_->bakeOutOfDate().contains("another state"));

    // A damaged cache: the document opens, the dock names the problem.
    QFile damaged(cache);
    QVERIFY(damaged.open(QIODevice::ReadWrite));
    QVERIFY(damaged.resize(damaged.size() / 2));
    damaged.close();
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QCOMPARE(tool_->garmentCount(), 1);
    QVERIFY(!tool_->hasBake());
    QVERIFY2(tool_->lastError().contains("baked.mqbake") && tool_->lastError().contains("truncated"),
             qPrintable(tool_->lastError()));

    // Saved without a bake: the old cache goes.
    QVERIFY2(window_->saveDocument(path, &error), qPrintable(error));
    QVERIFY(!QFile::exists(cache));
    doc()->setClip(-1);
  }

  // The case: a scene document that is a sheet and colliders, no character.
  void sheetAndCollidersWithoutCharacter() {
    QTemporaryDir dir;
    const QString path = dir.filePath("sheet.mqscene");
    const nlohmann::json scene = {{"format", "mannequin-scene"},
                                  {"version", 1},
                                  {"character", nullptr},
                                  {"cloth",
                                   {{"garment",
                                     {{"type", "sheet"},
                                      {"columns", 16},
                                      {"rows", 16},
                                      {"width", 0.8},
                                      {"height", 0.8},
                                      {"center", {0.0, 0.6, 0.0}}}},
                                    {"fps", 24}}},
                                  {"colliders", {{{"type", "sphere"}, {"center", {0.0, 0.3, 0.0}}, {"radius", 0.2}}}}};
    {
      QFile file(path);
      QVERIFY(file.open(QIODevice::WriteOnly));
      file.write(QByteArray::fromStdString(scene.dump()));
    }
    QString error;
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QVERIFY(doc()->character().meshes.empty());
    QCOMPARE(tool_->garmentCount(), 0);
    QVERIFY(tool_->hasSheet());
    QCOMPARE(tool_->shownSheetPositions().size(), size_t(3 * 16 * 16));
    QCOMPARE(tool_->colliderCount(), 1);
    QCOMPARE(tool_->colliderActors().count(), size_t(1));
    QVERIFY(panel()->simulateButton()->isEnabled());
    const std::vector<float> placed = tool_->shownSheetPositions();

    // Simulated: it falls onto the sphere and stays outside it.
    tool_->setSimulating(true);
    QTRY_VERIFY_WITH_TIMEOUT(tool_->simulatedSteps() >= 12, 60000);
    tool_->setSimulating(false);
    QVERIFY2(tool_->lastError().isEmpty(), qPrintable(tool_->lastError()));
    const std::vector<float>& fallen = tool_->shownSheetPositions();
    QVERIFY(allFinite(fallen));
    QVERIFY(maxDifference(fallen, placed) > 0.05f);
    for (size_t v = 0; v < fallen.size() / 3; ++v)
      QVERIFY(glm::length(glm::vec3(fallen[3 * v], fallen[3 * v + 1], fallen[3 * v + 2]) -
                          glm::vec3(0.0f, 0.3f, 0.0f)) > 0.19f);

    // A floor, saved and reopened with the sheet.
    tool_->addCollider(cloth::PrimitiveCollider::Shape::Plane);
    QCOMPARE(tool_->colliderCount(), 2);
    QVERIFY(tool_->scene().cloth.colliders[1].a.y < 0.6f);  // below the sheet
    QVERIFY2(window_->saveDocument(path, &error), qPrintable(error));
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QCOMPARE(tool_->colliderCount(), 2);
    QVERIFY(tool_->hasSheet());
    QCOMPARE(tool_->scene().cloth.colliders[1].shape, cloth::PrimitiveCollider::Shape::Plane);
    QVERIFY(!doc()->sceneSections().garments.is_array());
    renderNow();
    keepShot("garment_sheet_colliders");
  }

  // A bake estimated at minutes asks first. Cancel leaves everything as it
  // was; "Do not ask again" is remembered; a short bake does not ask.
  void longBakeAsksFirst() {
    QTemporaryDir dir;
    const QString path = dir.filePath("big_sheet.mqscene");
    const nlohmann::json scene = {{"format", "mannequin-scene"},
                                  {"version", 1},
                                  {"character", nullptr},
                                  {"cloth",
                                   {{"garment",
                                     {{"type", "sheet"},
                                      {"columns", 64},
                                      {"rows", 64},
                                      {"width", 0.8},
                                      {"height", 0.8},
                                      {"center", {0.0, 0.6, 0.0}}}},
                                    {"fps", 24},
                                    {"bake_frames", 100000}}}};
    {
      QFile file(path);
      QVERIFY(file.open(QIODevice::WriteOnly));
      file.write(QByteArray::fromStdString(scene.dump()));
    }
    QString error;
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    QVERIFY(tool_->hasSheet());
    setAskBeforeLongJobs(true);

    // The question, answered as a user would, whenever it shows.
    QString asked;
    bool start = false, dontAsk = false;
    QTimer answer;
    connect(&answer, &QTimer::timeout, this, [&] {
      auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
      if (!box || box->objectName() != "longJobQuestion") return;
      if (asked.isEmpty() && !qEnvironmentVariable("MANNEQUIN_TEST_SHOTS").isEmpty())
        box->grab().save(qEnvironmentVariable("MANNEQUIN_TEST_SHOTS") + "/long_bake_question.png");
      asked = box->text();
      box->checkBox()->setChecked(dontAsk);
      for (QAbstractButton* button : box->buttons())
        if ((box->buttonRole(button) == QMessageBox::AcceptRole) == start) button->click();
    });
    answer.start(20);
    QTimer cancelSoon;
    connect(&cancelSoon, &QTimer::timeout, tool_, [&] {
      if (tool_->baking()) tool_->cancelBake();
    });

    panel()->bakeButton()->click();
    QVERIFY2(asked.contains("100000 frames"), qPrintable(asked));
    QVERIFY(tool_->lastBakeEstimate() > kLongJobSeconds);
    QVERIFY(!tool_->baking() && !tool_->hasBake());
    QCOMPARE(tool_->lastError(), QString("Bake not started"));

    asked.clear();
    start = dontAsk = true;
    cancelSoon.start(10);
    panel()->bakeButton()->click();
    QVERIFY(!asked.isEmpty());
    QCOMPARE(tool_->lastError(), QString("Bake cancelled"));
    QVERIFY(!askBeforeLongJobs());

    asked.clear();
    panel()->bakeButton()->click();  // not asked again
    QVERIFY(asked.isEmpty());
    QCOMPARE(tool_->lastError(), QString("Bake cancelled"));
    cancelSoon.stop();

    setAskBeforeLongJobs(true);
    tool_->setBakeFrames(3);
    panel()->bakeButton()->click();
    QVERIFY(asked.isEmpty());
    QVERIFY2(tool_->hasBake(), qPrintable(tool_->lastError()));
    QCOMPARE(tool_->bakedFrameCount(), 3);
  }

  // Last: opening the dock resizes the viewport, which the live-simulation
  // tests above are timed by.
  void thePatternDockOpensUnderTheTimeline() {
    PatternView* view = tool_->patternView();
    tool_->showPatternDock();
    QVERIFY(view->isVisible());
    QTRY_VERIFY(view->height() > 150);
    QVERIFY(view->mapTo(window_, QPoint(0, 0)).y() > window_->viewport()->mapTo(window_, QPoint(0, 0)).y());
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(VtkViewportWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("MannequinTests");
  QApplication::setApplicationName("gui_garments");
  // Never hang: give up after five minutes (the bakes run real simulations).
  mq::ui::exitAfter(300, "gui_garments");
  GarmentToolTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "garment_tool_test.moc"
