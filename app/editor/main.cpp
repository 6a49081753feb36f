// mannequin: the editor. `mannequin [FILE] [--screenshot OUT.png]`.
// FILE is "default" (the built-in mannequin, also when omitted), a character
// (glTF, GLB, FBX, DAE), a BVH motion (applied to the default mannequin) or a
// scene document. --screenshot renders the window once the file is open,
// saves it as a PNG and quits (exit code 1 if the file could not be opened).
// --select NAME (bone, material or mesh), --clip NAME and --time SECONDS set up the view first;
// --map MAP names the bone-name map of a BVH FILE. --add-garment TYPE,
// --bake-garments (twice: bake twice), --export-bake DIR, --simulate-garments N, --garment-stretch,
// --garment-pattern and --save-as script the garment tool
// (documentation pictures, test scenes).
#include <cstdio>
#include <cstdlib>

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>

#include "ui/document/autosave.h"
#include "ui/document/document_loader.h"
#include "ui/main_window.h"
#include "ui/scripted_session.h"
#include "ui/theme.h"
#include "ui/viewport/vtk_viewport_widget.h"

namespace {

// The editor's command line (its man page is made from --help).
struct EditorOptions {
  const QCommandLineOption screenshot{"screenshot", "Save a picture of the window to OUT.png and quit.", "OUT.png"};
  const QCommandLineOption size{"size", "Window size, WIDTHxHEIGHT (default 1600x1000).", "WxH", "1600x1000"};
  const QCommandLineOption select{
      "select", "Select a bone (shows the rotation gizmo on it), a material or a mesh by NAME.", "NAME"};
  const QCommandLineOption clip{"clip", "Show clip NAME (or index; rest: the rest pose).", "NAME"};
  const QCommandLineOption time{"time", "Go to SECONDS into the clip.", "SECONDS"};
  const QCommandLineOption map{"map", "Bone-name map for a BVH FILE (see core/io/bvh_import.h).", "MAP"};
  const QCommandLineOption addGarment{"add-garment", "Add a built-in garment: tshirt, skirt or trousers (repeatable).",
                                      "TYPE"};
  const QCommandLineOption bakeGarments{"bake-garments", "Bake the garments over the clip before the screenshot."};
  const QCommandLineOption simulateGarments{
      "simulate-garments", "Simulate the garments (and the sheet) live for N steps before the screenshot.", "N"};
  const QCommandLineOption exportBake{"export-bake", "After --bake-garments, write the bake as OBJ sequences into DIR.",
                                      "DIR"};
  const QCommandLineOption garmentStretch{"garment-stretch", "Show the garments' stretch overlay."};
  const QCommandLineOption garmentPattern{"garment-pattern", "Show the current garment's pattern dock."};
  const QCommandLineOption hairBrush{"hair-brush", "Choose a grooming brush in the Hair dock (comb, cut, ...).",
                                     "NAME"};
  const QCommandLineOption saveAs{"save-as", "Save the scene document to FILE once set up.", "FILE"};

  void describe(QCommandLineParser& parser) const {
    parser.setApplicationDescription("Mannequin: pose, animate, groom and dress virtual humans.");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument("FILE",
                                 "default, a character (.gltf .glb .fbx .dae), a motion (.bvh) "
                                 "or a scene document (.mqscene)",
                                 "[FILE]");
    parser.addOptions({addGarment, bakeGarments, simulateGarments, exportBake, garmentStretch, garmentPattern,
                       hairBrush, saveAs, map, screenshot, select, clip, time, size});
  }
};

// --help and --version print and exit without a display: a QApplication
// would need one, and the man page is made from them at build time.
void answerHelpOrVersion(QCommandLineParser& parser, int& argc, char** argv) {
  QStringList arguments;
  for (int i = 0; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);
  if (!parser.parse(arguments) || !(parser.isSet("help") || parser.isSet("version"))) return;
  if (parser.isSet("version")) {
    std::printf("Mannequin %s\nLicence: GPL-3.0-or-later (it links CGAL's GPL packages); see LICENSE.\n",
                MANNEQUIN_VERSION);
    std::exit(0);
  }
  QCoreApplication app(argc, argv);
  parser.process(app);  // prints and exits
}

}  // namespace

int main(int argc, char** argv) {
  // The viewport bridge needs this before QApplication exists.
  QSurfaceFormat::setDefaultFormat(mq::ui::VtkViewportWidget::defaultFormat());
  QCoreApplication::setApplicationName("Mannequin");
  QCoreApplication::setOrganizationName("Mannequin");
  QCoreApplication::setApplicationVersion(MANNEQUIN_VERSION);
  QCommandLineParser parser;
  const EditorOptions options;
  options.describe(parser);
  answerHelpOrVersion(parser, argc, argv);

  QApplication app(argc, argv);
  mq::ui::applyEditorTheme(app);
  parser.process(app);
  const QStringList files = parser.positionalArguments();
  const QString file = files.isEmpty() ? QString("default") : files.first();

  mq::ui::MainWindow window;
  const QStringList wh = parser.value(options.size).split('x');
  window.resize(wh.value(0).toInt() > 0 ? wh.value(0).toInt() : 1600,
                wh.value(1).toInt() > 0 ? wh.value(1).toInt() : 1000);
  const bool takeScreenshot = parser.isSet(options.screenshot);
  // Screenshots use the default layout, so they look the same everywhere.
  if (!takeScreenshot && !parser.isSet(options.size)) window.restoreWindowState();
  if (takeScreenshot) {
    // No dialogs in batch mode: errors go to stderr.
    window.reportError = [](const QString&, const QString& message) {
      std::fprintf(stderr, "mannequin: %s\n", qPrintable(message));
    };
  }
  window.show();

  // Once the file is open: the scripted actions, then the screenshot.
  mq::ui::ScriptedSession session;
  session.clip = parser.value(options.clip);
  session.setTime = parser.isSet(options.time);
  session.time = parser.value(options.time).toDouble();
  session.select = parser.value(options.select);
  session.addGarments = parser.values(options.addGarment);
  session.bakes = int(parser.optionNames().count("bake-garments"));
  session.exportBakeDir = parser.value(options.exportBake);
  session.simulateSteps = parser.value(options.simulateGarments).toInt();
  session.showStretch = parser.isSet(options.garmentStretch);
  session.showPattern = parser.isSet(options.garmentPattern);
  session.hairBrush = parser.value(options.hairBrush);
  session.saveAs = parser.value(options.saveAs);
  session.screenshot = parser.value(options.screenshot);
  auto afterLoad = [&window, session] {
    QObject::connect(
        &window, &mq::ui::MainWindow::loadFinished, &window, [&window, session](bool ok) { session.run(window, ok); },
        Qt::SingleShotConnection);
  };

  if (mq::ui::isMotionFile(file)) {
    // A motion alone is shown on the default mannequin.
    const QString mapPath = parser.value(options.map);
    QObject::connect(
        &window, &mq::ui::MainWindow::loadFinished, &window,
        [&window, file, mapPath, afterLoad](bool) {
          afterLoad();
          window.applyMotion(file, mapPath);
        },
        Qt::SingleShotConnection);
    window.openFile("default");
  } else {
    afterLoad();
    window.openFile(file);
  }
  // Interactive sessions keep a recovery copy of unsaved work, and offer the
  // one a crashed session left once the first file is open.
  if (!takeScreenshot) {
    bool isNumber = false;
    const int seconds = qEnvironmentVariable("MANNEQUIN_AUTOSAVE_SECONDS").toInt(&isNumber);
    window.enableAutosave(mq::ui::Autosave::defaultFolder(), isNumber && seconds > 0 ? seconds : 60);
    QObject::connect(
        &window, &mq::ui::MainWindow::loadFinished, &window, [&window] { window.offerRecovery(); },
        Qt::SingleShotConnection);
  }

  return app.exec();
}
