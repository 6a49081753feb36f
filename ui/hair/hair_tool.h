#pragma once
// The editor's hair tool: grooms the document's character with the
// hairstyle of the scene document's "hair" section, shows the strands
// (render::HairActor) and the flow primitives' handles in the viewport, and
// edits the style through undo commands (HairStyleCommand). Dragging a
// handle (a sphere moves a primitive, a vortex's tip cube turns its axis)
// regrows the guides live; the children regrow when it is released.
// Regrowth, the self-shadow and the arrays the viewport draws are made on a
// worker thread (HairWorker): an edit returns at once, the last finished hair
// stays on screen and the status bar says "Updating hair..." until the
// newest is ready. The viewport shows at most displayStrandLimit() strands
// (an editor setting shown in the dock) and draws them in parts over
// several frames, so a frame never takes long.
// Simulate steps the guide dynamics as the timeline moves; Bake simulates the
// whole clip with a progress dialog and plays it back.
//
// It plugs into MainWindow through its extension points: addToolDock() for
// the panel, the document's signals, sceneView()->addProp(), and an event
// filter on the viewport for handle drags (clicks elsewhere pass through to
// the pose tool and the camera).

#include <memory>
#include <optional>

#include <QElapsedTimer>
#include <QObject>
#include <QPoint>

#include "core/hair/hairstyle.h"
#include "core/hair/scalp.h"
#include "core/io/baked_surface.h"
#include "render/hair_handles.h"
#include "sim/hair/hair_bake.h"
#include "ui/hair/hair_style_command.h"
#include "ui/hair/hair_worker.h"

class QDockWidget;
class QLabel;
class QMouseEvent;

namespace mq {
class HairGroom;
class HairSimulator;
namespace render {
class BrushCursor;
class HairActor;
}  // namespace render
}  // namespace mq

namespace mq::ui {

class HairPanel;
class MainWindow;

class HairTool : public QObject {
  Q_OBJECT

 public:
  explicit HairTool(MainWindow* window);
  ~HairTool() override;

  bool hasHair() const { return style_.has_value(); }
  // The baked guides at clip times `times` (each the bake's nearest frame)
  // as coloured lines, for an animated glTF; null without a bake.
  std::optional<BakedSurface> bakedGuides(const std::vector<float>& times) const;
  // The bake's own frames: its first frame's time, fps and frame count.
  float bakeStart() const { return bake_ ? bake_->startTime : 0.0f; }
  float bakeFps() const { return bake_ ? bake_->fps : 0.0f; }
  int bakeFrameCount() const { return bake_ ? bake_->frameCount() : 0; }
  // The style being edited (valid when hasHair()).
  const HairStyle& style() const { return *style_; }
  // Strands in the groom on screen (the last finished one).
  size_t strandCount() const;
  // The groom on screen (null without hair), for tests and exporters.
  const HairGroom* groom() const { return groom_.get(); }
  QString lastError() const { return lastError_; }

  // Hair work under way off the GUI thread (regrowing or reshading).
  bool backgroundWorkPending() const;
  // Waits for it and shows the result: the groom is then the current
  // style's (scripts, screenshots, the bake and tests need that).
  void finishBackgroundWork();
  // The viewport draws the hair in parts, a few tens of milliseconds a
  // frame, the rest in the frames after (render::HairActor); pending: parts
  // are left to draw (none when the last frame did not draw the hair: out
  // of view). Off: every frame draws all of it (screenshots).
  static constexpr double kHairFrameBudgetMs = 20.0;
  bool hairDrawingPending() const;
  void setDrawingInParts(bool on);

  // The viewport grows at most this many strands (an editor setting, kept
  // in QSettings; software GL draws about 40,000 interactively).
  static constexpr size_t kDefaultDisplayStrandLimit = 40000;
  size_t displayStrandLimit() const { return displayStrandLimit_; }
  void setDisplayStrandLimit(size_t limit);
  // The strands the document asks for (its count, else the style's density
  // on this scalp); the viewport shows min(this, displayStrandLimit()).
  size_t documentStrandCount() const;

  // Edits through the undo stack. mergeKey: steps with the same non-zero key
  // merge into one command (a drag, a spin box); live: guides only.
  void editStyle(const HairStyle& after, const QString& text, int mergeKey = 0, bool live = false);
  // A built-in style (hair is created when there is none).
  void useBuiltinStyle(const QString& name);
  void removeHair();
  // Applies a style (nullopt: no hair) without undo (the commands call this).
  void applyStyle(const std::optional<HairStyle>& style, bool live);

  // Scalp: the region the hair grows from (saved in the document's hair
  // section). editScalp checks the region first: an empty one (a cone too
  // narrow, a bone driving no face) is refused with a status-bar message and
  // the current scalp stays; false then (lastError() says why).
  const ScalpRegion& scalp() const { return scalp_; }
  bool editScalp(const ScalpRegion& after, const QString& text, int mergeKey = 0);
  // Applies a region without undo (the commands call this): re-extracts the
  // scalp and regrows the hair on it.
  void applyScalp(const ScalpRegion& region);
  // The character has faces tagged as scalp (the default mannequin does).
  bool characterHasTaggedScalp() const;
  // The region automaticScalpRegion() picks (a tagged or bone-cone default
  // when it cannot: the character has no head).
  ScalpRegion automaticScalp() const;
  // The current scalp as a face list (what the brush paints on).
  ScalpRegion scalpAsFaces() const;
  // The current scalp is the face list automaticScalp() picks.
  bool scalpIsAutomatic() const;
  // The head bone found on the character (empty when none).
  std::string headBoneName() const;
  std::vector<std::string> boneNames() const;
  // The current scalp's area (m^2; 0 without a groom).
  float scalpArea() const;
  // Painting the scalp with a brush (the Scalp group's Paint button): while
  // on, a left drag on the character adds the faces under the brush to the
  // scalp and a Ctrl+left drag erases them (core/hair/scalp_paint.h), on any
  // mesh, a static head scan included; one undo step a stroke, the hair
  // regrowing as the stroke goes (at most every kPaintApplyMs). A drag that
  // starts off the character orbits as usual.
  void setPaintingScalp(bool on);
  bool paintingScalp() const { return painting_; }
  void setBrushRadius(float metres) { brushRadius_ = metres; }
  float brushRadius() const { return brushRadius_; }
  // One dab at a world point on the character as shown, applied at once
  // (tests, scripts); false when nothing is under it or the scalp would be empty.
  bool paintScalpAt(const glm::vec3& world, bool erase, int mergeKey = 0);
  static constexpr int kPaintApplyMs = 120;

  // Grooming brushes (core/hair/groom_stroke.h): while one is chosen, a
  // left drag on the hair or the character lays a stroke of it (Ctrl+drag:
  // the length brush shortens); the brush moves on the plane facing the
  // camera through the hair it started on. The guides follow live, the
  // children when the drag ends; one undo step a stroke. A drag that starts
  // off the hair and the character orbits as usual.
  void setGroomBrush(std::optional<GroomBrush> brush);
  std::optional<GroomBrush> groomBrush() const { return groomBrush_; }
  void setGroomRadius(float metres) { groomRadius_ = metres; }
  float groomRadius() const { return groomRadius_; }
  void setGroomStrength(float strength) { groomStrength_ = strength; }
  float groomStrength() const { return groomStrength_; }
  void setGroomMirror(bool on) { groomMirror_ = on; }
  // What a paint brush paints (paintRange()); Ctrl+drag paints the unpainted value.
  void setGroomValue(float value) { groomValue_ = value; }
  float groomValue() const { return groomValue_; }
  bool groomMirror() const { return groomMirror_; }
  // The brush circle in the viewport (null before the tool is set up).
  const render::BrushCursor* brushCursor() const { return cursor_.get(); }
  // One stroke of the current brush from world point `from` to `to` (as
  // shown), applied at once (tests, scripts); false without a brush or hair.
  bool groomStroke(const glm::vec3& from, const glm::vec3& to, bool invert = false);
  // Takes every stroke away (one undo step).
  void clearStrokes();

  // Primitive selection (shown by the panel and the handles).
  PrimitiveRef selectedPrimitive() const { return selected_; }
  void selectPrimitive(const PrimitiveRef& ref);
  void setHandlesVisible(bool visible);
  // Head space (rest head centre, world axes) to the world as posed now:
  // where the handles are drawn.
  glm::mat4 worldFromHead() const;
  // Self-shadowing by opacity shadow maps instead of the exact count.
  void setOpacityShadowMaps(bool on);
  bool opacityShadowMaps() const;

  // Dynamics
  void setSimulating(bool on);
  bool simulating() const { return simulating_; }
  // Simulates the current clip; false when cancelled or impossible.
  bool bake();
  bool hasBake() const { return bake_.has_value(); }
  // The live dynamics' kernel radius of hair against hair (0: off or not simulating yet).
  float interactionRadius() const { return simulator_ ? simulator_->interactionRadius() : 0.0f; }

  HairPanel* panel() const { return panel_; }
  QDockWidget* dock() const { return dock_; }

 signals:
  void styleChanged();
  void scalpChanged();
  void selectionChanged();
  void hairRegrown();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  // What a HairStyleCommand applies: applyStyle.
  HairStyleCommand::Apply applyStyleSnapshot();
  void onCharacterReplaced();
  void onPoseChanged();
  void loadSection();
  void storeSection();
  bool makeGroom();
  size_t viewportStrandCount(const HairStyle& style) const;
  // Asks the worker for the current style's hair (live: guides only).
  void requestRegrow(bool live);
  void onRegrown(const HairWorker::Regrown& result);
  void onBusyChanged(bool busy);
  glm::mat4 posedFromRest();
  void showPosedStrands();
  void ensureDynamics();
  void updateHandles();
  void invalidateDynamics();
  glm::vec3 headCenter() const;
  QPoint toDisplay(const QPointF& position) const;
  bool onPress(QMouseEvent* event);
  bool onMove(QMouseEvent* event);
  bool onRelease(QMouseEvent* event);
  QString dragText() const;  // the undo text of the drag under way

  MainWindow* window_;
  HairPanel* panel_ = nullptr;
  QDockWidget* dock_ = nullptr;
  std::unique_ptr<render::HairActor> actor_;
  std::unique_ptr<HairHandles> handles_;
  // The groom on screen and what it was grown with (shared with the worker,
  // which grows a copy: never modified once shown).
  std::shared_ptr<const HairGroom> groom_;
  std::optional<HairStyle> grownStyle_;
  size_t grownStrands_ = 0;
  bool childrenCurrent_ = false;  // false after a drag step regrew the guides alone
  HairWorker* worker_ = nullptr;
  QLabel* busyLabel_ = nullptr;
  bool announceScalp_ = false;  // the next regrown hair is on a new scalp: say so
  size_t hairFramesSeen_ = 0;   // the actor's framesDrawn() at the last frame
  bool lastFrameDrewHair_ = false;
  std::optional<HairStyle> style_;
  ScalpRegion scalp_;
  size_t requestedStrands_ = 20000;
  size_t displayStrandLimit_ = kDefaultDisplayStrandLimit;
  PrimitiveRef selected_;
  QString lastError_;
  bool loading_ = false;     // a section being loaded: not written back
  bool guidesOnly_ = false;  // the actor shows the guides alone (during a drag)

  // Dynamics
  std::unique_ptr<HairSimulator> simulator_;
  std::unique_ptr<HairRig> rig_;
  std::optional<HairBake> bake_;
  bool simulating_ = false;
  float lastTime_ = 0.0f;

  // Scalp painting
  bool painting_ = false;
  float brushRadius_ = 0.02f;          // metres
  std::optional<ScalpRegion> stroke_;  // the stroke's region, applied every kPaintApplyMs
  bool strokeErases_ = false;
  int strokeKey_ = 0;
  qint64 strokeAppliedMs_ = 0;
  QElapsedTimer strokeClock_;
  // Adds one dab to the stroke's region; false when it is not on the character.
  bool dab(const glm::vec3& world);
  bool onPaintPress(QMouseEvent* event);

  // Grooming brushes
  std::optional<GroomBrush> groomBrush_;
  float groomRadius_ = 0.03f;  // metres
  float groomStrength_ = 0.5f;
  bool groomMirror_ = false;
  float groomValue_ = 0.5f;
  // A stroke of the current brush and settings (invert: Ctrl held).
  GroomStroke newStroke(bool invert) const;
  std::optional<GroomStroke> groomStroke_;  // the stroke being drawn
  HairStyle groomBefore_;                   // the style when it started
  glm::vec3 groomAnchor_{0.0f};             // world: the depth the brush moves at
  glm::vec3 groomLast_{0.0f};               // head space: the last dab
  int groomKey_ = 0;
  qint64 groomAppliedMs_ = 0;
  // The point a brush press at display (x, y) starts from: on the ray, at
  // the nearest guide point within the brush's radius of it, else on the
  // character; none off both. A paint brush: on the character only.
  std::optional<glm::vec3> groomAnchorAt(int x, int y);
  bool onGroomPress(QMouseEvent* event);
  // The brush circle: where the brush under display point `display` would act.
  std::unique_ptr<render::BrushCursor> cursor_;
  QElapsedTimer hoverClock_;
  void updateBrushCursor(const QPoint& display);
  void extendGroomStroke(const glm::vec3& world);
  // The style with the stroke under way; pushed live or, at the end, whole.
  void pushGroomStroke(bool live);
  QString groomText() const;

  // Handle drag
  PrimitiveRef dragging_;
  HandleHit::Part dragPart_ = HandleHit::Body;  // the sphere moves it, a vortex's tip turns its axis
  int dragKey_ = 0;
  HairStyle dragBefore_;
  glm::vec3 dragWorld_{0.0f};
  glm::mat4 dragWorldFromHead_{1.0f};
  bool dragMoved_ = false;
};

}  // namespace mq::ui
