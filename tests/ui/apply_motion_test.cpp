// File > Apply Motion on the default mannequin: the dialog shows the CMU
// skeleton beside the character's with the counts and the unmatched bones,
// a name map (good or bad) changes the pairing in place, Apply adds the clip
// in one undo step and the status bar reports the match, undo restores the
// pose from before, and a malformed BVH is refused with the file named.
// Run as `mannequin_gui_tests motion`; with MANNEQUIN_SCREENSHOT_DIR set it
// saves the dialog as apply_motion_dialog.png there.
#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QUndoStack>

#include "test_window.h"
#include "ui/document/editor_document.h"
#include "ui/motion/apply_motion_dialog.h"

using namespace mq;
using namespace mq::ui;

namespace {

const QString kCmu = QString(MANNEQUIN_SHARED_DIR) + "/assets/motion/cmu_01_01.bvh";
const QString kCmuMap = QString(MANNEQUIN_SOURCE_DIR) + "/resources/motion_maps/cmu_to_default.txt";

std::vector<float> allPositions(const EditorDocument& doc) {
  std::vector<float> out;
  for (const PosedMesh& m : doc.posed().meshes()) out.insert(out.end(), m.positions.begin(), m.positions.end());
  return out;
}

// Items of a tree, all levels, and those drawn as unmatched.
void countItems(QTreeWidgetItem* item, int& all, int& unmatched) {
  ++all;
  if (item->background(0).style() != Qt::NoBrush) ++unmatched;
  for (int c = 0; c < item->childCount(); ++c) countItems(item->child(c), all, unmatched);
}

std::pair<int, int> itemCounts(QTreeWidget* tree) {
  int all = 0, unmatched = 0;
  for (int i = 0; i < tree->topLevelItemCount(); ++i) countItems(tree->topLevelItem(i), all, unmatched);
  return {all, unmatched};
}

QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& text) {
  QFile file(dir.filePath(name));
  if (file.open(QIODevice::WriteOnly)) file.write(text);
  return file.fileName();
}

}  // namespace

class ApplyMotionTest : public QObject {
  Q_OBJECT

 private:
  MainWindow* window_ = nullptr;
  QTemporaryDir dir_;
  EditorDocument* doc() { return window_->document(); }

  ApplyMotionDialog* openDialog() {
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);  // the last test's dialog
    window_->applyMotionWithDialog();
    auto* dialog = window_->findChild<ApplyMotionDialog*>();
    if (dialog && !QTest::qWaitForWindowExposed(dialog)) return nullptr;
    return dialog;
  }

 private slots:
  void initTestCase() {
    window_ = makeTestWindow();
    QVERIFY(QTest::qWaitForWindowExposed(window_));
    QString error;
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
  }

  void cleanupTestCase() { delete window_; }

  void dialogShowsBothSkeletonsAndTheMatches() {
    ApplyMotionDialog* dialog = openDialog();
    QVERIFY(dialog);
    QVERIFY(!dialog->applyButton()->isEnabled());  // nothing chosen yet
    dialog->setMotionFile(kCmu);
    QVERIFY2(dialog->summaryLabel()->text().startsWith("matched 19 of 31 bones\nunmatched: LHipJoint, LeftToeBase"),
             qPrintable(dialog->summaryLabel()->text()));
    QVERIFY(dialog->summaryLabel()->text().endsWith("\nnot driven on the character: toes_l, toes_r"));
    QCOMPARE(itemCounts(dialog->motionTree()), std::make_pair(31, 12));
    QCOMPARE(itemCounts(dialog->characterTree()), std::make_pair(doc()->character().skeleton.boneCount(), 2));
    QTreeWidgetItem* hips = dialog->motionTree()->topLevelItem(0);
    QCOMPARE(hips->text(0), QString("Hips"));
    QCOMPARE(hips->text(1), QString("pelvis"));
    QCOMPARE(hips->text(2), QString("humanoid role (pelvis)"));
    QVERIFY(dialog->applyButton()->isEnabled());
    QApplication::processEvents();  // lay out the summary's lines before a screenshot
    if (const QByteArray shots = qgetenv("MANNEQUIN_SCREENSHOT_DIR"); !shots.isEmpty())
      QVERIFY(dialog->grab().save(QDir(QString::fromLocal8Bit(shots)).filePath("apply_motion_dialog.png")));
    dialog->reject();
  }

  void nameMapInsideTheDialog() {
    ApplyMotionDialog* dialog = openDialog();
    QVERIFY(dialog);
    dialog->setMotionFile(kCmu);
    dialog->setNameMapFile(kCmuMap);
    QVERIFY2(dialog->summaryLabel()->text().startsWith("matched 21 of 31 bones\n"),
             qPrintable(dialog->summaryLabel()->text()));
    QCOMPARE(dialog->motionTree()->topLevelItem(0)->text(2), QString("name map"));

    const QString bad = writeFile(dir_, "bad.map", "Hips pelvis\nLeftArm\n");
    dialog->setNameMapFile(bad);
    const QString problem = dialog->summaryLabel()->text();
    QVERIFY2(problem.contains(bad) && problem.contains("line 2"), qPrintable(problem));
    QVERIFY(!dialog->applyButton()->isEnabled());
    dialog->setNameMapFile(QString());
    QVERIFY(dialog->summaryLabel()->text().startsWith("matched 19 of 31 bones\n"));
    QVERIFY(dialog->applyButton()->isEnabled());
    dialog->reject();
  }

  void applyIsOneUndoStep() {
    const int clipsBefore = int(doc()->character().clips.size());
    const int clipBefore = doc()->clipIndex();
    const std::vector<float> before = allPositions(*doc());
    const int undoBefore = doc()->undoStack()->count();
    const bool modifiedBefore = doc()->isModified();

    ApplyMotionDialog* dialog = openDialog();
    QVERIFY(dialog);
    dialog->setMotionFile(kCmu);
    dialog->rootMotionBox()->setChecked(false);  // in place
    QSignalSpy finished(window_, &MainWindow::loadFinished);
    dialog->applyButton()->click();
    QVERIFY(finished.wait(30000));
    QCOMPARE(finished.first().first().toBool(), true);

    QCOMPARE(int(doc()->character().clips.size()), clipsBefore + 1);
    QCOMPARE(doc()->character().clips[doc()->clipIndex()].name, std::string("cmu_01_01"));
    QCOMPARE(doc()->undoStack()->count(), undoBefore + 1);
    QVERIFY(doc()->isModified());
    QVERIFY(doc()->sceneSections().motionInPlace);
    QCOMPARE(QString::fromStdString(doc()->sceneSections().motionFile), QFileInfo(kCmu).absoluteFilePath());
    const QString status = window_->statusBar()->currentMessage();
    QVERIFY2(status.contains("matched 19 of 31 bones; unmatched: LHipJoint"), qPrintable(status));
    doc()->setTime(2.0f);
    QVERIFY(allPositions(*doc()) != before);

    doc()->undoStack()->undo();
    QCOMPARE(int(doc()->character().clips.size()), clipsBefore);
    QCOMPARE(doc()->clipIndex(), clipBefore);
    QVERIFY(doc()->sceneSections().motionFile.empty());
    QVERIFY(!doc()->sceneSections().motionInPlace);
    QCOMPARE(allPositions(*doc()), before);
    QCOMPARE(doc()->isModified(), modifiedBefore);

    doc()->undoStack()->redo();
    QCOMPARE(doc()->character().clips.back().name, std::string("cmu_01_01"));
    doc()->undoStack()->undo();
  }

  // View > Follow Character: the camera moves with the pelvis over the
  // ground while the CMU capture carries the mannequin away.
  void followCharacterKeepsTheWalkInView() {
    QSignalSpy finished(window_, &MainWindow::loadFinished);
    window_->applyMotion(kCmu);
    QVERIFY(finished.wait(30000));
    QCOMPARE(finished.first().first().toBool(), true);
    window_->followAction()->setChecked(true);
    const int pelvis = doc()->character().skeleton.findBone("pelvis");
    const auto pelvisAt = [&](float t) {
      doc()->setTime(t);
      return glm::vec3(doc()->posed().worldFromBone()[pelvis][3]);
    };
    const glm::vec3 start = pelvisAt(0.0f);
    const glm::vec3 focusAtStart = window_->sceneView()->cameraFocus();
    const glm::vec3 later = pelvisAt(5.0f);
    const glm::vec3 moved = window_->sceneView()->cameraFocus() - focusAtStart;
    QVERIFY(glm::length(glm::vec2(later.x - start.x, later.z - start.z)) > 0.5f);
    QVERIFY(std::abs(moved.x - (later.x - start.x)) < 1e-3f);
    QVERIFY(std::abs(moved.z - (later.z - start.z)) < 1e-3f);
    QVERIFY(std::abs(moved.y) < 1e-6f);  // the steps' bob does not shake the view
    window_->followAction()->setChecked(false);
    const glm::vec3 focus = window_->sceneView()->cameraFocus();
    pelvisAt(0.0f);
    QCOMPARE(window_->sceneView()->cameraFocus(), focus);
    doc()->undoStack()->undo();
  }

  void malformedBvhKeepsTheDocument() {
    const QString bad = writeFile(dir_, "broken.bvh", "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 x\n");
    ApplyMotionDialog* dialog = openDialog();
    QVERIFY(dialog);
    dialog->setMotionFile(bad);
    const QString problem = dialog->summaryLabel()->text();
    QVERIFY2(problem.contains(bad) && problem.contains("line 4"), qPrintable(problem));
    QVERIFY(!dialog->applyButton()->isEnabled());
    dialog->reject();

    // Applied without the dialog (a dropped file): an error naming the file.
    const size_t clips = doc()->character().clips.size();
    const std::vector<float> before = allPositions(*doc());
    QString reported;
    auto previous = window_->reportError;
    window_->reportError = [&reported](const QString&, const QString& message) { reported = message; };
    QSignalSpy finished(window_, &MainWindow::loadFinished);
    window_->applyMotion(bad);
    QVERIFY(finished.wait(20000));
    window_->reportError = previous;
    QCOMPARE(finished.first().first().toBool(), false);
    QVERIFY2(reported.contains("broken.bvh") && reported.contains("line 4"), qPrintable(reported));
    QCOMPARE(doc()->character().clips.size(), clips);
    QCOMPARE(allPositions(*doc()), before);
  }
};

int runApplyMotionTest(int argc, char** argv) {
  mq::ui::exitAfter(180, "gui_apply_motion");  // never hang
  ApplyMotionTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "apply_motion_test.moc"
