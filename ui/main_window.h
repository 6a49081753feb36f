#pragma once
// The editor's main window: the 3D viewport in the centre, the scene tree on
// the left, the properties of the selection on the right, the timeline at the
// bottom, and a status bar with progress for long work. Files open on a
// worker thread; a failed open reports the error and leaves the current
// document untouched.
//
// Extension points for other tools (hair, garments): addToolDock() for their
// panels, document() and its signals (documentChanged, poseChanged,
// timeChanged), sceneView() to add actors, viewport()->requestRender().

#include <functional>
#include <memory>
#include <optional>

#include <glm/vec3.hpp>

#include <QMainWindow>
#include <QStringList>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QProgressBar;
class QToolBar;

namespace mq::render {
class SceneView;
}

namespace mq::ui {

class Autosave;
class EditorDocument;
struct ExportAnimatedChoice;
struct ExportAnimatedSources;
class PoseTool;
struct RecoveryCopy;
class PropertiesPanel;
class SceneTreePanel;
class TimelinePanel;
class VtkViewportWidget;
struct LoadedDocument;
struct LoadedMotion;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  EditorDocument* document() const { return document_; }
  VtkViewportWidget* viewport() const { return viewport_; }
  render::SceneView* sceneView() const { return scene_.get(); }
  PoseTool* poseTool() const { return poseTool_; }
  SceneTreePanel* sceneTree() const { return sceneTree_; }
  PropertiesPanel* properties() const { return properties_; }
  TimelinePanel* timeline() const { return timeline_; }
  // View > Follow Character: the camera travels with the character's root.
  QAction* followAction() const { return followAction_; }
  QAction* showWeightsAction() const { return showWeightsAction_; }
  QAction* showConesAction() const { return showConesAction_; }

  // Adds a tool's dock and lists it in the View menu: on the right, tabbed
  // with the properties (the default); at the bottom, under the timeline.
  void addToolDock(QDockWidget* dock, Qt::DockWidgetArea area = Qt::RightDockWidgetArea);

  // Opens "default", a character, a scene document, or a BVH motion (applied
  // to the current character) on a worker thread; emits loadFinished.
  void openFile(const QString& fileOrDefault);
  // Applies a BVH motion to the current character as a new clip (worker
  // thread, one undo step), pairing joints with bones through `nameMapPath`
  // first when given; `inPlace` drops the root's horizontal travel. The
  // status bar says how many bones matched and which did not.
  void applyMotion(const QString& bvhPath, const QString& nameMapPath = QString(), bool inPlace = false);
  // File > Apply Motion: the dialog that shows both skeletons and the
  // matches before applying (window-modal, returns at once).
  void applyMotionWithDialog();
  bool isBusy() const { return busy_; }
  // Same, on the calling thread (tests, scripts). False and `error` on failure.
  bool openFileNow(const QString& fileOrDefault, QString* error = nullptr);
  bool saveDocument(const QString& path, QString* error = nullptr);
  // Recovery copies of the modified document in `folder` every `seconds`
  // (see ui/document/autosave.h); a save or a clean close removes them.
  void enableAutosave(const QString& folder, int seconds);
  Autosave* autosave() const { return autosave_; }
  // When a recovery copy left by a crashed editor exists, asks whether to
  // restore it (confirmRecovery) and opens it as the document it stood for,
  // with its changes unsaved. Returns whether a restore started.
  bool offerRecovery();
  // Where Save As starts: the document itself, unless it is one of the
  // shipped examples (resources/scenes), lives in a folder the user cannot
  // write, or is not a scene document yet; then `documentsDir`.
  static QString saveAsProposal(const QString& documentPath, const QString& characterName, const QString& documentsDir);
  bool exportPosedMesh(const QString& path, QString* error = nullptr);
  // The character rigged to glTF/GLB (core/io/rigged_export.h): with a
  // garment or hair bake, one take of the baked frames with the garments and
  // the hair guides as morph-target surfaces; without, every clip at 30 fps.
  // Returns what was written (for the status bar), empty with `error` on failure.
  QString exportAnimatedGltf(const QString& path, QString* error = nullptr);
  // The same as the File > Export Animated glTF dialog chose it: every clip,
  // or the take with the chosen bakes, and point caches beside the glTF.
  QString exportAnimated(const ExportAnimatedChoice& choice, QString* error = nullptr);
  // What the dialog offers: the clips and the bakes there are.
  ExportAnimatedSources exportAnimatedSources() const;
  void frameAll();
  void setSkeletonVisible(bool visible);
  // Dock layout and window size from the last session (QSettings); the
  // layout is saved when the window closes.
  void restoreWindowState();

  // Progress of long work in the status bar (bakes, simulations): percent
  // 0..100, or -1 for a busy indicator. Tools call hideProgress when done.
  void showProgress(const QString& message, int percent = -1);
  void hideProgress(const QString& message = QString());

  // How errors and questions reach the user (message boxes by default;
  // tests replace them).
  std::function<void(const QString& title, const QString& message)> reportError;
  std::function<bool()> confirmDiscardChanges;
  std::function<bool(const RecoveryCopy& copy)> confirmRecovery;

 signals:
  void loadFinished(bool ok);
  // The document was written to `path` (tools save what lives beside it).
  void documentSaved(const QString& path);
  // A load or motion is being read on a worker (true) or has come back (false).
  void busyChanged(bool busy);
  // Relayed from the document for tools that only know the window.
  void documentChanged();
  void timeChanged(float seconds);

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void createDocks();
  void createActions();
  void createMenus();
  void createToolBar();
  void createStatusBar();
  void connectDocument();
  void restoreLayout();

  // File menu
  void newDocument();
  void openWithDialog();
  bool save();
  bool saveAs();
  void exportWithDialog();
  void exportAnimatedWithDialog();
  bool maybeDiscardChanges();
  // The document as a scene file at `path`: referenced files relative to
  // it, or absolute (recovery copies live apart from the document).
  bool writeSceneTo(const QString& path, bool absolutePaths, QString* error);
  void adoptLoaded(LoadedDocument loaded, double seconds);
  // One undo step: the motion's clip made current and recorded in the scene.
  void adoptMotion(LoadedMotion motion, double seconds);
  void addRecentFile(const QString& path);
  void rebuildRecentMenu();
  void setBusy(bool busy, const QString& message);

  // Document -> scene sync
  void onCharacterReplaced();
  // Shows the document's character (its skeleton changed, or it was replaced).
  void showCharacter();
  void onPoseChanged();
  void followCharacter();
  // The root bone's position projected on the ground (y = 0); none without bones.
  std::optional<glm::vec3> rootOnGround() const;
  // Shades the scene with the document's surface look and ticks its menu entry.
  void applyLook();
  // The selected bone's weights as a heat map on the skin, when the view asks.
  void showWeights();
  // The section cones around the limbs, when the view asks (fitted on showing).
  void showCones();
  void onSelectionChanged();
  void updateTitle();
  void storeCamera();
  void restoreCamera();

  EditorDocument* document_;
  std::unique_ptr<render::SceneView> scene_;
  VtkViewportWidget* viewport_;
  PoseTool* poseTool_ = nullptr;
  SceneTreePanel* sceneTree_ = nullptr;
  PropertiesPanel* properties_ = nullptr;
  TimelinePanel* timeline_ = nullptr;
  QDockWidget* treeDock_ = nullptr;
  QDockWidget* propertiesDock_ = nullptr;
  QDockWidget* timelineDock_ = nullptr;
  QDockWidget* historyDock_ = nullptr;

  QAction* newAction_ = nullptr;
  QAction* openAction_ = nullptr;
  Autosave* autosave_ = nullptr;
  QAction* saveAction_ = nullptr;
  QAction* saveAsAction_ = nullptr;
  QAction* exportAction_ = nullptr;
  QAction* exportAnimatedAction_ = nullptr;
  QAction* applyMotionAction_ = nullptr;
  QAction* quitAction_ = nullptr;
  QAction* undoAction_ = nullptr;
  QAction* redoAction_ = nullptr;
  QAction* frameAllAction_ = nullptr;
  QAction* showSkeletonAction_ = nullptr;
  QAction* showWeightsAction_ = nullptr;
  bool weightsShown_ = false;  // the scene shows a weight heat map
  QAction* showConesAction_ = nullptr;
  bool conesShown_ = false;
  QAction* showGridAction_ = nullptr;
  QAction* followAction_ = nullptr;
  QAction* resetBoneAction_ = nullptr;
  QAction* resetPoseAction_ = nullptr;
  QAction* deselectAction_ = nullptr;
  QAction* playAction_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  QMenu* viewMenu_ = nullptr;
  QMenu* lookMenu_ = nullptr;  // surface look: auto, skin, mannequin, plain
  QMenu* panelsMenu_ = nullptr;
  QToolBar* toolBar_ = nullptr;

  QProgressBar* progress_ = nullptr;
  QLabel* selectionLabel_ = nullptr;
  QLabel* statsLabel_ = nullptr;
  bool busy_ = false;
  std::optional<glm::vec3> followedRoot_;  // where the root was when the camera last followed
};

}  // namespace mq::ui
