// mannequin: the editor. `mannequin [FILE] [--screenshot OUT.png]`.
// FILE is "default" (the built-in mannequin, also when omitted), a character
// (glTF, GLB, FBX, DAE), a BVH motion (applied to the default mannequin) or a
// scene document. --screenshot renders the window once the file is open,
// saves it as a PNG and quits (exit code 1 if the file could not be opened).
#include <cstdio>

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>
#include <QTimer>

#include "ui/document/document_loader.h"
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
  parser.addOption(screenshot);
  parser.addOption(size);
  parser.process(app);
  const QStringList files = parser.positionalArguments();
  const QString file = files.isEmpty() ? QString("default") : files.first();

  mq::ui::MainWindow window;
  const QStringList wh = parser.value(size).split('x');
  window.resize(wh.value(0).toInt() > 0 ? wh.value(0).toInt() : 1600, wh.value(1).toInt() > 0 ? wh.value(1).toInt() : 1000);
  const bool takeScreenshot = parser.isSet(screenshot);
  if (takeScreenshot) {
    // No dialogs in batch mode: errors go to stderr.
    window.reportError = [](const QString&, const QString& message) {
      std::fprintf(stderr, "mannequin: %s\n", qPrintable(message));
    };
  }
  window.show();

  const QString screenshotPath = parser.value(screenshot);
  // After the next load finishes, let the layout settle and the viewport
  // paint, then grab.
  auto screenshotAfterLoad = [&window, takeScreenshot, screenshotPath] {
    if (!takeScreenshot) return;
    QObject::connect(&window, &mq::ui::MainWindow::loadFinished, &window, [&window, screenshotPath](bool ok) {
      QTimer::singleShot(400, &window, [&window, screenshotPath, ok] { saveScreenshotAndQuit(window, screenshotPath, ok); });
    }, Qt::SingleShotConnection);
  };

  if (mq::ui::isMotionFile(file)) {
    // A motion alone is shown on the default mannequin.
    QObject::connect(&window, &mq::ui::MainWindow::loadFinished, &window, [&window, file, screenshotAfterLoad](bool) {
      screenshotAfterLoad();
      window.openFile(file);
    }, Qt::SingleShotConnection);
    window.openFile("default");
  } else {
    screenshotAfterLoad();
    window.openFile(file);
  }
  return app.exec();
}
