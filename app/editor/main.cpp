// mannequin: the editor. `mannequin [FILE] [--screenshot OUT.png]`.
// FILE is "default" (the built-in mannequin, also when omitted), a character
// (glTF, GLB, FBX, DAE), a BVH motion (applied to the default mannequin) or a
// scene document. --screenshot renders the window once the file is open,
// saves it as a PNG and quits (exit code 1 if the file could not be opened).
// --select NAME (bone, material or mesh), --clip NAME and --time SECONDS set up the view first;
// --map MAP names the bone-name map of a BVH FILE. --add-garment TYPE,
// --bake-garments (twice: bake twice), --export-bake DIR, --simulate-garments N, --garment-stretch
// and --save-as script the garment tool
// (documentation pictures, test scenes).
#include <cstdio>

#include <QApplication>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QEventLoop>
#include <QSurfaceFormat>
#include <QTimer>

#include "ui/document/document_loader.h"
#include "ui/document/editor_document.h"
#include "ui/garment/garment_tool.h"
#include "ui/hair/hair_tool.h"
#include "ui/document/autosave.h"
#include "ui/main_window.h"
#include "ui/theme.h"
#include "ui/viewport/vtk_viewport_widget.h"

namespace {

// Saves a picture of the whole window and quits.
void saveScreenshotAndQuit(mq::ui::MainWindow& window, const QString& path, bool loaded) {
  const bool saved = window.grab().save(path);
  if (!saved) std::fprintf(stderr, "mannequin: %s: could not write the screenshot\n", qPrintable(path));
  QCoreApplication::exit(saved && loaded ? 0 : 1);
}

}  // namespace

int main(int argc, char** argv) {
  // The viewport bridge needs this before QApplication exists.
  QSurfaceFormat::setDefaultFormat(mq::ui::VtkViewportWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setApplicationName("Mannequin");
  QApplication::setOrganizationName("Mannequin");
  QApplication::setApplicationVersion("0.1");
  mq::ui::applyEditorTheme(app);

  QCommandLineParser parser;
  parser.setApplicationDescription("Mannequin: pose, animate, groom and dress virtual humans.");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument("FILE", "default, a character (.gltf .glb .fbx .dae), a motion (.bvh) "
                                       "or a scene document (.mqscene)");
  const QCommandLineOption screenshot("screenshot", "Save a picture of the window to OUT.png and quit.", "OUT.png");
  const QCommandLineOption size("size", "Window size, WIDTHxHEIGHT (default 1600x1000).", "WxH", "1600x1000");
  const QCommandLineOption select("select", "Select a bone (shows the rotation gizmo on it), a material or a mesh by NAME.",
                                  "NAME");
  const QCommandLineOption clip("clip", "Show clip NAME (or index; rest: the rest pose).", "NAME");
  const QCommandLineOption timeOption("time", "Go to SECONDS into the clip.", "SECONDS");
  const QCommandLineOption map("map", "Bone-name map for a BVH FILE (see core/io/bvh_import.h).", "MAP");
  const QCommandLineOption addGarment("add-garment", "Add a built-in garment: tshirt, skirt or trousers (repeatable).",
                                      "TYPE");
  const QCommandLineOption bakeGarments("bake-garments", "Bake the garments over the clip before the screenshot.");
  const QCommandLineOption garmentStretch("garment-stretch", "Show the garments' stretch overlay.");
  const QCommandLineOption saveAs("save-as", "Save the scene document to FILE once set up.", "FILE");
  parser.addOption(addGarment);
  parser.addOption(bakeGarments);
  const QCommandLineOption simulateGarments("simulate-garments",
                                            "Simulate the garments (and the sheet) live for N steps before the screenshot.", "N");
  parser.addOption(simulateGarments);
  const QCommandLineOption exportBake("export-bake", "After --bake-garments, write the bake as OBJ sequences into DIR.",
                                      "DIR");
  parser.addOption(exportBake);
  parser.addOption(garmentStretch);
  parser.addOption(saveAs);
  parser.addOption(map);
  parser.addOption(screenshot);
  parser.addOption(select);
  parser.addOption(clip);
  parser.addOption(timeOption);
  parser.addOption(size);
  parser.process(app);
  const QStringList files = parser.positionalArguments();
  const QString file = files.isEmpty() ? QString("default") : files.first();

  mq::ui::MainWindow window;
  const QStringList wh = parser.value(size).split('x');
  window.resize(wh.value(0).toInt() > 0 ? wh.value(0).toInt() : 1600, wh.value(1).toInt() > 0 ? wh.value(1).toInt() : 1000);
  const bool takeScreenshot = parser.isSet(screenshot);
  // Screenshots use the default layout, so they look the same everywhere.
  if (!takeScreenshot && !parser.isSet(size)) window.restoreWindowState();
  if (takeScreenshot) {
    // No dialogs in batch mode: errors go to stderr.
    window.reportError = [](const QString&, const QString& message) {
      std::fprintf(stderr, "mannequin: %s\n", qPrintable(message));
    };
  }
  window.show();

  // Once the file is open: apply the view options, then take the screenshot
  // after the layout has settled and the viewport has painted.
  const QString screenshotPath = parser.value(screenshot);
  const QString selectBone = parser.value(select), clipName = parser.value(clip);
  const double time = parser.value(timeOption).toDouble();
  const bool setTime = parser.isSet(timeOption);
  const QStringList garments = parser.values(addGarment);
  // Given twice, bakes twice (the second reuses the sewn garments): each bake's time goes to stderr.
  const int bake = int(parser.optionNames().count("bake-garments"));
  const bool stretch = parser.isSet(garmentStretch);
  const int simulateSteps = parser.value(simulateGarments).toInt();
  const QString savePath = parser.value(saveAs);
  const QString exportDir = parser.value(exportBake);
  auto afterLoad = [&window, takeScreenshot, screenshotPath, selectBone, clipName, time, setTime, garments, bake,
                    stretch, simulateSteps, savePath, exportDir] {
    QObject::connect(&window, &mq::ui::MainWindow::loadFinished, &window,
        [&window, takeScreenshot, screenshotPath, selectBone, clipName, time, setTime, garments, bake, stretch,
         simulateSteps, savePath, exportDir](bool ok) {
          mq::ui::EditorDocument* doc = window.document();
          if (clipName == "rest") doc->setClip(-1);
          else if (!clipName.isEmpty()) doc->setClip(doc->character().findClip(clipName.toStdString()));
          auto* garmentTool = window.findChild<mq::ui::GarmentTool*>();
          for (const QString& type : garments) garmentTool->addGarment(type.toStdString());
          if (!garments.isEmpty() || bake || stretch) garmentTool->dock()->raise();
          if (simulateSteps > 0 || bake) garmentTool->dock()->raise();
          for (int b = 0; b < bake; ++b) {
            if (!garmentTool->bake()) {
              std::fprintf(stderr, "mannequin: bake: %s\n", qPrintable(garmentTool->lastError()));
              break;
            }
            std::fprintf(stderr,
                         "mannequin: bake %d: %d frames in %.1f s: sewing %.1f s, draping %.1f s, frames %.1f s "
                         "(sewing ran %d times, reused %d times)\n",
                         b + 1, garmentTool->bakedFrameCount(), garmentTool->lastBakeSeconds(),
                         garmentTool->lastBakePhaseSeconds(0), garmentTool->lastBakePhaseSeconds(1),
                         garmentTool->lastBakePhaseSeconds(2), garmentTool->sewingRuns(), garmentTool->reusedSewings());
          }
          if (!exportDir.isEmpty()) {
            if (garmentTool->exportBake(exportDir))
              std::fprintf(stderr, "mannequin: exported %d baked frames to %s\n", garmentTool->bakedFrameCount(),
                           qPrintable(exportDir));
            else
              std::fprintf(stderr, "mannequin: export bake: %s\n", qPrintable(garmentTool->lastError()));
          }
          if (simulateSteps > 0) {
            garmentTool->setSimulating(true);
            while (garmentTool->simulating() && garmentTool->simulatedSteps() < simulateSteps)
              QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
            garmentTool->setSimulating(false);
            if (!garmentTool->lastError().isEmpty())
              std::fprintf(stderr, "mannequin: simulate: %s\n", qPrintable(garmentTool->lastError()));
          }
          if (stretch) garmentTool->setStretchVisible(true);
          if (setTime) doc->setTime(doc->clipStart() + float(time));
          if (!selectBone.isEmpty() && !doc->selectByName(selectBone.toStdString()))
            std::fprintf(stderr, "mannequin: --select: no bone, material or mesh named '%s'\n", qPrintable(selectBone));
          QString error;
          if (!savePath.isEmpty() && !window.saveDocument(savePath, &error))
            std::fprintf(stderr, "mannequin: %s\n", qPrintable(error));
          if (!takeScreenshot) return;
          // The hair grows on a worker: the picture shows it grown.
          if (auto* hairTool = window.findChild<mq::ui::HairTool*>()) {
            hairTool->finishBackgroundWork();
            hairTool->setDrawingInParts(false);
          }
          QTimer::singleShot(400, &window, [&window, screenshotPath, ok] { saveScreenshotAndQuit(window, screenshotPath, ok); });
        },
        Qt::SingleShotConnection);
  };

  // Interactive sessions keep a recovery copy of unsaved work, and offer the
  // one a crashed session left once the first file is open.
  if (!takeScreenshot) {
    bool isNumber = false;
    const int seconds = qEnvironmentVariable("MANNEQUIN_AUTOSAVE_SECONDS").toInt(&isNumber);
    window.enableAutosave(mq::ui::Autosave::defaultFolder(), isNumber && seconds > 0 ? seconds : 60);
    QObject::connect(&window, &mq::ui::MainWindow::loadFinished, &window, [&window] { window.offerRecovery(); },
                     Qt::SingleShotConnection);
  }

  if (mq::ui::isMotionFile(file)) {
    // A motion alone is shown on the default mannequin.
    const QString mapPath = parser.value(map);
    QObject::connect(&window, &mq::ui::MainWindow::loadFinished, &window, [&window, file, mapPath, afterLoad](bool) {
      afterLoad();
      window.applyMotion(file, mapPath);
    }, Qt::SingleShotConnection);
    window.openFile("default");
  } else {
    afterLoad();
    window.openFile(file);
  }
  return app.exec();
}
