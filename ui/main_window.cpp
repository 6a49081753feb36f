#include "ui/main_window.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QUndoStack>
#include <QtConcurrent/QtConcurrentRun>

#include <variant>

#include "core/io/mesh_export.h"
#include "render/scene_view.h"
#include "ui/document/document_loader.h"
#include "ui/document/editor_document.h"
#include "ui/document/pose_commands.h"
#include "ui/icons.h"
#include "ui/panels/properties_panel.h"
#include "ui/panels/scene_tree_panel.h"
#include "ui/panels/timeline_panel.h"
#include "ui/hair/hair_tool.h"
#include "ui/viewport/pose_tool.h"
#include "ui/viewport/vtk_viewport_widget.h"

namespace mq::ui {
namespace {

constexpr int kMaxRecentFiles = 8;
const char* kRecentFilesKey = "recentFiles";

// What a worker thread hands back: the result or the error text.
template <typename T>
using Outcome = std::variant<T, QString>;

template <typename T, typename Work>
Outcome<T> runCatching(Work work) {
  try {
    return work();
  } catch (const std::exception& e) {
    return QString::fromUtf8(e.what());
  }
}

QString summaryOf(const Character& c) {
  const QLocale locale;
  return QObject::tr("%1 vertices, %2 triangles, %3 bones, %4 clips")
      .arg(locale.toString(qulonglong(c.vertexCount())))
      .arg(locale.toString(qulonglong(c.triangleCount())))
      .arg(c.skeleton.boneCount())
      .arg(c.clips.size());
}

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      document_(new EditorDocument(this)),
      scene_(std::make_unique<render::SceneView>()),
      viewport_(new VtkViewportWidget(this)) {
  setObjectName("MannequinMainWindow");
  setAcceptDrops(true);
  setDockOptions(AnimatedDocks | AllowTabbedDocks | AllowNestedDocks);
  setCentralWidget(viewport_);
  viewport_->addRenderer(scene_->renderer());
  poseTool_ = new PoseTool(document_, scene_.get(), viewport_, this);

  reportError = [this](const QString& title, const QString& message) {
    QMessageBox::critical(this, title, message);
  };
  confirmDiscardChanges = [this] {
    const auto answer = QMessageBox::question(
        this, tr("Unsaved changes"), tr("The document has unsaved changes. Save them first?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
  };

  createDocks();
  createActions();
  createMenus();
  createToolBar();
  createStatusBar();
  connectDocument();
  new HairTool(this);  // the hair dock and viewport handles (ui/hair)
  restoreLayout();
  updateTitle();
}

MainWindow::~MainWindow() {
  // The viewport (a child widget) must release the scene's GL resources
  // before the scene goes away.
  delete poseTool_;
  poseTool_ = nullptr;
  delete viewport_;
  viewport_ = nullptr;
}

// --- construction ----------------------------------------------------------------

void MainWindow::createDocks() {
  sceneTree_ = new SceneTreePanel(document_, this);
  treeDock_ = new QDockWidget(tr("Scene"), this);
  treeDock_->setObjectName("sceneDock");
  treeDock_->setWidget(sceneTree_);
  addDockWidget(Qt::LeftDockWidgetArea, treeDock_);

  properties_ = new PropertiesPanel(document_, this);
  propertiesDock_ = new QDockWidget(tr("Properties"), this);
  propertiesDock_->setObjectName("propertiesDock");
  propertiesDock_->setWidget(properties_);
  addDockWidget(Qt::RightDockWidgetArea, propertiesDock_);

  timeline_ = new TimelinePanel(document_, this);
  timelineDock_ = new QDockWidget(tr("Timeline"), this);
  timelineDock_->setObjectName("timelineDock");
  timelineDock_->setWidget(timeline_);
  timelineDock_->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetClosable);
  addDockWidget(Qt::BottomDockWidgetArea, timelineDock_);

  // Side docks run the full height; the timeline spans only the viewport.
  setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
  setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
}

void MainWindow::createActions() {
  newAction_ = new QAction(makeIcon(Icon::New), tr("&New"), this);
  newAction_->setShortcut(QKeySequence::New);
  newAction_->setStatusTip(tr("A new scene with the default mannequin"));
  connect(newAction_, &QAction::triggered, this, &MainWindow::newDocument);

  openAction_ = new QAction(makeIcon(Icon::Open), tr("&Open..."), this);
  openAction_->setShortcut(QKeySequence::Open);
  openAction_->setStatusTip(tr("Open a character (glTF, GLB, FBX, DAE), a motion (BVH) or a scene"));
  connect(openAction_, &QAction::triggered, this, &MainWindow::openWithDialog);

  saveAction_ = new QAction(makeIcon(Icon::Save), tr("&Save"), this);
  saveAction_->setShortcut(QKeySequence::Save);
  connect(saveAction_, &QAction::triggered, this, &MainWindow::save);

  saveAsAction_ = new QAction(tr("Save &As..."), this);
  saveAsAction_->setShortcut(QKeySequence::SaveAs);
  connect(saveAsAction_, &QAction::triggered, this, &MainWindow::saveAs);

  applyMotionAction_ = new QAction(tr("Apply &Motion..."), this);
  applyMotionAction_->setStatusTip(tr("Retarget a BVH motion onto the character, optionally with a bone-name map"));
  connect(applyMotionAction_, &QAction::triggered, this, &MainWindow::applyMotionWithDialog);

  exportAction_ = new QAction(tr("&Export Posed Mesh..."), this);
  exportAction_->setShortcut(QKeySequence(tr("Ctrl+E")));
  exportAction_->setStatusTip(tr("Write the posed meshes as OBJ or PLY"));
  connect(exportAction_, &QAction::triggered, this, &MainWindow::exportWithDialog);

  quitAction_ = new QAction(tr("&Quit"), this);
  quitAction_->setShortcut(QKeySequence::Quit);
  connect(quitAction_, &QAction::triggered, this, &QWidget::close);

  QUndoStack* stack = document_->undoStack();
  undoAction_ = stack->createUndoAction(this, tr("&Undo"));
  undoAction_->setShortcut(QKeySequence(tr("Ctrl+Z")));
  undoAction_->setIcon(makeIcon(Icon::Undo));
  redoAction_ = stack->createRedoAction(this, tr("&Redo"));
  redoAction_->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence(tr("Ctrl+Y"))});
  redoAction_->setIcon(makeIcon(Icon::Redo));

  frameAllAction_ = new QAction(makeIcon(Icon::FrameAll), tr("&Frame All"), this);
  frameAllAction_->setShortcut(QKeySequence(tr("Home")));
  frameAllAction_->setStatusTip(tr("Fit the character in the viewport (also F in the viewport)"));
  connect(frameAllAction_, &QAction::triggered, this, &MainWindow::frameAll);

  showSkeletonAction_ = new QAction(makeIcon(Icon::Skeleton), tr("Show &Skeleton"), this);
  showSkeletonAction_->setCheckable(true);
  showSkeletonAction_->setShortcut(QKeySequence(tr("Ctrl+K")));
  connect(showSkeletonAction_, &QAction::toggled, this, &MainWindow::setSkeletonVisible);

  showGridAction_ = new QAction(tr("Show &Grid"), this);
  showGridAction_->setCheckable(true);
  showGridAction_->setChecked(true);
  connect(showGridAction_, &QAction::toggled, this, [this](bool visible) {
    scene_->setGridVisible(visible);
    viewport_->requestRender();
  });

  resetBoneAction_ = new QAction(tr("Reset &Bone Rotation"), this);
  resetBoneAction_->setShortcut(QKeySequence(tr("Alt+R")));
  connect(resetBoneAction_, &QAction::triggered, this, [this] {
    const int bone = document_->selectedBone();
    if (bone >= 0 && document_->boneRotation(bone))
      document_->undoStack()->push(new SetBoneRotationCommand(document_, bone, std::nullopt));
  });
  resetPoseAction_ = new QAction(tr("Reset &Pose"), this);
  resetPoseAction_->setShortcut(QKeySequence(tr("Alt+Shift+R")));
  connect(resetPoseAction_, &QAction::triggered, this, [this] {
    if (!document_->poseEdits().empty())
      document_->undoStack()->push(new SetPoseEditsCommand(document_, PoseEdits{}, tr("Reset pose")));
  });
  deselectAction_ = new QAction(tr("&Deselect"), this);
  deselectAction_->setShortcut(QKeySequence(tr("Esc")));
  connect(deselectAction_, &QAction::triggered, this, [this] { document_->selectBone(-1); });

  // Frame steps, Blender-style, while the viewport has the focus.
  auto* previousFrame = new QAction(tr("Previous Frame"), viewport_);
  previousFrame->setShortcut(QKeySequence(Qt::Key_Left));
  previousFrame->setShortcutContext(Qt::WidgetShortcut);
  connect(previousFrame, &QAction::triggered, this, [this] { timeline_->stepFrames(-1); });
  auto* nextFrame = new QAction(tr("Next Frame"), viewport_);
  nextFrame->setShortcut(QKeySequence(Qt::Key_Right));
  nextFrame->setShortcutContext(Qt::WidgetShortcut);
  connect(nextFrame, &QAction::triggered, this, [this] { timeline_->stepFrames(1); });
  viewport_->addAction(previousFrame);
  viewport_->addAction(nextFrame);

  playAction_ = new QAction(makeIcon(Icon::Play), tr("&Play / Pause"), this);
  playAction_->setShortcut(QKeySequence(tr("Space")));
  connect(playAction_, &QAction::triggered, timeline_, &TimelinePanel::togglePlaying);
  connect(timeline_, &TimelinePanel::playingChanged, this, [this](bool playing) {
    playAction_->setIcon(makeIcon(playing ? Icon::Pause : Icon::Play));
  });
}

void MainWindow::createMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(newAction_);
  file->addAction(openAction_);
  recentMenu_ = file->addMenu(tr("Open &Recent"));
  file->addAction(applyMotionAction_);
  file->addSeparator();
  file->addAction(saveAction_);
  file->addAction(saveAsAction_);
  file->addAction(exportAction_);
  file->addSeparator();
  file->addAction(quitAction_);
  rebuildRecentMenu();

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  edit->addAction(undoAction_);
  edit->addAction(redoAction_);
  edit->addSeparator();
  edit->addAction(resetBoneAction_);
  edit->addAction(resetPoseAction_);
  edit->addAction(deselectAction_);

  viewMenu_ = menuBar()->addMenu(tr("&View"));
  viewMenu_->addAction(showSkeletonAction_);
  viewMenu_->addAction(showGridAction_);
  viewMenu_->addAction(frameAllAction_);
  viewMenu_->addSeparator();
  panelsMenu_ = viewMenu_->addMenu(tr("&Panels"));
  for (QDockWidget* dock : {treeDock_, propertiesDock_, timelineDock_}) panelsMenu_->addAction(dock->toggleViewAction());

  QMenu* animation = menuBar()->addMenu(tr("&Animation"));
  animation->addAction(playAction_);

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&Controls"), this, [this] {
    QMessageBox::information(this, tr("Viewport controls"),
                             tr("Orbit: left drag, middle drag or Alt+left drag\n"
                                "Pan: Shift+left or Shift+middle drag\n"
                                "Zoom: wheel, right drag or Ctrl+left drag\n"
                                "Select a bone: click it\n"
                                "Rotate the selected bone: drag a ring of the gizmo\n"
                                "Frame all: F in the viewport, or Home"));
  });
}

void MainWindow::createToolBar() {
  toolBar_ = addToolBar(tr("Main"));
  toolBar_->setObjectName("mainToolBar");
  toolBar_->setMovable(false);
  toolBar_->setIconSize(QSize(18, 18));
  toolBar_->addAction(newAction_);
  toolBar_->addAction(openAction_);
  toolBar_->addAction(saveAction_);
  toolBar_->addSeparator();
  toolBar_->addAction(undoAction_);
  toolBar_->addAction(redoAction_);
  toolBar_->addSeparator();
  toolBar_->addAction(frameAllAction_);
  toolBar_->addAction(showSkeletonAction_);
}

void MainWindow::createStatusBar() {
  selectionLabel_ = new QLabel(this);
  statsLabel_ = new QLabel(this);
  progress_ = new QProgressBar(this);
  progress_->setMaximumWidth(180);
  progress_->setMaximumHeight(16);
  progress_->setTextVisible(false);
  progress_->setVisible(false);
  statusBar()->addPermanentWidget(selectionLabel_);
  statusBar()->addPermanentWidget(statsLabel_);
  statusBar()->addPermanentWidget(progress_);
  statusBar()->showMessage(tr("Ready"));
}

void MainWindow::restoreLayout() {
  resizeDocks({treeDock_, propertiesDock_}, {270, 300}, Qt::Horizontal);
  resizeDocks({timelineDock_}, {timeline_->sizeHint().height()}, Qt::Vertical);
}

void MainWindow::addToolDock(QDockWidget* dock, Qt::DockWidgetArea area) {
  if (dock->objectName().isEmpty()) dock->setObjectName(dock->windowTitle());
  addDockWidget(area, dock);
  if (area == Qt::RightDockWidgetArea) {
    tabifyDockWidget(propertiesDock_, dock);
    propertiesDock_->raise();  // the selection's properties stay in front
  }
  panelsMenu_->addAction(dock->toggleViewAction());
}

void MainWindow::connectDocument() {
  connect(document_, &EditorDocument::characterReplaced, this, &MainWindow::onCharacterReplaced);
  connect(document_, &EditorDocument::poseChanged, this, &MainWindow::onPoseChanged);
  connect(document_, &EditorDocument::selectionChanged, this, &MainWindow::onSelectionChanged);
  connect(document_, &EditorDocument::viewSettingsChanged, this, [this] {
    const bool visible = document_->viewSettings().showSkeleton;
    showSkeletonAction_->setChecked(visible);
    scene_->setSkeletonVisible(visible);
    viewport_->requestRender();
  });
  connect(document_, &EditorDocument::modifiedChanged, this, &MainWindow::updateTitle);
  connect(document_, &EditorDocument::clipsChanged, this,
          [this] { statsLabel_->setText(summaryOf(document_->character())); });
  connect(document_, &EditorDocument::documentChanged, this, &MainWindow::documentChanged);
  connect(document_, &EditorDocument::timeChanged, this, &MainWindow::timeChanged);
  connect(poseTool_, &PoseTool::bonePicked, this, [this](int bone) {
    if (bone < 0) statusBar()->showMessage(tr("Nothing picked"), 2000);
  });
}

// --- document -> scene ---------------------------------------------------------------

void MainWindow::onCharacterReplaced() {
  scene_->setCharacter(document_->character());
  scene_->updatePose(document_->posed());
  scene_->setSkeletonVisible(document_->viewSettings().showSkeleton);
  scene_->setHighlightedBone(-1);
  restoreCamera();
  statsLabel_->setText(summaryOf(document_->character()));
  updateTitle();
  viewport_->requestRender();
}

void MainWindow::onPoseChanged() {
  scene_->updatePose(document_->posed());
  viewport_->requestRender();
}

void MainWindow::onSelectionChanged() {
  const int bone = document_->selectedBone();
  scene_->setHighlightedBone(bone);
  const Character& c = document_->character();
  if (bone >= 0)
    selectionLabel_->setText(tr("Bone: %1").arg(QString::fromStdString(c.skeleton.bone(bone).name)));
  else if (document_->selectedMesh() >= 0)
    selectionLabel_->setText(tr("Mesh: %1").arg(QString::fromStdString(c.meshes[document_->selectedMesh()].name)));
  else
    selectionLabel_->clear();
  viewport_->requestRender();
}

void MainWindow::updateTitle() {
  const QString name = document_->displayName().isEmpty() ? tr("untitled") : document_->displayName();
  setWindowTitle(QString::fromUtf8("Mannequin — %1[*]").arg(name));
  setWindowModified(document_->isModified());
}

void MainWindow::frameAll() {
  scene_->frameAll();
  viewport_->requestRender();
}

void MainWindow::setSkeletonVisible(bool visible) { document_->setSkeletonVisible(visible); }

void MainWindow::storeCamera() {
  ViewSettings& view = document_->sceneSections().view;
  view.hasCamera = true;
  view.cameraPosition = scene_->cameraPosition();
  view.cameraFocus = scene_->cameraFocus();
}

void MainWindow::restoreCamera() {
  const ViewSettings& view = document_->viewSettings();
  if (view.hasCamera) scene_->setCamera(view.cameraPosition, view.cameraFocus);
  else scene_->frameAll();
}

// --- files -----------------------------------------------------------------------------

bool MainWindow::maybeDiscardChanges() {
  return !document_->isModified() || !confirmDiscardChanges || confirmDiscardChanges();
}

void MainWindow::newDocument() {
  if (maybeDiscardChanges()) openFile("default");
}

void MainWindow::openWithDialog() {
  QSettings settings;
  const QString start = settings.value("lastDirectory").toString();
  const QString path = QFileDialog::getOpenFileName(this, tr("Open"), start, openFileFilter());
  if (path.isEmpty()) return;
  settings.setValue("lastDirectory", QFileInfo(path).absolutePath());
  if (isMotionFile(path) || maybeDiscardChanges()) openFile(path);
}

void MainWindow::setBusy(bool busy, const QString& message) {
  busy_ = busy;
  progress_->setRange(0, 0);  // busy indicator: the loaders report no fraction
  progress_->setVisible(busy);
  for (QAction* a : {newAction_, openAction_, applyMotionAction_, saveAction_, saveAsAction_, exportAction_})
    a->setEnabled(!busy);
  recentMenu_->setEnabled(!busy);
  if (busy) QApplication::setOverrideCursor(Qt::BusyCursor);
  else QApplication::restoreOverrideCursor();
  statusBar()->showMessage(message, busy ? 0 : 8000);
}

void MainWindow::showProgress(const QString& message, int percent) {
  if (percent < 0) progress_->setRange(0, 0);
  else {
    progress_->setRange(0, 100);
    progress_->setValue(percent);
  }
  progress_->setVisible(true);
  statusBar()->showMessage(message);
}

void MainWindow::hideProgress(const QString& message) {
  progress_->setVisible(busy_);
  if (message.isEmpty()) statusBar()->clearMessage();
  else statusBar()->showMessage(message, 8000);
}

void MainWindow::openFile(const QString& fileOrDefault) {
  if (busy_) return;
  if (isMotionFile(fileOrDefault)) {
    applyMotion(fileOrDefault);
    return;
  }
  const QString shown = fileOrDefault == "default" ? tr("the default mannequin") : QFileInfo(fileOrDefault).fileName();
  setBusy(true, tr("Opening %1...").arg(shown));
  auto clock = std::make_shared<QElapsedTimer>();
  clock->start();

  auto* watcher = new QFutureWatcher<Outcome<LoadedDocument>>(this);
  connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, fileOrDefault, clock] {
    Outcome<LoadedDocument> outcome = watcher->future().takeResult();
    watcher->deleteLater();
    setBusy(false, QString());
    if (auto* error = std::get_if<QString>(&outcome)) {
      statusBar()->showMessage(tr("Could not open %1").arg(fileOrDefault), 8000);
      if (reportError) reportError(tr("Could not open the file"), *error);
      emit loadFinished(false);
      return;
    }
    if (fileOrDefault != "default") addRecentFile(fileOrDefault);
    adoptLoaded(std::move(std::get<LoadedDocument>(outcome)), clock->elapsed() / 1000.0);
    emit loadFinished(true);
  });
  watcher->setFuture(QtConcurrent::run([fileOrDefault] {
    return runCatching<LoadedDocument>([&] { return loadDocument(fileOrDefault); });
  }));
}

void MainWindow::applyMotion(const QString& bvhPath, const QString& nameMapPath) {
  if (busy_) return;
  setBusy(true, tr("Applying %1...").arg(QFileInfo(bvhPath).fileName()));
  auto clock = std::make_shared<QElapsedTimer>();
  clock->start();
  auto* watcher = new QFutureWatcher<Outcome<Clip>>(this);
  connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, bvhPath, nameMapPath, clock] {
    Outcome<Clip> outcome = watcher->future().takeResult();
    watcher->deleteLater();
    setBusy(false, QString());
    if (auto* error = std::get_if<QString>(&outcome)) {
      statusBar()->showMessage(tr("Could not apply %1").arg(bvhPath), 8000);
      if (reportError) reportError(tr("Could not apply the motion"), *error);
      emit loadFinished(false);
      return;
    }
    Clip clip = std::move(std::get<Clip>(outcome));
    const QString name = QString::fromStdString(clip.name);
    // The document records the motion so a saved scene re-applies it.
    SceneDocument& scene = document_->sceneSections();
    scene.motionFile = QFileInfo(bvhPath).absoluteFilePath().toStdString();
    scene.motionMapFile = nameMapPath.isEmpty() ? std::string() : QFileInfo(nameMapPath).absoluteFilePath().toStdString();
    document_->addClip(std::move(clip));
    addRecentFile(bvhPath);
    statusBar()->showMessage(tr("Applied motion %1 (%2 s)").arg(name).arg(clock->elapsed() / 1000.0, 0, 'f', 2), 8000);
    emit loadFinished(true);
  });
  const Character target = document_->character();
  watcher->setFuture(QtConcurrent::run([bvhPath, nameMapPath, target] {
    return runCatching<Clip>([&] { return loadMotion(bvhPath, target, nameMapPath); });
  }));
}

void MainWindow::applyMotionWithDialog() {
  QSettings settings;
  const QString bvh = QFileDialog::getOpenFileName(this, tr("Apply Motion"), settings.value("lastDirectory").toString(),
                                                   motionFilter());
  if (bvh.isEmpty()) return;
  settings.setValue("lastDirectory", QFileInfo(bvh).absolutePath());
  const QString map = QFileDialog::getOpenFileName(
      this, tr("Bone-name map for %1 (cancel: match names as they are)").arg(QFileInfo(bvh).fileName()),
      QFileInfo(bvh).absolutePath(), nameMapFilter());
  applyMotion(bvh, map);
}

bool MainWindow::openFileNow(const QString& fileOrDefault, QString* error) {
  QElapsedTimer clock;
  clock.start();
  try {
    if (isMotionFile(fileOrDefault)) {
      Clip clip = loadMotion(fileOrDefault, document_->character());
      document_->sceneSections().motionFile = QFileInfo(fileOrDefault).absoluteFilePath().toStdString();
      document_->addClip(std::move(clip));
    } else {
      adoptLoaded(loadDocument(fileOrDefault), clock.elapsed() / 1000.0);
    }
    emit loadFinished(true);
    return true;
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    emit loadFinished(false);
    return false;
  }
}

void MainWindow::adoptLoaded(LoadedDocument loaded, double seconds) {
  // A new character shows its skeleton so it can be posed at once.
  if (loaded.documentPath.isEmpty()) loaded.scene.view.showSkeleton = true;
  const QString name = loaded.displayName;
  document_->replace(std::move(loaded));
  statusBar()->showMessage(tr("Opened %1: %2 (%3 s)")
                               .arg(name, summaryOf(document_->character()))
                               .arg(seconds, 0, 'f', 2),
                           8000);
}

bool MainWindow::saveDocument(const QString& path, QString* error) {
  storeCamera();
  SceneDocument scene = document_->sceneDocument();
  // Files the document refers to are stored relative to it.
  const QDir folder = QFileInfo(path).absoluteDir();
  const QDir oldFolder = document_->documentPath().isEmpty() ? QDir::current()
                                                              : QFileInfo(document_->documentPath()).absoluteDir();
  auto relative = [&](std::string& stored) {
    if (stored.empty() || stored == "default") return;
    const QString absolute = oldFolder.absoluteFilePath(QString::fromStdString(stored));
    stored = folder.relativeFilePath(absolute).toStdString();
  };
  relative(scene.character);
  relative(scene.motionFile);
  relative(scene.motionMapFile);
  try {
    saveSceneDocument(scene, path.toStdString());
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  document_->setDocumentPath(QFileInfo(path).absoluteFilePath());
  document_->markSaved();
  addRecentFile(path);
  updateTitle();
  statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
  return true;
}

bool MainWindow::save() {
  if (document_->documentPath().isEmpty()) return saveAs();
  QString error;
  if (saveDocument(document_->documentPath(), &error)) return true;
  if (reportError) reportError(tr("Could not save"), error);
  return false;
}

bool MainWindow::saveAs() {
  QString path = QFileDialog::getSaveFileName(this, tr("Save Scene"), document_->documentPath(), saveSceneFilter());
  if (path.isEmpty()) return false;
  if (QFileInfo(path).suffix().isEmpty()) path += ".mqscene";
  QString error;
  if (saveDocument(path, &error)) return true;
  if (reportError) reportError(tr("Could not save"), error);
  return false;
}

bool MainWindow::exportPosedMesh(const QString& path, QString* error) {
  const Character& character = document_->character();
  std::vector<const Mesh*> meshes;
  for (const Mesh& m : character.meshes) meshes.push_back(&m);
  try {
    mq::exportPosedMesh(meshes, document_->posed().meshes(), path.toStdString());
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  statusBar()->showMessage(tr("Exported %1").arg(path), 5000);
  return true;
}

void MainWindow::exportWithDialog() {
  QString filter;
  QString path = QFileDialog::getSaveFileName(this, tr("Export Posed Mesh"), QString(), exportMeshFilter(), &filter);
  if (path.isEmpty()) return;
  if (QFileInfo(path).suffix().isEmpty()) path += filter.contains("ply") ? ".ply" : ".obj";
  QString error;
  if (!exportPosedMesh(path, &error) && reportError) reportError(tr("Could not export"), error);
}

void MainWindow::addRecentFile(const QString& path) {
  QSettings settings;
  QStringList files = settings.value(kRecentFilesKey).toStringList();
  const QString absolute = QFileInfo(path).absoluteFilePath();
  files.removeAll(absolute);
  files.prepend(absolute);
  while (files.size() > kMaxRecentFiles) files.removeLast();
  settings.setValue(kRecentFilesKey, files);
  rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
  recentMenu_->clear();
  const QStringList files = QSettings().value(kRecentFilesKey).toStringList();
  for (const QString& file : files) {
    QAction* action = recentMenu_->addAction(QFileInfo(file).fileName());
    action->setToolTip(file);
    connect(action, &QAction::triggered, this, [this, file] {
      if (isMotionFile(file) || maybeDiscardChanges()) openFile(file);
    });
  }
  recentMenu_->setEnabled(!files.isEmpty() && !busy_);
}

// --- window events ------------------------------------------------------------------

void MainWindow::closeEvent(QCloseEvent* event) {
  if (busy_ || !maybeDiscardChanges()) {
    event->ignore();
    return;
  }
  QSettings settings;
  settings.setValue("window/geometry", saveGeometry());
  settings.setValue("window/state", saveState());
  event->accept();
}

void MainWindow::restoreWindowState() {
  QSettings settings;
  restoreGeometry(settings.value("window/geometry").toByteArray());
  restoreState(settings.value("window/state").toByteArray());
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  const QMimeData* mime = event->mimeData();
  if (!mime->hasUrls()) return;
  for (const QUrl& url : mime->urls())
    if (url.isLocalFile() && isOpenableFile(url.toLocalFile())) {
      event->acceptProposedAction();
      return;
    }
}

void MainWindow::dropEvent(QDropEvent* event) {
  for (const QUrl& url : event->mimeData()->urls()) {
    const QString path = url.toLocalFile();
    if (!isOpenableFile(path)) continue;
    event->acceptProposedAction();
    if (isMotionFile(path) || maybeDiscardChanges()) openFile(path);
    return;
  }
}

}  // namespace mq::ui
