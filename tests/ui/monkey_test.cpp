// A seeded monkey: 2,000 random actions a user can take (open files, scrub,
// switch clips, pose bones, undo and redo, skinning and looks, hairstyles,
// garments, short bakes cancelled or not, simulate on and off) must leave
// the editor running with a finite posed character.
// Run as `mannequin_gui_tests monkey [ACTIONS [SEED]]`.
#include <random>

#include <QTimer>
#include <QUndoStack>

#include "test_window.h"
#include "ui/document/editor_document.h"
#include "ui/garment/garment_tool.h"
#include "ui/hair/hair_tool.h"

using namespace mq;
using namespace mq::ui;

namespace {

int gActions = 2000;
unsigned gSeed = 20261204;

const QString kAssets = QString(MANNEQUIN_SHARED_DIR) + "/assets/";
const QString kScenes = QString(MANNEQUIN_SOURCE_DIR) + "/resources/scenes/";

class MonkeyTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    window_ = makeTestWindow();
    QString error;
    QVERIFY2(window_->openFileNow("default", &error), qPrintable(error));
    // Refusals of impossible actions (trousers on a sheet without a body)
    // are fine; they are counted and must read as messages, not internals.
    window_->reportError = [this](const QString& title, const QString& message) {
      ++refusals_;
      if (message.contains("json.exception") || message.contains("std::") || message.isEmpty())
        QFAIL(qPrintable("an error a user cannot read: " + title + ": " + message));
    };
    garments_ = window_->findChild<GarmentTool*>();
    hair_ = window_->findChild<HairTool*>();
    QVERIFY(garments_ && hair_);
  }

  void randomActions() {
    std::mt19937 rng(gSeed);
    const QStringList files = {
        "default",
        kAssets + "characters/CesiumMan/glTF-Binary/CesiumMan.glb",
        kAssets + "characters/RiggedSimple/RiggedSimple.gltf",
        kAssets + "characters/assimp_fbx_animation_with_skeleton/animation_with_skeleton.fbx",
        kAssets + "characters/assimp_collada_library_animation_clips/library_animation_clips.dae",
        kScenes + "hair_bob.json",
        kScenes + "garment_tshirt_walk.json",
        kScenes + "cloth_sheet_colliders.json"};
    // Weighted actions: cheap ones often, files and bakes seldom.
    struct Action {
      int weight;
      std::function<void()> run;
    };
    auto pick = [&](int n) { return n > 0 ? int(rng() % unsigned(n)) : 0; };
    auto unit = [&] { return std::uniform_real_distribution<float>(0.0f, 1.0f)(rng); };
    EditorDocument* doc = nullptr;
    const std::vector<Action> actions = {
        {25, [&] { doc->setTime(doc->clipStart() + unit() * std::max(0.0f, doc->clipEnd() - doc->clipStart())); }},
        {6, [&] { doc->setClip(pick(int(doc->character().clips.size()) + 1) - 1); }},
        {15,
         [&] {
           const int bones = int(doc->character().skeleton.boneCount());
           if (bones == 0) return;
           const glm::vec3 axis = glm::normalize(glm::vec3(unit() - 0.5f, unit() - 0.5f, unit() - 0.5f) + 1e-3f);
           doc->setBoneRotation(pick(bones), glm::angleAxis(3.0f * (unit() - 0.5f), axis));
         }},
        {10,
         [&] {
           const int bones = int(doc->character().skeleton.boneCount());
           if (bones > 0) doc->selectByName(doc->character().skeleton.bone(pick(bones)).name);
         }},
        {12, [&] { doc->undoStack()->undo(); }},
        {8, [&] { doc->undoStack()->redo(); }},
        {3, [&] { doc->setSkinning(SkinningMethod(pick(3))); }},
        {3,
         [&] {
           doc->setLook(std::vector<std::string>{"auto", "skin", "mannequin", "plain"}[pick(4)]);
         }},
        {3, [&] { window_->setSkeletonVisible(pick(2) == 0); }},
        {2, [&] { window_->frameAll(); }},
        {2, [&] { renderNow(window_); }},
        {2,
         [&] {
           hair_->useBuiltinStyle(QStringList{"bob", "wavy", "curly", "long_straight"}[pick(4)]);
         }},
        {1, [&] { hair_->removeHair(); }},
        {2,
         [&] {
           garments_->addGarment(std::vector<std::string>{"tshirt", "skirt", "trousers"}[pick(3)]);
         }},
        {1,
         [&] {
           if (doc->clipIndex() < 0) return;
           // A short bake, cancelled at once half of the time.
           QTimer cancel;
           if (pick(2) == 0) {
             connect(&cancel, &QTimer::timeout, garments_, [&] {
               if (garments_->baking()) garments_->cancelBake();
             });
             cancel.start(5);
           }
           garments_->bake(doc->clipStart(), doc->clipStart() + 0.1f);
         }},
        {1, [&] { garments_->clearBake(); }},
        {1,
         [&] {
           garments_->setSimulating(true);
           QTest::qWait(50);
           garments_->setSimulating(false);
         }},
        {2,
         [&] {
           QString error;
           window_->openFileNow(files[pick(int(files.size()))], &error);  // every listed file opens
           QVERIFY2(error.isEmpty(), qPrintable(error));
         }},
    };
    int total = 0;
    for (const Action& a : actions) total += a.weight;
    std::vector<int> counts(actions.size(), 0);
    for (int i = 0; i < gActions; ++i) {
      doc = window_->document();
      int r = pick(total);
      size_t k = 0;
      while (r >= actions[k].weight) r -= actions[k++].weight;
      actions[k].run();
      if (QTest::currentTestFailed()) QFAIL(qPrintable(QString("action %1 (kind %2) failed").arg(i).arg(k)));
      ++counts[k];
      QApplication::processEvents();
    }
    hair_->finishBackgroundWork();
    QApplication::processEvents();
    QVERIFY(!window_->isBusy());
    for (const PosedMesh& mesh : window_->document()->posed().meshes())
      for (float x : mesh.positions) QVERIFY(std::isfinite(x));
    QString summary;
    for (size_t k = 0; k < counts.size(); ++k) summary += QString(" %1").arg(counts[k]);
    qInfo("monkey: %d actions (seed %u), %d refused with a message; by kind:%s", gActions, gSeed, refusals_,
          qPrintable(summary));
  }

  void cleanupTestCase() { delete window_; }

 private:
  MainWindow* window_ = nullptr;
  GarmentTool* garments_ = nullptr;
  HairTool* hair_ = nullptr;
  int refusals_ = 0;
};

}  // namespace

int runMonkeyTest(int argc, char** argv) {
  // `monkey [ACTIONS [SEED]]` before the QTest options.
  if (argc > 1 && argv[1][0] != '-') gActions = std::atoi(argv[1]), --argc, ++argv;
  if (argc > 1 && argv[1][0] != '-') gSeed = unsigned(std::strtoul(argv[1], nullptr, 10)), --argc, ++argv;
  mq::ui::exitAfter(1500, "gui_monkey");  // never hang
  MonkeyTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "monkey_test.moc"
