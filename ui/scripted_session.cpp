#include "ui/scripted_session.h"

#include <cstdio>

#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QEventLoop>
#include <QTimer>

#include "ui/document/editor_document.h"
#include "ui/garment/garment_tool.h"
#include "ui/hair/hair_panel.h"
#include "ui/hair/hair_tool.h"
#include "ui/main_window.h"

namespace mq::ui {
namespace {

// Saves a picture of the whole window and quits.
void saveScreenshotAndQuit(MainWindow& window, const QString& path, bool loaded) {
  const bool saved = window.grab().save(path);
  if (!saved) std::fprintf(stderr, "mannequin: %s: could not write the screenshot\n", qPrintable(path));
  QCoreApplication::exit(saved && loaded ? 0 : 1);
}

void bake(GarmentTool& tool, int count) {
  // Given twice, bakes twice (the second reuses the sewn garments): each bake's time goes to stderr.
  for (int b = 0; b < count; ++b) {
    if (!tool.bake()) {
      std::fprintf(stderr, "mannequin: bake: %s\n", qPrintable(tool.lastError()));
      return;
    }
    std::fprintf(stderr,
                 "mannequin: bake %d: %d frames in %.1f s: sewing %.1f s, draping %.1f s, frames %.1f s "
                 "(sewing ran %d times, reused %d times)\n",
                 b + 1, tool.bakedFrameCount(), tool.lastBakeSeconds(), tool.lastBakePhaseSeconds(0),
                 tool.lastBakePhaseSeconds(1), tool.lastBakePhaseSeconds(2), tool.sewingRuns(), tool.reusedSewings());
  }
}

void simulate(GarmentTool& tool, int steps) {
  tool.setSimulating(true);
  while (tool.simulating() && tool.simulatedSteps() < steps) QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
  tool.setSimulating(false);
  if (!tool.lastError().isEmpty()) std::fprintf(stderr, "mannequin: simulate: %s\n", qPrintable(tool.lastError()));
}

}  // namespace

void ScriptedSession::run(MainWindow& window, bool loaded) const {
  EditorDocument* doc = window.document();
  if (clip == "rest")
    doc->setClip(-1);
  else if (!clip.isEmpty())
    doc->setClip(doc->character().findClip(clip.toStdString()));
  auto* garments = window.findChild<GarmentTool*>();
  for (const QString& type : addGarments) garments->addGarment(type.toStdString());
  if (!addGarments.isEmpty() || bakes > 0 || showStretch || simulateSteps > 0) garments->dock()->raise();
  bake(*garments, bakes);
  if (!exportBakeDir.isEmpty()) {
    if (garments->exportBake(exportBakeDir))
      std::fprintf(stderr, "mannequin: exported %d baked frames to %s\n", garments->bakedFrameCount(),
                   qPrintable(exportBakeDir));
    else
      std::fprintf(stderr, "mannequin: export bake: %s\n", qPrintable(garments->lastError()));
  }
  if (simulateSteps > 0) simulate(*garments, simulateSteps);
  if (showStretch) garments->setStretchVisible(true);
  if (showPattern) garments->showPatternDock();
  if (!hairBrush.isEmpty()) {
    auto* hair = window.findChild<HairTool*>();
    const int index = hair->panel()->groomBrushCombo()->findText(QString(hairBrush).replace('_', ' '));
    if (index > 0 && hair->hasHair()) {
      hair->dock()->raise();
      hair->panel()->groomBrushCombo()->setCurrentIndex(index);
    } else {
      std::fprintf(stderr, "mannequin: --hair-brush: no hair, or no brush named '%s'\n", qPrintable(hairBrush));
    }
  }
  if (setTime) doc->setTime(doc->clipStart() + float(time));
  if (!select.isEmpty() && !doc->selectByName(select.toStdString()))
    std::fprintf(stderr, "mannequin: --select: no bone, material or mesh named '%s'\n", qPrintable(select));
  QString error;
  if (!saveAs.isEmpty() && !window.saveDocument(saveAs, &error))
    std::fprintf(stderr, "mannequin: %s\n", qPrintable(error));
  if (!takesScreenshot()) return;
  // The hair grows on a worker: the picture shows it grown.
  if (auto* hair = window.findChild<HairTool*>()) {
    hair->finishBackgroundWork();
    hair->setDrawingInParts(false);
  }
  const QString path = screenshot;
  QTimer::singleShot(400, &window, [&window, path, loaded] { saveScreenshotAndQuit(window, path, loaded); });
}

}  // namespace mq::ui
