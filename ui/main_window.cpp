#include "ui/main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QLayout>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QUndoStack>
#include <QUndoView>

#include "render/scene_view.h"
#include "ui/document/editor_document.h"
#include "ui/document/pose_commands.h"
#include "ui/garment/garment_tool.h"
#include "ui/hair/hair_tool.h"
#include "ui/icons.h"
#include "ui/panels/properties_panel.h"
#include "ui/panels/scene_tree_panel.h"
#include "ui/panels/timeline_panel.h"
#include "ui/viewport/pose_tool.h"
#include "ui/viewport/vtk_viewport_widget.h"

namespace mq::ui {

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

  reportError = [this](const QString& title, const QString& message) { QMessageBox::critical(this, title, message); };
  confirmDiscardChanges = [this] {
    const auto answer =
        QMessageBox::question(this, tr("Unsaved changes"), tr("The document has unsaved changes. Save them first?"),
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
  new HairTool(this);     // the hair dock and viewport handles (ui/hair)
  new GarmentTool(this);  // the garments dock, pins and cloth (ui/garment)
  restoreLayout();
  updateTitle();
}

MainWindow::~MainWindow() {
  // Tools (the pose tool, hair, ...) hold actors and renderer pointers of the
  // scene, and the viewport (a child widget) must release the scene's GL
  // resources: all of them go before the scene does.
  poseTool_ = nullptr;
  const QObjectList children = this->children();
  for (QObject* child : children)
    if (!child->isWidgetType() && !qobject_cast<QLayout*>(child) && child != document_) delete child;
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

  // The undo history, below the scene tree: click an entry to go back to it.
  auto* history = new QUndoView(document_->undoStack(), this);
  history->setEmptyLabel(tr("<opened>"));
  historyDock_ = new QDockWidget(tr("History"), this);
  historyDock_->setObjectName("historyDock");
  historyDock_->setWidget(history);
  splitDockWidget(treeDock_, historyDock_, Qt::Vertical);

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

  exportAnimatedAction_ = new QAction(tr("Export &Animated glTF..."), this);
  exportAnimatedAction_->setShortcut(QKeySequence(tr("Ctrl+Shift+E")));
  exportAnimatedAction_->setStatusTip(
      tr("Write the character rigged with its clips, or with the garment and hair bakes, as glTF for other programs"));
  connect(exportAnimatedAction_, &QAction::triggered, this, &MainWindow::exportAnimatedWithDialog);

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
  showWeightsAction_ = new QAction(tr("Show Skin &Weights"), this);
  showWeightsAction_->setCheckable(true);
  showWeightsAction_->setToolTip(tr("Colour the skin by the selected bone's weights: blue none, red all"));
  connect(showWeightsAction_, &QAction::toggled, this, [this](bool on) { document_->setWeightsVisible(on); });
  showConesAction_ = new QAction(tr("Show Section &Cones"), this);
  showConesAction_->setCheckable(true);
  showConesAction_->setToolTip(
      tr("Draw the survey's section cones around the limbs: the memorised sections the "
         "cones skinning keeps, following the pose"));
  connect(showConesAction_, &QAction::toggled, this, [this](bool on) { document_->setConesVisible(on); });

  showGridAction_ = new QAction(tr("Show &Grid"), this);
  showGridAction_->setCheckable(true);
  showGridAction_->setChecked(true);
  connect(showGridAction_, &QAction::toggled, this, [this](bool visible) {
    scene_->setGridVisible(visible);
    viewport_->requestRender();
  });

  followAction_ = new QAction(tr("F&ollow Character"), this);
  followAction_->setCheckable(true);
  followAction_->setStatusTip(tr("Move the camera with the character when a motion carries it away"));
  connect(followAction_, &QAction::toggled, this,
          [this](bool on) { followedRoot_ = on ? rootOnGround() : std::nullopt; });

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
  connect(timeline_, &TimelinePanel::playingChanged, this,
          [this](bool playing) { playAction_->setIcon(makeIcon(playing ? Icon::Pause : Icon::Play)); });
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
  file->addAction(exportAnimatedAction_);
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
  viewMenu_->addAction(showWeightsAction_);
  viewMenu_->addAction(showConesAction_);
  viewMenu_->addAction(showGridAction_);
  viewMenu_->addAction(frameAllAction_);
  viewMenu_->addAction(followAction_);
  lookMenu_ = viewMenu_->addMenu(tr("Surface &Look"));
  auto* looks = new QActionGroup(this);
  for (const auto& [mode, label, tip] :
       {std::tuple{render::LookMode::Auto, tr("&Auto"),
                   tr("Each surface by its file's material; the mannequin in wood")},
        std::tuple{render::LookMode::Skin, tr("&Skin"), tr("Every surface shaded as skin")},
        std::tuple{render::LookMode::Mannequin, tr("&Mannequin"), tr("Every surface in the mannequin's wood")},
        std::tuple{render::LookMode::Plain, tr("&Plain"), tr("Every surface in its flat colour, no texture")}}) {
    QAction* action = lookMenu_->addAction(label);
    action->setCheckable(true);
    action->setToolTip(tip);
    action->setData(QString(render::lookModeName(mode)));
    looks->addAction(action);
    connect(action, &QAction::triggered, this, [this, mode] { document_->setLook(render::lookModeName(mode)); });
  }
  viewMenu_->addSeparator();
  panelsMenu_ = viewMenu_->addMenu(tr("&Panels"));
  for (QDockWidget* dock : {treeDock_, historyDock_, propertiesDock_, timelineDock_})
    panelsMenu_->addAction(dock->toggleViewAction());

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
                                "Frame all: F in the viewport, or Home\n"
                                "Select garment vertices: Garments > Select vertices, then drag a\n"
                                "rectangle (Shift adds, Ctrl removes); Ctrl+Alt+drag at any time"));
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
  resizeDocks({treeDock_, historyDock_}, {620, 200}, Qt::Vertical);
}

void MainWindow::addToolDock(QDockWidget* dock, Qt::DockWidgetArea area) {
  if (dock->objectName().isEmpty()) dock->setObjectName(dock->windowTitle());
  addDockWidget(area, dock);
  if (area == Qt::RightDockWidgetArea) {
    tabifyDockWidget(propertiesDock_, dock);
    propertiesDock_->raise();  // the selection's properties stay in front
  } else if (area == Qt::BottomDockWidgetArea) {
    splitDockWidget(timelineDock_, dock, Qt::Vertical);  // under the timeline, the viewport's full width
  }
  panelsMenu_->addAction(dock->toggleViewAction());
}

void MainWindow::connectDocument() {
  connect(document_, &EditorDocument::characterReplaced, this, &MainWindow::onCharacterReplaced);
  connect(document_, &EditorDocument::skeletonChanged, this, &MainWindow::showCharacter);
  connect(document_, &EditorDocument::poseChanged, this, &MainWindow::onPoseChanged);
  connect(document_, &EditorDocument::selectionChanged, this, &MainWindow::onSelectionChanged);
  connect(document_, &EditorDocument::weightsChanged, this, [this] {
    showWeights();
    viewport_->requestRender();
  });
  connect(document_, &EditorDocument::viewSettingsChanged, this, [this] {
    const bool visible = document_->viewSettings().showSkeleton;
    showSkeletonAction_->setChecked(visible);
    scene_->setSkeletonVisible(visible);
    showWeightsAction_->setChecked(document_->viewSettings().showWeights);
    showConesAction_->setChecked(document_->viewSettings().showCones);
    applyLook();
    showWeights();
    showCones();
    viewport_->requestRender();
  });
  connect(document_, &EditorDocument::materialChanged, this, [this](int index) {
    scene_->setMaterial(index, document_->character().materials[index]);
    viewport_->requestRender();
  });
  connect(document_, &EditorDocument::modifiedChanged, this, &MainWindow::updateTitle);
  connect(document_, &EditorDocument::clipsChanged, this, [this] { statsLabel_->setText(document_->summary()); });
  connect(document_, &EditorDocument::documentChanged, this, &MainWindow::documentChanged);
  connect(document_, &EditorDocument::timeChanged, this, &MainWindow::timeChanged);
  connect(poseTool_, &PoseTool::bonePicked, this, [this](int bone) {
    if (bone < 0) statusBar()->showMessage(tr("Nothing picked"), 2000);
  });
}

// --- document -> scene ---------------------------------------------------------------

void MainWindow::onCharacterReplaced() {
  showCharacter();
  restoreCamera();
  followedRoot_ = followAction_->isChecked() ? rootOnGround() : std::nullopt;  // follow from here
  viewport_->requestRender();
}

void MainWindow::showCharacter() {
  scene_->setCharacter(document_->character());
  applyLook();
  scene_->updatePose(document_->posed());
  scene_->setSkeletonVisible(document_->viewSettings().showSkeleton);
  scene_->setHighlightedBone(-1);
  showWeights();
  conesShown_ = false;  // setCharacter dropped them
  showCones();
  statsLabel_->setText(document_->summary());
  updateTitle();
  viewport_->requestRender();
}

void MainWindow::applyLook() {
  render::LookMode mode = render::LookMode::Auto;
  render::parseLookMode(document_->viewSettings().look, mode);
  if (mode != scene_->lookMode()) scene_->setLookMode(mode);
  for (QAction* action : lookMenu_->actions())
    action->setChecked(action->data().toString().toStdString() == render::lookModeName(mode));
}

void MainWindow::onPoseChanged() {
  scene_->updatePose(document_->posed());
  followCharacter();
  viewport_->requestRender();
}

// The camera keeps its view of the root bone's place on the ground: it
// follows the travel, not the up-and-down of the steps.
void MainWindow::followCharacter() {
  if (!followAction_->isChecked()) return;
  const std::optional<glm::vec3> root = rootOnGround();
  if (root && followedRoot_) {
    const glm::vec3 shift = *root - *followedRoot_;
    scene_->setCamera(scene_->cameraPosition() + shift, scene_->cameraFocus() + shift);
  }
  followedRoot_ = root;
}

std::optional<glm::vec3> MainWindow::rootOnGround() const {
  const std::vector<glm::mat4>& worldFromBone = document_->posed().worldFromBone();
  if (worldFromBone.empty()) return std::nullopt;
  return glm::vec3(worldFromBone[0][3].x, 0.0f, worldFromBone[0][3].z);
}

void MainWindow::onSelectionChanged() {
  const int bone = document_->selectedBone();
  scene_->setHighlightedBone(bone);
  showWeights();
  const Character& c = document_->character();
  if (bone >= 0)
    selectionLabel_->setText(tr("Bone: %1").arg(QString::fromStdString(c.skeleton.bone(bone).name)));
  else if (document_->selectedMesh() >= 0)
    selectionLabel_->setText(tr("Mesh: %1").arg(QString::fromStdString(c.meshes[document_->selectedMesh()].name)));
  else
    selectionLabel_->clear();
  viewport_->requestRender();
}

void MainWindow::showWeights() {
  const bool on = document_->viewSettings().showWeights;
  if (!on && !weightsShown_) return;
  weightsShown_ = on;
  scene_->setVertexHeat(on ? boneWeights(document_->character(), document_->selectedBone())
                           : std::vector<std::vector<float>>());
}

void MainWindow::showCones() {
  const bool on = document_->viewSettings().showCones;
  if (on == conesShown_) return;
  conesShown_ = on;
  if (!on) {
    scene_->hideSectionCones();
    return;
  }
  QApplication::setOverrideCursor(Qt::WaitCursor);  // fitting: about half a second on the mannequin
  scene_->showSectionCones(document_->character());
  QApplication::restoreOverrideCursor();
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
  if (view.hasCamera)
    scene_->setCamera(view.cameraPosition, view.cameraFocus);
  else
    scene_->frameAll();
}

}  // namespace mq::ui
