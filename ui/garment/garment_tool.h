#pragma once
// The editor's garment tool: the document's garments (built-in T-shirt,
// skirt, trousers sized from the character), their fabric and pins, and the
// cloth settings, edited through undo commands (GarmentEditCommand) and
// stored in the scene document's "garments" and "cloth" sections.
//
// The viewport shows each garment with the cloth shader (render::ClothActor):
// as placed around the rest body, as the live simulation has it, or the baked
// frame of the current time. Simulate steps every garment's GarmentSimulation
// on a worker thread, one step in flight at a time, with the body where the
// timeline has it, so the editor stays responsive while the clip plays. Bake
// simulates the whole clip on a worker thread behind a progress dialog with
// Cancel; the timeline then scrubs the baked frames. Any edit restarts the
// simulation and drops the bake.
//
// Pins: in vertex-select mode a rubber-band drag in the viewport selects the
// current garment's vertices that face the camera (Shift adds, Ctrl removes);
// Pin selected / Unpin edit the pins. Pinned vertices are drawn as dots, and
// the stretch overlay colours the garment by GarmentSimulation::vertexStretch.
// Pins survive a rebuild of the mesh (a measurement or the particle
// distance): they are carried to the nearest vertex of the same panel
// (core/garment/pin_remap.h).
//
// Colliders: the document's primitive colliders (sphere, capsule, plane),
// listed, added, edited and removed as undoable edits like the garments,
// drawn as translucent actors (render::ColliderActors); every simulation and
// bake collides with them. In the viewport a click selects a collider and
// its move gizmo drags it (ColliderDragTool); a running simulation goes on
// with a collider that moves (only the colliders changed: no restart). The
// "cloth" section's sheet, when the document has one, is shown and
// simulated with the garments (a scene may be a sheet and colliders with no
// character at all). With no character there is no clip to follow: Bake
// then bakes the cloth section's bake_frames at its fps from the placed
// sheet, and the document gets a time axis of that length
// (EditorDocument::setNoClipDuration) on which the timeline scrubs the bake.
//
// Sewing is slow, so each garment's sewn state (and its state draped onto a
// bake's first frame) is kept, keyed on everything it depends on (garment,
// fabric, pins, solver settings, fps, colliders, the body): Simulate and Bake
// start from there while those are unchanged.

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QObject>
#include <QPoint>
#include <QRect>
#include <QString>

#include <glm/glm.hpp>

#include "core/io/baked_surface.h"
#include "sim/cloth/collision/primitive_collider.h"
#include "sim/garment/garment_simulation.h"
#include "ui/garment/garment_scene.h"
#include "ui/garment/held_drape.h"
#include "ui/jobs/long_job.h"

class QDockWidget;
class QMouseEvent;
class QRubberBand;

namespace mq {
struct GarmentMesh;
}

namespace mq::render {
class ColliderActors;
}

namespace mq::ui {

class ColliderDragTool;
class GarmentPanel;
class PatternView;
class MainWindow;

class GarmentTool : public QObject {
  Q_OBJECT

 public:
  explicit GarmentTool(MainWindow* window);
  ~GarmentTool() override;

  const GarmentScene& scene() const { return scene_; }
  int garmentCount() const { return int(scene_.garments.size()); }
  int currentGarment() const { return current_; }  // -1: none
  void setCurrentGarment(int index);
  // The meshed garment (unwelded GarmentMesh order), null when out of range.
  const GarmentMesh* garmentMesh(int garment) const;
  // What the viewport shows for a garment now (3 floats per vertex) and its stretch.
  const std::vector<float>& shownPositions(int garment) const;
  const std::vector<float>& shownStretch(int garment) const;
  QString lastError() const { return lastError_; }

  // Undoable edits. mergeKey: steps with the same non-zero key merge.
  void edit(const GarmentScene& after, const QString& text, int mergeKey = 0);
  void addGarment(const std::string& type);  // "tshirt", "skirt", "trousers"
  void removeGarment(int index);
  void setMeasurement(int garment, const std::string& name, float value, int mergeKey = 0);
  // The cloth resolution: the target edge length of the garment's mesh (metres).
  void setParticleDistance(int garment, float metres, int mergeKey = 0);
  // Layering: the garment is worn over those of lower layers (and those
  // before it in the list on its own layer); Simulate and Bake step them inner to outer.
  void setLayer(int garment, int layer);
  void setFabricPreset(int garment, const std::string& preset);
  void setFabric(int garment, const Fabric& fabric, int mergeKey = 0);
  void setIntegrator(cloth::IntegratorKind integrator);
  void setSelfCollisions(bool on);
  // Simulation and bake frames per second (the "cloth" section's fps).
  void setClothFps(float fps, int mergeKey = 0);
  // With no clip to follow (bakesWithoutClip): how many frames Bake makes (the section's bake_frames).
  void setBakeFrames(int frames, int mergeKey = 0);
  // The document has no character, so no clip: Bake bakes bake_frames from the placed cloth.
  bool bakesWithoutClip() const { return restBody_.empty(); }
  void setPinsFollowBody(int garment, bool followBody);
  void pinSelected();
  void unpinSelected();
  void clearPins();
  // Colliders (the document's "colliders" section).
  int colliderCount() const { return int(scene_.cloth.colliders.size()); }
  int currentCollider() const { return currentCollider_; }  // -1: none
  // -1 clears the selection (it stays clear through later edits until a collider is chosen).
  void setCurrentCollider(int index);
  // A collider of that shape placed near the character (or the sheet).
  void addCollider(cloth::PrimitiveCollider::Shape shape);
  // False (lastError says why) for a zero normal, a radius <= 0 or a value that is not finite.
  // text: the undo step's name ("Edit <shape> collider" when empty).
  bool setCollider(int index, const cloth::PrimitiveCollider& collider, int mergeKey = 0,
                   const QString& text = QString());
  void removeCollider(int index);
  void setCollidersVisible(bool visible);
  bool collidersVisible() const { return collidersVisible_; }
  const render::ColliderActors& colliderActors() const { return *colliderActors_; }
  // The collider under display position (x, y), -1 for none or when the
  // character or a garment (or the sheet) is in front of it there.
  int pickCollider(int x, int y) const;
  ColliderDragTool* colliderDragTool() const { return colliderDrag_; }

  // The "cloth" section's sheet as shown (empty without a sheet).
  bool hasSheet() const { return sheet_ != nullptr; }
  const std::vector<float>& shownSheetPositions() const;

  // Replaces the state without undo (the commands call this).
  void applyScene(const GarmentScene& scene);

  // Vertex selection on the current garment.
  enum class SelectOp { Replace, Add, Remove };
  const std::vector<uint32_t>& selectedVertices() const { return selection_; }
  void setSelectedVertices(std::vector<uint32_t> vertices);
  // Selects the current garment's camera-facing vertices inside `rect` (viewport widget coordinates).
  void selectInRect(const QRect& rect, SelectOp op);
  void setSelectMode(bool on);
  bool selectMode() const { return selectMode_; }
  // Widget coordinates of a world point in the viewport (for tests and the rubber band).
  QPointF toWidget(const glm::vec3& world) const;

  // Live simulation.
  void setSimulating(bool on);
  // Back to the placed panels: the drapes are dropped (and a bake with
  // them), and the next Simulate or Bake sews the garments anew.
  void resetDrapes();
  bool simulating() const { return simulating_; }
  int simulatedSteps() const { return steps_; }
  // Steps (cloth frames) simulated per second of wall time lately; 0 before
  // there are a few. Against the cloth fps: whether live simulation keeps up
  // with the clip played in real time.
  double simulatedFramesPerSecond() const { return framesPerSecond_; }
  // "Sewing", "Draping", "Following the clip", "Simulating" (no character) or "" while not simulating.
  QString simulationPhase() const;
  // Blocks until the step in flight (if any) is done.
  void waitForStep();

  // Bake: simulates the current clip (or its part from `from` to `to`
  // seconds, when given), or with no character bake_frames from the placed
  // cloth; false when cancelled or impossible (lastError says why).
  // With `askIfLong`, a bake estimated at over a minute (ui/jobs/long_job.h)
  // first asks the user; refused, it does not start (false, lastError()).
  bool bake(float from = -1.0f, float to = -1.0f, bool askIfLong = false);
  // The seconds the last bake that got as far as its estimate was expected to take.
  double lastBakeEstimate() const { return lastBakeEstimate_; }
  void cancelBake() { cancelBake_ = true; }
  bool baking() const { return baking_; }
  bool hasBake() const { return bake_ != nullptr; }
  // Why the last bake was dropped by an edit ("fabric changed"); empty while
  // a bake holds, after a new bake, or when there was none.
  QString bakeOutOfDate() const { return bakeOutOfDate_; }
  int bakedFrameCount() const;
  void clearBake();
  // Writes the bake as OBJ sequences into `dir` (created if missing): one file
  // per frame per garment, <garment stem>_0001.obj ..., and sheet_0001.obj ...
  // for the sheet; false (lastError names the file and the problem) when it
  // cannot, or when there is no bake.
  // pointCache: one Point Cache 2 file per garment instead (<stem>.pc2 and
  // the mesh it deforms, <stem>.obj: BakedCloth::exportPointCache).
  bool exportBake(const QString& dir, bool pointCache = false);
  // The garment's sewing pattern as SVG at 1:1 (core/garment/pattern_svg.h),
  // with the cutting line seamAllowance metres outside when > 0; false
  // (lastError says why) when it cannot be written.
  bool exportPattern(int garment, const QString& path, float seamAllowance = 0.0f);
  // A DXF pattern's panels and seams as a new garment (one undo step);
  // false with lastError() naming the file and the problem when it cannot be read.
  bool importPattern(const QString& path);
  // The bake for an animated glTF: its clip (-1 none), first frame's time,
  // fps and frame count, and one surface per garment (the sheet last),
  // coloured by fabric. Null without a bake.
  struct BakeForExport {
    int clip = -1;
    float start = 0.0f, fps = 30.0f;
    int frames = 0;
    std::vector<BakedSurface> surfaces;
  };
  std::optional<BakeForExport> bakeForExport() const;
  // How often sewing ran from the placed panels (Simulate or Bake), and how
  // often a kept sewn or draped state was used instead.
  int sewingRuns() const { return sewingRuns_; }
  int reusedSewings() const { return reusedSewings_; }
  // How often Simulate started from the drape on screen (after an edit, an undo or a stop).
  int warmStarts() const { return warmStarts_; }
  // Wall time of the last bake that finished, seconds.
  double lastBakeSeconds() const { return lastBakeSeconds_; }
  // Of which the worker spent: 0 sewing, 1 draping onto the first frame, 2 simulating the frames.
  double lastBakePhaseSeconds(int phase) const { return lastBakePhases_[phase]; }

  // Display
  void setStretchVisible(bool visible);
  bool stretchVisible() const { return stretchVisible_; }
  void setPinsVisible(bool visible);

  GarmentPanel* panel() const { return panel_; }
  PatternView* patternView() const { return patternView_; }
  // Opens the pattern's dock under the timeline (hidden at start).
  void showPatternDock();
  QDockWidget* dock() const { return dock_; }

 signals:
  void sceneChanged();
  void currentGarmentChanged();
  void selectionChanged();
  void simulationChanged();  // started, stopped, stepped, baked or dropped

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  struct View;
  struct Bake;

 public:
  struct BakeGarment;  // one garment of a bake (garment_tool.cpp)

 private:
  struct KeptState {
    std::string key;
    cloth::GarmentSimulation::Snapshot snapshot;
  };

  void onCharacterReplaced();
  // The bake beside the document (sim/cloth/bake_cache.h): written with it,
  // read back when it still matches the scene.
  void saveBakeBeside(const QString& documentPath);
  void loadBakeBeside(const QString& documentPath);
  std::string bakeKey(int clip, float start, int frames) const;
  void loadSections();
  void storeSections();
  void rebuildViews(const GarmentScene& before);
  void dropDynamics(bool keepBake = false);
  void holdShownDrapes();
  void recallDrapes();
  void showGarments();
  void restartSimulation();
  void startStep();
  void onStepFinished();
  std::vector<float> posedBody() const;
  std::vector<View*> simulatedViews() const;  // the garments, then the sheet
  std::vector<size_t> layerOrder() const;     // indices of simulatedViews(), inner to outer, the sheet last
  std::vector<BakeGarment> prepareBake(const std::vector<float>& firstBody, float fps) const;
  std::vector<BakeGarment> prepareBakeWithoutClip() const;
  std::unique_ptr<cloth::GarmentSimulation> makeViewSimulation(size_t view) const;
  std::string sewingKey(size_t view) const;
  const cloth::GarmentSimulation::Snapshot* keptState(const std::string& key) const;
  void keepState(std::string key, cloth::GarmentSimulation::Snapshot snapshot);
  void rebuildSheet();
  void showColliders();
  void moveCollidersLive(const GarmentScene& scene);
  void applyMovedColliders();
  void updateTimeAxis();
  cloth::PrimitiveCollider placedCollider(cloth::PrimitiveCollider::Shape shape) const;
  bool onPress(QMouseEvent* event);
  bool onMove(QMouseEvent* event);
  bool onRelease(QMouseEvent* event);

  MainWindow* window_;
  GarmentPanel* panel_ = nullptr;
  PatternView* patternView_ = nullptr;  // the current garment's pattern, in its own dock
  QDockWidget* patternDock_ = nullptr;
  QDockWidget* dock_ = nullptr;
  GarmentScene scene_;
  std::vector<std::unique_ptr<View>> views_;  // one per garment
  std::unique_ptr<View> sheet_;               // the cloth section's sheet, if any
  std::unique_ptr<render::ColliderActors> colliderActors_;
  ColliderDragTool* colliderDrag_ = nullptr;
  int currentCollider_ = -1;
  bool colliderDeselected_ = false;  // setCurrentCollider(-1): no collider selected until one is chosen
  bool collidersVisible_ = true;
  int current_ = -1;
  QString lastError_;
  bool loading_ = false;

  // The body the garments are draped on: the character in its rest pose.
  std::vector<float> restBody_;
  std::vector<uint32_t> bodyTriangles_;
  std::string bodyKey_;  // identifies restBody_ and bodyTriangles_ in kept states

  // Sewn and draped states, newest first (a few garments' worth).
  std::vector<KeptState> kept_;
  DrapeMemory drapes_;  // the drapes of recent garment states, for undo
  int sewingRuns_ = 0, reusedSewings_ = 0, warmStarts_ = 0;
  double lastBakeSeconds_ = 0.0;
  double lastBakeEstimate_ = 0.0;
  // Seconds per garment vertex stepped once: before the first bake, the
  // outfit's figure (`simulate garment_outfit_walk.json`) on a 2-core machine.
  static constexpr double kPriorSecondsPerVertexStep = 2e-5;
  JobRate bakeRate_{kPriorSecondsPerVertexStep};
  double lastBakePhases_[3] = {0.0, 0.0, 0.0};

  // Live simulation
  bool simulating_ = false;
  bool collidersMoved_ = false;  // the next step gives the simulations the scene's colliders
  int steps_ = 0;
  float simulatedSeconds_ = 0.0f;
  QElapsedTimer stepClock_;       // since the last step finished
  double framesPerSecond_ = 0.0;  // smoothed
  bool sewingShown_ = false;      // the status bar shows the sewing progress
  QFutureWatcher<QString> stepWatcher_;

  // Bake
  std::unique_ptr<Bake> bake_;  // null: no valid bake
  QString bakeOutOfDate_;
  std::atomic<bool> cancelBake_{false};
  bool baking_ = false;

  // Display and selection
  bool stretchVisible_ = false;
  bool pinsVisible_ = true;
  bool selectMode_ = false;
  std::vector<uint32_t> selection_;
  QRubberBand* rubberBand_ = nullptr;
  QPoint dragStart_;
  bool dragging_ = false;
};

}  // namespace mq::ui
