// GUI test of the hair tool (needs X: run under xvfb-run; `mannequin_gui_tests
// hair`). Drives the real main window and hair dock: a scene with a groom is
// opened, a flow primitive is added with the panel's button, its strength and
// position are changed in the panel's fields, and each edit must regrow the
// guides; undo and redo must give back exactly the strands before and after;
// the document saved and reopened must hold the same hairstyle and grow the
// same strands. The source is also dragged by its handle in the viewport, and
// a vortex's axis is turned by its tip handle.
#include <cstdlib>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QImage>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QMouseEvent>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <vtkRenderer.h>

#include "core/hair/hair_groom.h"
#include "core/hair/hairstyle_json.h"
#include "core/io/character_import.h"
#include "render/brush_cursor.h"
#include "render/scene_view.h"
#include "test_window.h"
#include "ui/document/editor_document.h"
#include "ui/hair/hair_panel.h"
#include "ui/hair/hair_tool.h"
#include "ui/main_window.h"
#include "ui/viewport/vtk_viewport_widget.h"

using namespace mq;
using namespace mq::ui;

namespace {

// The guides' points: what a primitive edit regrows.
std::vector<float> guidePoints(const HairTool& tool) {
  const HairGroom* groom = tool.groom();
  if (!groom) return {};
  const Strands& s = groom->strands();
  return std::vector<float>(s.points.begin(), s.points.begin() + 3 * groom->guideCount() * size_t(s.pointsPerStrand));
}

float maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return INFINITY;
  float d = 0.0f;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

std::string styleText(const HairTool& tool) { return toJson(tool.style()).dump(); }

float guideLengths(const HairTool& tool) {
  const Strands& s = tool.groom()->strands();
  float sum = 0.0f;
  for (size_t g = 0; g < tool.groom()->guideCount(); ++g) {
    float length = 0.0f;
    for (int k = 1; k < s.pointsPerStrand; ++k) {
      const float* p = s.strand(g) + 3 * k;
      length += glm::length(glm::vec3(p[0], p[1], p[2]) - glm::vec3(p[-3], p[-2], p[-1]));
    }
    sum += length;
  }
  return sum;
}

// Every strand's root: what a scalp change moves.
std::vector<float> rootPoints(const HairTool& tool) {
  std::vector<float> roots;
  if (!tool.groom()) return roots;
  const Strands& s = tool.groom()->strands();
  for (size_t i = 0; i < s.strandCount(); ++i)
    for (int d = 0; d < 3; ++d) roots.push_back(s.points[3 * i * size_t(s.pointsPerStrand) + d]);
  return roots;
}

// Diagonal of the roots' bounding box (m).
float rootSpread(const std::vector<float>& roots) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (size_t k = 0; k + 2 < roots.size(); k += 3) {
    const glm::vec3 p(roots[k], roots[k + 1], roots[k + 2]);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return roots.empty() ? 0.0f : glm::length(hi - lo);
}

}  // namespace

class HairToolTest : public QObject {
  Q_OBJECT

 private:
  MainWindow* window_ = nullptr;
  HairTool* tool_ = nullptr;
  EditorDocument* doc() { return window_->document(); }
  HairPanel* panel() { return tool_->panel(); }

  QPoint toWidget(const glm::vec3& world) { return mq::ui::toWidget(window_, world); }

  void renderNow() { mq::ui::renderNow(window_); }
  // Edits regrow the hair on a worker thread: the groom read next must be
  // the edited one.
  void waitForHair() { tool_->finishBackgroundWork(); }

  // State after each step, compared by undo/redo and the reopen.
  std::vector<float> opened_, added_, strengthened_, moved_;
  std::string openedStyle_, movedStyle_;
  std::vector<float> taggedRoots_, wideConeRoots_, narrowConeRoots_;
  QTemporaryDir dir_;

 private slots:
  void initTestCase() {
    window_ = makeTestWindow();
    QVERIFY(QTest::qWaitForWindowExposed(window_));
    tool_ = window_->findChild<HairTool*>();
    QVERIFY(tool_ != nullptr);
    QVERIFY(dir_.isValid());
    tool_->setDisplayStrandLimit(HairTool::kDefaultDisplayStrandLimit);  // a setting kept between runs
  }

  void cleanupTestCase() {
    delete window_;
    window_ = nullptr;
  }

  void openingAHairSceneGrooms() {
    QString error;
    QVERIFY2(window_->openFileNow(MANNEQUIN_SOURCE_DIR "/resources/scenes/hair_bob.json", &error), qPrintable(error));
    waitForHair();
    QVERIFY2(tool_->hasHair(), qPrintable(tool_->lastError()));
    QCOMPARE(QString::fromStdString(tool_->style().name), QString("bob"));
    QVERIFY(tool_->strandCount() > 1000);
    QVERIFY(tool_->groom()->countPointsInside() == 0);
    opened_ = guidePoints(*tool_);
    openedStyle_ = styleText(*tool_);
    QVERIFY(!opened_.empty());
    QCOMPARE(panel()->primitiveList()->count(),
             int(tool_->style().primitives.streams.size() + tool_->style().primitives.sources.size() +
                 tool_->style().primitives.vortices.size()));
  }

  void addingASourceRegrowsTheGuides() {
    const size_t sources = tool_->style().primitives.sources.size();
    const int rows = panel()->primitiveList()->count();
    const int commands = doc()->undoStack()->index();
    QSignalSpy regrown(tool_, &HairTool::hairRegrown);
    QTest::mouseClick(panel()->addSourceButton(), Qt::LeftButton);
    waitForHair();
    QCOMPARE(tool_->style().primitives.sources.size(), sources + 1);
    QCOMPARE(panel()->primitiveList()->count(), rows + 1);
    QCOMPARE(doc()->undoStack()->index(), commands + 1);
    QCOMPARE(tool_->selectedPrimitive().kind, PrimitiveRef::Source);
    QCOMPARE(tool_->selectedPrimitive().index, int(sources));
    QVERIFY(regrown.count() >= 1);
    added_ = guidePoints(*tool_);
    QVERIFY2(maxDifference(opened_, added_) > 1e-3f, "a new source in front of the head did not move the guides");
    QCOMPARE(tool_->groom()->countPointsInside(), size_t(0));
    QVERIFY(window_->isWindowModified());
  }

  void strengthInThePanelRegrowsTheGuides() {
    const int index = tool_->selectedPrimitive().index;
    QDoubleSpinBox* strength = panel()->strengthBox();
    QVERIFY(strength->isEnabled());
    QVERIFY(std::abs(strength->value() - tool_->style().primitives.sources[index].strength) < 1e-3);
    const int commands = doc()->undoStack()->index();
    strength->setValue(2.5);  // as if typed + Enter
    waitForHair();
    QCOMPARE(tool_->style().primitives.sources[index].strength, 2.5f);
    QCOMPARE(doc()->undoStack()->index(), commands + 1);
    strengthened_ = guidePoints(*tool_);
    QVERIFY2(maxDifference(added_, strengthened_) > 1e-3f, "a stronger source did not move the guides");
  }

  void positionInThePanelMovesThePrimitive() {
    const int index = tool_->selectedPrimitive().index;
    const int commands = doc()->undoStack()->index();
    panel()->positionBox(0)->setValue(0.08);  // to the character's left of the face
    waitForHair();
    QCOMPARE(tool_->style().primitives.sources[index].position.x, 0.08f);
    QCOMPARE(doc()->undoStack()->index(), commands + 1);
    moved_ = guidePoints(*tool_);
    movedStyle_ = styleText(*tool_);
    QVERIFY2(maxDifference(strengthened_, moved_) > 1e-3f, "moving the source did not move the guides");
    QCOMPARE(tool_->groom()->countPointsInside(), size_t(0));
  }

  void undoAndRedoGiveTheStrandsBack() {
    QUndoStack* undo = doc()->undoStack();
    undo->undo();  // position
    waitForHair();
    QCOMPARE(guidePoints(*tool_), strengthened_);
    undo->undo();  // strength
    waitForHair();
    QCOMPARE(guidePoints(*tool_), added_);
    QVERIFY(std::abs(panel()->strengthBox()->value() - 0.3) < 1e-3);  // the panel follows
    undo->undo();                                                     // the source
    waitForHair();
    QCOMPARE(guidePoints(*tool_), opened_);
    QCOMPARE(styleText(*tool_), openedStyle_);
    undo->redo();
    undo->redo();
    undo->redo();
    waitForHair();
    QCOMPARE(guidePoints(*tool_), moved_);
    QCOMPARE(styleText(*tool_), movedStyle_);
  }

  void opacityShadowMapsCheckboxSwitchesTheShadowing() {
    QVERIFY(!tool_->opacityShadowMaps());
    // A frame with a stale shadow asks the worker for the new one.
    renderNow();
    waitForHair();
    const QImage counted = window_->viewport()->grabFramebuffer();
    panel()->shadowMapsBox()->setChecked(true);
    QVERIFY(tool_->opacityShadowMaps());
    renderNow();
    waitForHair();
    const QImage mapped = window_->viewport()->grabFramebuffer();
    int differing = 0;
    for (int y = 0; y < counted.height(); ++y)
      for (int x = 0; x < counted.width(); ++x) differing += counted.pixel(x, y) != mapped.pixel(x, y);
    QVERIFY2(differing > 100, "the viewport looks the same with opacity shadow maps");
    panel()->shadowMapsBox()->setChecked(false);
    QVERIFY(!tool_->opacityShadowMaps());
  }

  // The Shading group: the physical model and a pigment preset change the
  // viewport, each one undo step, without regrowing the strands.
  void shadingModelAndPigmentAreUndoableAndShown() {
    renderNow();
    waitForHair();
    const QImage kajiyaKay = window_->viewport()->grabFramebuffer();
    const std::vector<float> guides = guidePoints(*tool_);
    const int commands = doc()->undoStack()->index();
    panel()->shadingModelCombo()->setCurrentIndex(1);
    emit panel()->shadingModelCombo()->activated(1);  // as a user's pick
    QCOMPARE(tool_->style().shading.model, HairShadingModel::Physical);
    QCOMPARE(doc()->undoStack()->index(), commands + 1);
    QVERIFY(!panel()->pigmentButtons().empty());
    panel()->pigmentButtons().front()->click();
    QCOMPARE(doc()->undoStack()->index(), commands + 2);
    const float melanin = tool_->style().shading.melanin;
    renderNow();
    waitForHair();
    const QImage physical = window_->viewport()->grabFramebuffer();
    int differing = 0;
    for (int y = 0; y < physical.height(); ++y)
      for (int x = 0; x < physical.width(); ++x) differing += kajiyaKay.pixel(x, y) != physical.pixel(x, y);
    QVERIFY2(differing > 100, "the viewport looks the same with the physical hair shader");
    QCOMPARE(guidePoints(*tool_), guides);
    doc()->undoStack()->undo();
    QVERIFY(tool_->style().shading.melanin != melanin || panel()->pigmentButtons().size() == 1);
    doc()->undoStack()->undo();
    QCOMPARE(tool_->style().shading.model, HairShadingModel::KajiyaKay);
    QCOMPARE(panel()->shadingModelCombo()->currentIndex(), 0);
  }

  // Dragging the source's handle in the viewport moves it: live guides
  // during the drag, one undo step for the whole drag, children regrown at
  // the release.
  void draggingTheHandleMovesThePrimitive() {
    tool_->dock()->show();
    tool_->dock()->raise();
    QApplication::processEvents();
    renderNow();
    const PrimitiveRef source{PrimitiveRef::Source, int(tool_->style().primitives.sources.size()) - 1};
    QCOMPARE(tool_->style().primitives.sources[source.index].position.x, 0.08f);  // the one added and moved
    const glm::vec3 before = tool_->style().primitives.sources[source.index].position;
    const QPoint at = toWidget(glm::vec3(tool_->worldFromHead() * glm::vec4(before, 1.0f)));
    const int commands = doc()->undoStack()->index();
    QWidget* viewport = window_->viewport();
    sendMouse(viewport, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
    for (int step = 1; step <= 4; ++step)
      sendMouse(viewport, QEvent::MouseMove, at + QPoint(0, -8 * step), Qt::NoButton, Qt::LeftButton);
    sendMouse(viewport, QEvent::MouseButtonRelease, at + QPoint(0, -32), Qt::LeftButton, Qt::NoButton);
    waitForHair();
    QCOMPARE(doc()->undoStack()->index(), commands + 1);  // one step for the drag
    const glm::vec3 after = tool_->style().primitives.sources[source.index].position;
    QVERIFY2(after.y > before.y + 0.01f, "dragging the handle up did not raise the source");
    const std::vector<float> dragged = guidePoints(*tool_);
    QVERIFY2(maxDifference(moved_, dragged) > 1e-3f, "the guides did not follow the dragged source");
    QCOMPARE(tool_->groom()->countPointsInside(), size_t(0));
    doc()->undoStack()->undo();
    waitForHair();
    QCOMPARE(guidePoints(*tool_), moved_);
    doc()->undoStack()->redo();
    waitForHair();
    QCOMPARE(guidePoints(*tool_), dragged);
    moved_ = dragged;
    movedStyle_ = styleText(*tool_);
  }

  void savedDocumentReopensWithTheHairstyle() {
    const QString path = dir_.filePath("styled.mqscene");
    QString error;
    QVERIFY2(window_->saveDocument(path, &error), qPrintable(error));
    QVERIFY(!window_->isWindowModified());
    // Something else in between, so the reopen really reloads.
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    QVERIFY(!tool_->hasHair());
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    waitForHair();
    QVERIFY2(tool_->hasHair(), qPrintable(tool_->lastError()));
    QCOMPARE(styleText(*tool_), movedStyle_);
    QCOMPARE(guidePoints(*tool_), moved_);  // deterministic groom from the saved style
    QCOMPARE(doc()->undoStack()->count(), 0);
  }

  // The Scalp group: the mannequin starts on its tagged scalp; a head-bone
  // cone replaces it (one undo step each) and a narrower cone grows the hair
  // on a smaller patch.
  void narrowerBoneConeGrowsOnASmallerPatch() {
    QComboBox* mode = panel()->scalpModeCombo();
    QVERIFY(mode->isEnabled());
    QCOMPARE(mode->currentIndex(), int(HairPanel::ScalpTagged));
    auto* model = qobject_cast<QStandardItemModel*>(mode->model());
    QVERIFY(model && model->item(HairPanel::ScalpTagged)->isEnabled());  // the mannequin has scalp tags
    QVERIFY(!panel()->scalpAngleBox()->isEnabled());                     // no cone yet
    // A low density, so the root count follows the scalp's area (the viewport
    // grows at most 40,000 strands).
    HairStyle sparse = tool_->style();
    sparse.density = 20.0f;
    tool_->editStyle(sparse, "Hair density");
    waitForHair();
    taggedRoots_ = rootPoints(*tool_);
    QVERIFY(taggedRoots_.size() / 3 < 30000);
    const int commands = doc()->undoStack()->index();

    mode->setCurrentIndex(HairPanel::ScalpBoneCone);
    waitForHair();
    QCOMPARE(tool_->scalp().kind, ScalpRegion::Kind::BoneCone);
    QCOMPARE(doc()->undoStack()->index(), commands + 1);
    QCOMPARE(panel()->scalpBoneCombo()->currentText(), QString::fromStdString(tool_->scalp().bone));
    QVERIFY(panel()->scalpBoneCombo()->count() > 10);              // the character's bones
    QCOMPARE(panel()->scalpAxisPresetCombo()->currentIndex(), 1);  // up-back
    QVERIFY(panel()->scalpAngleBox()->isEnabled());
    wideConeRoots_ = rootPoints(*tool_);
    QVERIFY(!wideConeRoots_.empty());
    QVERIFY2(maxDifference(taggedRoots_, wideConeRoots_) > 1e-3f, "the cone did not move the roots");

    const float wideAngle = tool_->scalp().angleDegrees;
    panel()->scalpAngleBox()->setValue(wideAngle / 2);  // as if typed + Enter
    waitForHair();
    QCOMPARE(tool_->scalp().angleDegrees, wideAngle / 2);
    QCOMPARE(doc()->undoStack()->index(), commands + 2);
    narrowConeRoots_ = rootPoints(*tool_);
    qInfo("roots: tagged %zu (spread %.3f m), %.0f deg cone %zu (spread %.3f m), %.0f deg cone %zu (spread %.3f m)",
          taggedRoots_.size() / 3, rootSpread(taggedRoots_), wideAngle, wideConeRoots_.size() / 3,
          rootSpread(wideConeRoots_), wideAngle / 2, narrowConeRoots_.size() / 3, rootSpread(narrowConeRoots_));
    QVERIFY2(narrowConeRoots_.size() < wideConeRoots_.size(), "a narrower cone grew as many roots");
    QVERIFY2(rootSpread(narrowConeRoots_) < 0.9f * rootSpread(wideConeRoots_), "a narrower cone spread as wide");
    QVERIFY(panel()->scalpStatusLabel()->text().contains(QString::number(tool_->strandCount())));
    QCOMPARE(tool_->groom()->countPointsInside(), size_t(0));
  }

  void undoGivesThePreviousScalpBack() {
    QUndoStack* undo = doc()->undoStack();
    undo->undo();  // angle
    waitForHair();
    QCOMPARE(rootPoints(*tool_), wideConeRoots_);
    undo->undo();  // tagged -> cone
    waitForHair();
    QCOMPARE(tool_->scalp().kind, ScalpRegion::Kind::Tagged);
    QCOMPARE(panel()->scalpModeCombo()->currentIndex(), int(HairPanel::ScalpTagged));
    QCOMPARE(rootPoints(*tool_), taggedRoots_);
    undo->redo();
    undo->redo();
    waitForHair();
    QCOMPARE(rootPoints(*tool_), narrowConeRoots_);
    QCOMPARE(panel()->scalpModeCombo()->currentIndex(), int(HairPanel::ScalpBoneCone));
  }

  // A region with no face (a cone pointing down from the head bone, into the
  // neck the head does not drive) is refused: the scalp stays, a message says why.
  void anEmptyRegionKeepsTheScalpAndReports() {
    const ScalpRegion before = tool_->scalp();
    const int commands = doc()->undoStack()->index();
    ScalpRegion empty = before;
    empty.axis = glm::vec3(0.0f, -1.0f, 0.0f);
    empty.angleDegrees = 10.0f;
    QVERIFY(!tool_->editScalp(empty, "Scalp axis"));
    QCOMPARE(doc()->undoStack()->index(), commands);
    QCOMPARE(tool_->scalp().axis, before.axis);
    QCOMPARE(rootPoints(*tool_), narrowConeRoots_);
    QVERIFY2(window_->statusBar()->currentMessage().contains("Scalp unchanged"),
             qPrintable(window_->statusBar()->currentMessage()));
    QVERIFY(panel()->scalpStatusLabel()->text().contains("Scalp unchanged"));
    // The same from the panel: the smallest angle finds no face centre either.
    panel()->scalpAxisBox(1)->setValue(-1.0);
    QCOMPARE(doc()->undoStack()->index(), commands);
    QCOMPARE(rootPoints(*tool_), narrowConeRoots_);
    QVERIFY(std::abs(panel()->scalpAxisBox(1)->value() - before.axis.y) < 1e-3);  // the panel shows the scalp in use
  }

  void savedDocumentReopensWithTheScalp() {
    const ScalpRegion saved = tool_->scalp();
    const QString path = dir_.filePath("scalp.mqscene");
    QString error;
    QVERIFY2(window_->saveDocument(path, &error), qPrintable(error));
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    QVERIFY2(window_->openFileNow(path, &error), qPrintable(error));
    waitForHair();
    QVERIFY2(tool_->hasHair(), qPrintable(tool_->lastError()));
    QCOMPARE(tool_->scalp().kind, ScalpRegion::Kind::BoneCone);
    QCOMPARE(tool_->scalp().bone, saved.bone);
    QCOMPARE(tool_->scalp().angleDegrees, saved.angleDegrees);
    QVERIFY(glm::length(tool_->scalp().axis - saved.axis) < 1e-5f);
    QCOMPARE(panel()->scalpModeCombo()->currentIndex(), int(HairPanel::ScalpBoneCone));
    QCOMPARE(float(panel()->scalpAngleBox()->value()), saved.angleDegrees);
    QCOMPARE(rootPoints(*tool_), narrowConeRoots_);
  }

  // Dragging a vortex's tip handle (the cube at the end of its axis line)
  // turns its axis toward the cursor: a unit axis, the vortex stays put, live
  // guides, one undo step that gives the axis back exactly.
  void draggingTheVortexTipTurnsItsAxis() {
    tool_->dock()->show();
    tool_->dock()->raise();
    QTest::mouseClick(panel()->addVortexButton(), Qt::LeftButton);
    waitForHair();
    QApplication::processEvents();
    renderNow();
    const PrimitiveRef vortex{PrimitiveRef::Vortex, int(tool_->style().primitives.vortices.size()) - 1};
    QVERIFY(tool_->selectedPrimitive() == vortex);
    const Vortex before = tool_->style().primitives.vortices[vortex.index];
    const std::vector<float> guidesBefore = guidePoints(*tool_);
    const glm::mat4 worldFromHead = tool_->worldFromHead();
    auto tipOnScreen = [&] {
      return toWidget(glm::vec3(worldFromHead * glm::vec4(axisTipPosition(tool_->style(), vortex), 1.0f)));
    };
    const QPoint at = tipOnScreen();
    const int commands = doc()->undoStack()->index();
    QWidget* viewport = window_->viewport();
    sendMouse(viewport, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
    for (int step = 1; step <= 4; ++step)
      sendMouse(viewport, QEvent::MouseMove, at + QPoint(10 * step, 0), Qt::NoButton, Qt::LeftButton);
    sendMouse(viewport, QEvent::MouseButtonRelease, at + QPoint(40, 0), Qt::LeftButton, Qt::NoButton);
    waitForHair();
    QCOMPARE(doc()->undoStack()->index(), commands + 1);  // one step for the drag
    const Vortex after = tool_->style().primitives.vortices[vortex.index];
    QCOMPARE(after.position, before.position);  // the tip turns the axis, it does not move the vortex
    QVERIFY2(std::abs(glm::length(after.axis) - 1.0f) < 1e-3f, "the turned axis is not unit length");
    QVERIFY2(glm::length(after.axis - before.axis) > 0.1f, "dragging the tip did not turn the axis");
    const QPoint tipAfter = tipOnScreen();
    QVERIFY2(tipAfter.x() > at.x() + 15 && std::abs(tipAfter.y() - at.y()) < 15,
             qPrintable(QString("the tip went to (%1, %2), not right of (%3, %4)")
                            .arg(tipAfter.x())
                            .arg(tipAfter.y())
                            .arg(at.x())
                            .arg(at.y())));
    const std::vector<float> guidesAfter = guidePoints(*tool_);
    QVERIFY2(maxDifference(guidesBefore, guidesAfter) > 1e-3f, "the guides did not follow the turned axis");
    doc()->undoStack()->undo();
    waitForHair();
    QCOMPARE(tool_->style().primitives.vortices[vortex.index].axis, before.axis);
    QCOMPARE(guidePoints(*tool_), guidesBefore);
  }

  // Each typed value is an undo step of its own, even two in a row on the
  // same field; arrow clicks in a row on one field merge into one step.
  void eachTypedValueIsOneUndoStep() {
    QDoubleSpinBox* density = panel()->densityBox();
    QUndoStack* undo = doc()->undoStack();
    const float before = tool_->style().density;
    const int commands = undo->index();
    typeValue(density, before + 10.0);
    typeValue(density, before + 20.0);
    QCOMPARE(tool_->style().density, before + 20.0f);
    QCOMPARE(undo->index(), commands + 2);
    undo->undo();
    QCOMPARE(tool_->style().density, before + 10.0f);
    QTest::keyClick(density, Qt::Key_Up);
    QTest::keyClick(density, Qt::Key_Up);
    QCOMPARE(tool_->style().density, before + 10.0f + 2.0f * float(density->singleStep()));
    QCOMPARE(undo->index(), commands + 2);  // the two clicks: one step
    undo->undo();
    undo->undo();
    waitForHair();
    QCOMPARE(tool_->style().density, before);
    QCOMPARE(undo->index(), commands);
  }

  // Volume and friction (hair against hair) are the style's dynamics: each
  // typed value one undo step, no regrowth, and the live dynamics use them.
  void volumeAndFrictionAreUndoableAndReachTheDynamics() {
    waitForHair();
    QUndoStack* undo = doc()->undoStack();
    const int commands = undo->index();
    const std::vector<float> guides = guidePoints(*tool_);
    typeValue(panel()->volumeBox(), 0.6);
    typeValue(panel()->hairFrictionBox(), 0.3);
    QCOMPARE(tool_->style().dynamics.volume, 0.6f);
    QCOMPARE(tool_->style().dynamics.friction, 0.3f);
    QCOMPARE(undo->index(), commands + 2);
    waitForHair();
    QCOMPARE(guidePoints(*tool_), guides);
    tool_->setSimulating(true);
    QVERIFY(tool_->interactionRadius() > 0.0f);
    tool_->setSimulating(false);
    undo->undo();
    undo->undo();
    waitForHair();
    QCOMPARE(tool_->style().dynamics, HairDynamicsParams{});
    QCOMPARE(panel()->volumeBox()->value(), 0.0);
    tool_->setSimulating(true);
    QCOMPARE(tool_->interactionRadius(), 0.0f);
    tool_->setSimulating(false);
  }

  // The viewport's strand cap is a setting in the dock, which says how many
  // of the document's strands it shows.
  void theDisplayLimitCapsTheViewportAndSaysSo() {
    const QLocale locale;
    const size_t wanted = tool_->documentStrandCount();
    QVERIFY(wanted > 2000);
    QSpinBox* limit = panel()->displayLimitBox();
    const int commands = doc()->undoStack()->index();
    limit->setValue(2000);
    waitForHair();
    QCOMPARE(tool_->displayStrandLimit(), size_t(2000));
    QVERIFY2(tool_->strandCount() <= 2000 && tool_->strandCount() > 1500,
             qPrintable(QString::number(tool_->strandCount())));
    QCOMPARE(panel()->displayCountLabel()->text(),
             QString("Displaying %1 of %2 strands").arg(locale.toString(2000), locale.toString(qulonglong(wanted))));
    QCOMPARE(doc()->undoStack()->index(), commands);  // an editor setting, not a document edit
    limit->setValue(int(HairTool::kDefaultDisplayStrandLimit));
    waitForHair();
    QCOMPARE(tool_->strandCount(), std::min(wanted, HairTool::kDefaultDisplayStrandLimit));
  }

  void aBakeShowsProgressAndCanBeCancelled() {
    QString error;
    QVERIFY2(window_->openFileNow(MANNEQUIN_SOURCE_DIR "/resources/scenes/hair_bob.json", &error), qPrintable(error));
    waitForHair();
    QVERIFY(doc()->clipIndex() >= 0);  // the walk
    // Cancel as soon as the dialog has moved: the bake stops, keeps nothing.
    bool shown = false;
    QTimer poll;
    poll.setInterval(10);
    connect(&poll, &QTimer::timeout, [&] {
      for (QProgressDialog* dialog : window_->findChildren<QProgressDialog*>())
        if (dialog->isVisible() && dialog->value() > 0) shown = true, dialog->cancel();
    });
    poll.start();
    QVERIFY(!tool_->bake());
    poll.stop();
    QVERIFY2(shown, "no progress was shown during the bake");
    QVERIFY(!tool_->hasBake());
    // Left alone, it bakes the clip.
    QVERIFY2(tool_->bake(), qPrintable(tool_->lastError()));
    QVERIFY(tool_->hasBake());
    // File > Export Animated glTF takes the bake: the guides as a lines mesh
    // whose frames play in one take with the body.
    const QString gltf = dir_.filePath("hair_take.glb");
    const QString summary = window_->exportAnimatedGltf(gltf, &error);
    QVERIFY2(summary.contains("hair"), qPrintable(summary + error));
    const Character take = importCharacter(gltf.toStdString());
    QCOMPARE(take.meshes.size(), doc()->character().meshes.size() + 1);
    QVERIFY(take.meshes.back().triangles.empty());  // lines
    QCOMPARE(take.clips.size(), size_t(1));
  }

  // The scalp brush: a Ctrl+stroke erases the faces under it, a stroke paints
  // faces in, each one undo step; the hair grows where the scalp now is.
  void paintingTheScalpIsOneUndoStepAStroke() {
    tool_->dock()->show();
    tool_->dock()->raise();
    QApplication::processEvents();
    doc()->setClip(-1);  // the rest pose
    renderNow();
    // The top of the head and the front of the face, as shown.
    const std::vector<float>& body = doc()->posed().meshes()[0].positions;
    float headTop = -1e9f;
    for (size_t k = 1; k < body.size(); k += 3) headTop = std::max(headTop, body[k]);
    // The upper front of the head (the hairline), where the view sees the scalp.
    glm::vec3 top(0.0f, -1e9f, 0.0f);
    for (size_t k = 0; k + 2 < body.size(); k += 3)
      if (body[k + 1] > headTop - 0.15f && body[k + 1] + body[k + 2] > top.y + top.z)
        top = {body[k], body[k + 1], body[k + 2]};
    glm::vec3 face(0.0f, 0.0f, -1e9f);
    for (size_t k = 0; k + 2 < body.size(); k += 3)
      if (body[k + 1] > headTop - 0.15f && std::abs(body[k]) < 0.02f && body[k + 2] > face.z)
        face = {body[k], body[k + 1], body[k + 2]};
    panel()->brushRadiusBox()->setValue(3.0);
    QCOMPARE(tool_->brushRadius(), 0.03f);
    // The Painted region turns the brush on (one undo step: the same faces as a list).
    panel()->scalpModeCombo()->setCurrentIndex(HairPanel::ScalpPainted);
    waitForHair();
    QVERIFY(tool_->paintingScalp());
    QVERIFY(panel()->scalpPaintButton()->isVisibleTo(panel()) && panel()->scalpPaintButton()->isChecked());
    QWidget* viewport = window_->viewport();
    auto stroke = [&](const glm::vec3& at, Qt::KeyboardModifiers modifiers) {
      const QPoint p = toWidget(at);
      const qreal ratio = viewport->devicePixelRatioF();
      const std::optional<glm::vec3> hit = window_->sceneView()->pickSurface(
          int(p.x() * ratio), int(viewport->height() * ratio) - 1 - int(p.y() * ratio));
      QVERIFY2(hit && glm::length(*hit - at) < 0.03f, "the stroke's point is not on the character as shown");
      sendMouse(viewport, QEvent::MouseButtonPress, p, Qt::LeftButton, Qt::LeftButton, modifiers);
      for (int step = 1; step <= 3; ++step)
        sendMouse(viewport, QEvent::MouseMove, p + QPoint(2 * step, 0), Qt::NoButton, Qt::LeftButton, modifiers);
      sendMouse(viewport, QEvent::MouseButtonRelease, p + QPoint(6, 0), Qt::LeftButton, Qt::NoButton, modifiers);
      waitForHair();
    };
    const float areaBefore = tool_->scalpArea();
    const int commands = doc()->undoStack()->index();
    QCOMPARE(tool_->scalp().kind, ScalpRegion::Kind::Faces);
    stroke(top, Qt::ControlModifier);
    QCOMPARE(doc()->undoStack()->index(), commands + 1);
    QCOMPARE(tool_->scalp().kind, ScalpRegion::Kind::Faces);
    const float erased = tool_->scalpArea();
    QVERIFY2(erased < areaBefore - 1e-4f, qPrintable(QString("%1 -> %2 m2").arg(areaBefore).arg(erased)));
    stroke(face, Qt::NoModifier);
    QCOMPARE(doc()->undoStack()->index(), commands + 2);
    QVERIFY(tool_->scalpArea() > erased + 1e-4f);
    QCOMPARE(panel()->scalpModeCombo()->currentIndex(), int(HairPanel::ScalpPainted));
    // Some root now grows on the face, within the brush of where it was painted.
    float nearest = 1e9f;
    const std::vector<float> roots = rootPoints(*tool_);
    for (size_t k = 0; k + 2 < roots.size(); k += 3)
      nearest = std::min(nearest, glm::length(glm::vec3(roots[k], roots[k + 1], roots[k + 2]) - face));
    QVERIFY2(nearest < 0.04f, qPrintable(QString("nearest root %1 m from the painted face").arg(nearest)));
    doc()->undoStack()->undo();
    waitForHair();
    QCOMPARE(tool_->scalpArea(), erased);
    doc()->undoStack()->undo();
    waitForHair();
    QCOMPARE(tool_->scalpArea(), areaBefore);
    panel()->scalpPaintButton()->click();
    QVERIFY(!tool_->paintingScalp());
    panel()->scalpModeCombo()->setCurrentIndex(HairPanel::ScalpTagged);  // the brush goes with the region
    waitForHair();
    QVERIFY(!panel()->scalpPaintButton()->isVisibleTo(panel()));
  }

  void groomingWithABrushIsOneUndoStepAStroke() {
    tool_->dock()->show();
    tool_->dock()->raise();
    doc()->setClip(-1);  // the rest pose: the groom as shown
    renderNow();
    waitForHair();
    const size_t strokesBefore = tool_->style().strokes.size();
    const std::vector<float> guidesBefore = guidePoints(*tool_);
    // The comb, chosen in the dock: its settings show.
    panel()->groomBrushCombo()->setCurrentIndex(1 + int(GroomBrush::Comb));
    QCOMPARE(tool_->groomBrush(), std::optional<GroomBrush>(GroomBrush::Comb));
    QVERIFY(panel()->groomRadiusBox()->isVisibleTo(panel()));
    panel()->groomRadiusBox()->setValue(4.0);
    panel()->groomStrengthBox()->setValue(1.0);
    // A guide's middle, on the side facing the camera.
    const Strands& strands = tool_->groom()->strands();
    const int middle = strands.pointsPerStrand / 2;
    const glm::vec3 camera = window_->sceneView()->cameraPosition();
    glm::vec3 target(0.0f);
    float nearest = 1e9f;
    for (size_t g = 0; g < tool_->groom()->guideCount(); ++g) {
      const float* p = strands.strand(g) + 3 * middle;
      const glm::vec3 q(p[0], p[1], p[2]);
      if (glm::length(q - camera) < nearest) nearest = glm::length(q - camera), target = q;
    }
    QWidget* viewport = window_->viewport();
    const QPoint start = toWidget(target);
    // Hovering shows the brush circle there, of the brush's radius.
    QTest::qWait(40);
    sendMouse(viewport, QEvent::MouseMove, start, Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QVERIFY(tool_->brushCursor()->visible());
    const render::BrushCursor& cursor = *tool_->brushCursor();
    QVERIFY(std::abs(glm::length(cursor.point(0) - cursor.point(render::BrushCursor::kSegments / 2)) - 0.08f) < 1e-3f);
    const glm::vec3 circleCenter = 0.5f * (cursor.point(0) + cursor.point(render::BrushCursor::kSegments / 2));
    QVERIFY2(glm::length(circleCenter - target) < 0.04f, "the circle is not at the hair under the cursor");
    const int commands = doc()->undoStack()->index();
    sendMouse(viewport, QEvent::MouseButtonPress, start, Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
    for (int step = 1; step <= 6; ++step) {
      sendMouse(viewport, QEvent::MouseMove, start + QPoint(10 * step, 0), Qt::NoButton, Qt::LeftButton,
                Qt::NoModifier);
      QTest::qWait(30);
    }
    sendMouse(viewport, QEvent::MouseButtonRelease, start + QPoint(60, 0), Qt::LeftButton, Qt::NoButton,
              Qt::NoModifier);
    waitForHair();
    QCOMPARE(doc()->undoStack()->index(), commands + 1);
    QCOMPARE(doc()->undoStack()->undoText(), QString("Comb hair"));
    QCOMPARE(tool_->style().strokes.size(), strokesBefore + 1);
    QCOMPARE(tool_->style().strokes.back().brush, GroomBrush::Comb);
    const std::vector<float> combed = guidePoints(*tool_);
    QVERIFY2(maxDifference(combed, guidesBefore) > 0.01f,
             qPrintable(QString("the comb moved the guides by %1 m").arg(maxDifference(combed, guidesBefore))));
    // Saved in the document's hair section.
    QCOMPARE(doc()->sceneSections().hair["style"]["strokes"].size(), strokesBefore + 1);
    doc()->undoStack()->undo();
    waitForHair();
    QCOMPARE(guidePoints(*tool_), guidesBefore);
    doc()->undoStack()->redo();
    waitForHair();
    QCOMPARE(guidePoints(*tool_), combed);

    // A cut (scripted, as a plug-in would): the hair it crosses is shorter; Clear takes every stroke away.
    panel()->groomBrushCombo()->setCurrentIndex(1 + int(GroomBrush::Cut));
    const float before = guideLengths(*tool_);
    QVERIFY(tool_->groomStroke(target + glm::vec3(-0.3f, 0.0f, 0.0f), target + glm::vec3(0.3f, 0.0f, 0.0f)));
    waitForHair();
    QVERIFY2(guideLengths(*tool_) < 0.99f * before,
             qPrintable(QString("guides' length %1 -> %2 m").arg(before).arg(guideLengths(*tool_))));
    QVERIFY(panel()->clearStrokesButton()->isEnabled());
    panel()->clearStrokesButton()->click();
    waitForHair();
    QVERIFY(tool_->style().strokes.empty());
    QCOMPARE(doc()->undoStack()->undoText(), QString("Clear brush strokes"));
    doc()->undoStack()->undo();
    waitForHair();
    QCOMPARE(tool_->style().strokes.size(), strokesBefore + 2);
    // Painted density: fewer strands where painted, one undo step; Ctrl paints the full density back.
    panel()->groomBrushCombo()->setCurrentIndex(1 + int(GroomBrush::PaintDensity));
    QVERIFY(panel()->groomValueBox()->isVisibleTo(panel()));
    panel()->groomValueBox()->setValue(0.0);
    QCOMPARE(tool_->groomValue(), 0.0f);
    const size_t strandsBefore = tool_->groom()->strands().strandCount();
    const int beforePaint = doc()->undoStack()->index();
    // On the scalp, at a guide's root (the paint is read where the strands grow).
    const float* rootPoint = tool_->groom()->strands().strand(0);
    const glm::vec3 root(rootPoint[0], rootPoint[1], rootPoint[2]);
    QVERIFY(tool_->groomStroke(root, root + glm::vec3(0.05f, 0.0f, 0.0f)));
    waitForHair();
    QCOMPARE(doc()->undoStack()->index(), beforePaint + 1);
    QCOMPARE(doc()->undoStack()->undoText(), QString("Paint hair density"));
    QVERIFY2(tool_->groom()->strands().strandCount() < strandsBefore,
             qPrintable(QString("%1 -> %2 strands").arg(strandsBefore).arg(tool_->groom()->strands().strandCount())));
    QCOMPARE(tool_->style().strokes.back().value, 0.0f);
    QVERIFY(tool_->groomStroke(root, root + glm::vec3(0.05f, 0.0f, 0.0f), true));
    waitForHair();
    QCOMPARE(tool_->style().strokes.back().value, 1.0f);
    doc()->undoStack()->undo();
    doc()->undoStack()->undo();
    waitForHair();
    QCOMPARE(tool_->groom()->strands().strandCount(), strandsBefore);
    // Painted colour: a lighter streak (less melanin) where painted, one undo step; Ctrl paints the style's back.
    panel()->groomBrushCombo()->setCurrentIndex(1 + int(GroomBrush::PaintMelanin));
    QCOMPARE(panel()->groomValueBox()->maximum(), 8.0);
    panel()->groomValueBox()->setValue(0.2);
    QVERIFY(tool_->groom()->strands().pigmentPaint.empty());
    QVERIFY(tool_->groomStroke(root, root + glm::vec3(0.05f, 0.0f, 0.0f)));
    waitForHair();
    QCOMPARE(doc()->undoStack()->undoText(), QString("Paint hair melanin"));
    const std::vector<float>& paint = tool_->groom()->strands().pigmentPaint;
    QCOMPARE(paint.size(), 4 * tool_->groom()->strands().strandCount());
    const float melanin = tool_->style().shading.melanin;
    QVERIFY2(paint[0] * melanin + paint[1] < 0.5f * melanin,
             qPrintable(QString("guide 0's melanin %1 (style %2)").arg(paint[0] * melanin + paint[1]).arg(melanin)));
    QVERIFY(tool_->groomStroke(root, root + glm::vec3(0.05f, 0.0f, 0.0f), true));
    waitForHair();
    QCOMPARE(tool_->style().strokes.back().value, melanin);
    doc()->undoStack()->undo();
    doc()->undoStack()->undo();
    waitForHair();
    QVERIFY(tool_->groom()->strands().pigmentPaint.empty());
    // No brush: the settings go, the dock is as it was.
    panel()->groomBrushCombo()->setCurrentIndex(0);
    QVERIFY(!tool_->groomBrush());
    QVERIFY(!tool_->brushCursor()->visible());
    QVERIFY(!panel()->groomRadiusBox()->isVisibleTo(panel()));
  }
};

int runHairToolTest(int argc, char** argv) {
  mq::ui::exitAfter(180, "gui_hair_tool");  // never hang
  HairToolTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "hair_tool_test.moc"
