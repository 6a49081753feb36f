#include "ui/hair/hair_tool.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include <QDockWidget>
#include <QLabel>
#include <QMouseEvent>
#include <QSettings>
#include <QStatusBar>
#include <QUndoStack>

#include "core/hair/character_groom.h"
#include "core/hair/groom_stroke.h"
#include "core/hair/hair_groom.h"
#include "core/hair/hairstyle_json.h"
#include "core/hair/head_fit.h"
#include "core/hair/root_sampling.h"
#include "core/hair/scalp_paint.h"
#include "core/util/error.h"
#include "render/brush_cursor.h"
#include "render/hair_actor.h"
#include "render/scene_view.h"
#include "sim/hair/child_follow.h"
#include "sim/hair/hair_simulator.h"
#include "ui/document/editor_document.h"
#include "ui/hair/hair_panel.h"
#include "ui/hair/hair_style_command.h"
#include "ui/jobs/step_progress.h"
#include "ui/main_window.h"
#include "ui/viewport/mouse_routing.h"
#include "ui/viewport/vtk_viewport_widget.h"

namespace mq::ui {

namespace {

const char* const kDisplayStrandLimitKey = "hair/displayStrandLimit";

glm::quat rotationOf(const glm::mat4& m) {
  return glm::normalize(glm::quat_cast(
      glm::mat3(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])), glm::normalize(glm::vec3(m[2])))));
}

}  // namespace

HairTool::HairTool(MainWindow* window) : QObject(window), window_(window) {
  displayStrandLimit_ = std::clamp<size_t>(
      QSettings().value(kDisplayStrandLimitKey, qulonglong(kDefaultDisplayStrandLimit)).toULongLong(), 1,
      HairGroom::kMaxStrands);
  worker_ = new HairWorker(this);
  worker_->onRegrown = [this](const HairWorker::Regrown& result) { onRegrown(result); };
  worker_->onReshaded = [this](const std::shared_ptr<const render::HairGeometry>& source,
                               const std::shared_ptr<const render::HairGeometry>& reshaded) {
    if (actor_->geometry() != source) return;  // new strands came meanwhile
    actor_->showGeometry(reshaded);
    window_->viewport()->requestRender();
  };
  worker_->onBusyChanged = [this](bool busy) { onBusyChanged(busy); };
  busyLabel_ = new QLabel(tr("Updating hair…"));
  busyLabel_->setObjectName("HairBusyLabel");
  busyLabel_->hide();
  window->statusBar()->addPermanentWidget(busyLabel_);
  actor_ = std::make_unique<render::HairActor>();
  actor_->setVisible(false);
  // Called during a frame: the frame keeps the shadow it has, the worker
  // computes the new one (one at a time; the frame after asks again if the
  // light moved on meanwhile).
  actor_->setReshadeRequest([this] {
    if (!worker_->busy() && actor_->geometry() && actor_->keyLight())
      worker_->reshade(actor_->geometry(), actor_->shading(), *actor_->keyLight());
  });
  window->sceneView()->addProp(actor_->actor());
  actor_->setFrameBudget(kHairFrameBudgetMs);
  connect(window->viewport(), &VtkViewportWidget::frameRendered, this, [this] {
    lastFrameDrewHair_ = actor_->framesDrawn() != hairFramesSeen_;
    hairFramesSeen_ = actor_->framesDrawn();
    if (hairDrawingPending()) window_->viewport()->requestContinuation(actor_->actor());
  });
  handles_ = std::make_unique<HairHandles>(window->sceneView()->renderer());
  cursor_ = std::make_unique<render::BrushCursor>(window->sceneView()->renderer());
  hoverClock_.start();
  panel_ = new HairPanel(this);
  dock_ = new QDockWidget(tr("Hair"), window);
  dock_->setObjectName("HairToolDock");
  dock_->setWidget(panel_);
  window->addToolDock(dock_);
  window->viewport()->installEventFilter(this);
  connect(window->document(), &EditorDocument::characterReplaced, this, &HairTool::onCharacterReplaced);
  connect(window->document(), &EditorDocument::poseChanged, this, &HairTool::onPoseChanged);
  onCharacterReplaced();
}

// The callbacks reach into this tool: drop what is still under way.
HairTool::~HairTool() {
  worker_->cancel();
  worker_->finish();
}

size_t HairTool::strandCount() const { return groom_ ? groom_->strands().strandCount() : 0; }

std::optional<BakedSurface> HairTool::bakedGuides(const std::vector<float>& times) const {
  if (!bake_ || bake_->frameCount() == 0 || !style_) return std::nullopt;
  const int points = bake_->pointsPerStrand;
  const size_t guides = bake_->frames[0].size() / (3 * size_t(std::max(points, 1)));
  BakedSurface s = strandLines(guides, points, style_->rootColor, style_->tipColor);
  for (float t : times) s.frames.push_back(*bake_->frameAt(t));
  return s;
}

bool HairTool::backgroundWorkPending() const { return worker_->busy(); }

void HairTool::finishBackgroundWork() { worker_->finish(); }

void HairTool::onBusyChanged(bool busy) { busyLabel_->setVisible(busy); }

bool HairTool::hairDrawingPending() const { return lastFrameDrewHair_ && actor_->hasMoreToDraw(); }

void HairTool::setDrawingInParts(bool on) {
  actor_->setFrameBudget(on ? kHairFrameBudgetMs : 0.0);
  window_->viewport()->requestRender();
}

// ---- Document ----

void HairTool::onCharacterReplaced() {
  worker_->cancel();
  actor_->setVisible(false);  // the old character's hair
  groom_.reset();
  grownStyle_.reset();
  style_.reset();
  selected_ = {};
  invalidateDynamics();
  lastError_.clear();
  scalp_ = automaticScalp();  // no head: the groom reports why when hair is added
  loadSection();
  emit scalpChanged();
  emit styleChanged();
  emit selectionChanged();
}

void HairTool::loadSection() {
  const nlohmann::json& section = window_->document()->sceneSections().hair;
  if (section.is_null() || section.empty()) {
    loading_ = true;  // clearing the old hair is part of opening, not an edit
    applyStyle(std::nullopt, false);
    loading_ = false;
    return;
  }
  try {
    HairSection parsed = hairSectionFromJson(section);
    if (parsed.scalpGiven) scalp_ = parsed.scalp;
    requestedStrands_ = parsed.strands;
    if (parsed.fitToHead && makeGroom()) parsed.style = fitHairStyleToHead(parsed.style, groom_->proxy());
    loading_ = true;
    applyStyle(parsed.style, false);
    loading_ = false;
    dock_->raise();  // a document with hair opens on its hair
  } catch (const Error& e) {
    loading_ = false;
    lastError_ = QString::fromStdString(e.what());
  }
}

void HairTool::storeSection() {
  if (loading_) return;
  EditorDocument* document = window_->document();
  if (style_) {
    HairSection section;
    section.style = *style_;
    section.scalp = scalp_;
    section.strands = requestedStrands_;
    document->sceneSections().hair = toJson(section);
  } else {
    document->sceneSections().hair = nlohmann::json();
  }
  document->notifyChanged();
}

// ---- Editing ----

void HairTool::editStyle(const HairStyle& after, const QString& text, int mergeKey, bool live) {
  window_->document()->undoStack()->push(
      new HairStyleCommand(applyStyleSnapshot(), {style_, false}, {after, live}, text, mergeKey));
}

void HairTool::useBuiltinStyle(const QString& name) {
  try {
    HairStyle style = builtinHairStyle(name.toStdString());
    // Built-ins are made for the default mannequin's head.
    if (groom_ || makeGroom()) style = fitHairStyleToHead(style, groom_->proxy());
    window_->document()->undoStack()->push(
        new HairStyleCommand(applyStyleSnapshot(), {style_, false}, {style, false}, tr("Hairstyle %1").arg(name)));
  } catch (const Error& e) {
    lastError_ = QString::fromStdString(e.what());
  }
}

void HairTool::removeHair() {
  if (style_)
    window_->document()->undoStack()->push(
        new HairStyleCommand(applyStyleSnapshot(), {style_, false}, {std::nullopt, false}, tr("Remove hair")));
}

bool HairTool::makeGroom() {
  grownStyle_.reset();
  try {
    groom_ = makeCharacterGroom(window_->document()->character(), scalp_);
    return true;
  } catch (const Error& e) {
    lastError_ = QString::fromStdString(e.what());
    groom_.reset();
    return false;
  }
}

HairStyleCommand::Apply HairTool::applyStyleSnapshot() {
  return [this](const HairStyleSnapshot& snapshot) { applyStyle(snapshot.style, snapshot.live); };
}

void HairTool::applyStyle(const std::optional<HairStyle>& style, bool live) {
  style_ = style;
  invalidateDynamics();
  if (!style_) {
    worker_->cancel();
    actor_->setVisible(false);
    handles_->update(HairStyle{}, glm::mat4(1.0f), {});
    selected_ = {};
  } else if (groom_ || makeGroom()) {
    const auto all = primitivesOf(*style_);
    if (std::find(all.begin(), all.end(), selected_) == all.end()) selected_ = {};
    actor_->setColors(style_->rootColor, style_->tipColor);  // shader uniforms: at once
    actor_->setFibre(style_->shading);
    requestRegrow(live);
    updateHandles();
  }
  storeSection();
  window_->viewport()->requestRender();
  emit styleChanged();
}

size_t HairTool::documentStrandCount() const {
  if (!style_ || !groom_) return 0;
  const size_t wanted = requestedStrands_ ? requestedStrands_
                                          : rootCountForDensity(groom_->scalp(), style_->density,
                                                                size_t(std::max(0, style_->maxStrands)));
  return std::min(wanted, HairGroom::kMaxStrands);
}

// The document's count, else the style's density on this scalp (so a
// smaller scalp grows fewer strands), at most the display limit.
size_t HairTool::viewportStrandCount(const HairStyle& style) const {
  const size_t wanted =
      requestedStrands_ ? requestedStrands_
                        : rootCountForDensity(groom_->scalp(), style.density, size_t(std::max(0, style.maxStrands)));
  return std::clamp<size_t>(wanted, 1, displayStrandLimit_);
}

void HairTool::setDisplayStrandLimit(size_t limit) {
  limit = std::clamp<size_t>(limit, 1, HairGroom::kMaxStrands);
  if (limit == displayStrandLimit_) return;
  displayStrandLimit_ = limit;
  QSettings().setValue(kDisplayStrandLimitKey, qulonglong(limit));
  if (style_ && groom_) requestRegrow(false);
  emit styleChanged();
}

glm::mat4 HairTool::posedFromRest() {
  EditorDocument* document = window_->document();
  if (!rig_) rig_ = std::make_unique<HairRig>(HairRig::fromProxy(document->character(), groom_->proxy()));
  return rig_->posedFromRest(document->posed().worldFromBone());
}

void HairTool::requestRegrow(bool live) {
  const size_t strands = viewportStrandCount(*style_);
  // A colour alone changes shader uniforms: nothing to grow or upload.
  if (!live && !guidesOnly_ && !worker_->busy() &&
      regrowthNeeded(grownStyle_, grownStrands_, childrenCurrent_, *style_, strands) == Regrowth::Nothing) {
    grownStyle_ = *style_;
    return;
  }
  HairWorker::RegrowRequest request;
  request.groom = groom_;
  request.grownStyle = grownStyle_;
  request.grownStrands = grownStrands_;
  request.childrenCurrent = childrenCurrent_;
  request.style = *style_;
  request.strands = strands;
  request.live = live;
  request.posedFromRest = posedFromRest();
  request.shading = actor_->shading();
  request.keyLight = render::HairActor::keyLightOf(window_->sceneView()->renderer());
  worker_->regrow(std::move(request));
}

// The worker's hair for the newest edit: shown with a pointer swap.
void HairTool::onRegrown(const HairWorker::Regrown& result) {
  groom_ = result.groom;
  grownStyle_ = result.style;
  grownStrands_ = result.strands;
  childrenCurrent_ = result.childrenCurrent;
  guidesOnly_ = result.guidesOnly;
  actor_->showGeometry(result.geometry);
  actor_->setVisible(true);
  // The pose, a bake or the simulation moved on while the worker grew.
  if (!guidesOnly_ && (bake_ || simulating_ || posedFromRest() != result.posedFromRest)) showPosedStrands();
  if (announceScalp_) {
    announceScalp_ = false;
    window_->statusBar()->showMessage(
        tr("Scalp: %1 roots on %2 cm²").arg(strandCount()).arg(scalpArea() * 1e4f, 0, 'f', 0), 10000);
  }
  window_->viewport()->requestRender();
  emit hairRegrown();
}

// ---- Scalp ----

bool HairTool::editScalp(const ScalpRegion& after, const QString& text, int mergeKey) {
  try {
    extractScalp(window_->document()->character(), after);  // refuses an empty region
  } catch (const Error& e) {
    lastError_ = tr("Scalp unchanged: %1").arg(QString::fromStdString(e.what()));
    window_->statusBar()->showMessage(lastError_, 10000);
    emit scalpChanged();  // the panel goes back to the scalp in use
    return false;
  }
  lastError_.clear();
  window_->document()->undoStack()->push(
      new HairScalpCommand([this](const ScalpRegion& region) { applyScalp(region); }, scalp_, after, text, mergeKey));
  return true;
}

void HairTool::applyScalp(const ScalpRegion& region) {
  scalp_ = region;
  worker_->cancel();
  groom_.reset();
  grownStyle_.reset();
  invalidateDynamics();
  if (style_ && makeGroom()) {
    announceScalp_ = true;
    requestRegrow(false);
    updateHandles();
  }
  storeSection();
  window_->viewport()->requestRender();
  emit scalpChanged();
  emit styleChanged();
}

bool HairTool::characterHasTaggedScalp() const {
  for (const Mesh& mesh : window_->document()->character().meshes)
    if (mesh.vertexTags.size() == mesh.vertexCount() &&
        std::find(mesh.vertexTags.begin(), mesh.vertexTags.end(), TagScalp) != mesh.vertexTags.end())
      return true;
  return false;
}

ScalpRegion HairTool::scalpAsFaces() const { return mq::scalpAsFaces(window_->document()->character(), scalp_); }

bool HairTool::scalpIsAutomatic() const {
  const ScalpRegion automatic = automaticScalp();
  return automatic.kind == scalp_.kind && automatic.mesh == scalp_.mesh && automatic.faces == scalp_.faces;
}

ScalpRegion HairTool::automaticScalp() const {
  try {
    return automaticScalpRegion(window_->document()->character());
  } catch (const Error&) {
    return ScalpRegion{};
  }
}

std::string HairTool::headBoneName() const {
  const Character& character = window_->document()->character();
  const int head = findHeadBone(character);
  return head >= 0 ? character.skeleton.bone(head).name : std::string();
}

std::vector<std::string> HairTool::boneNames() const {
  const Skeleton& skeleton = window_->document()->character().skeleton;
  std::vector<std::string> names;
  for (int b = 0; b < skeleton.boneCount(); ++b) names.push_back(skeleton.bone(b).name);
  return names;
}

float HairTool::scalpArea() const { return groom_ ? groom_->scalp().area() : 0.0f; }

void HairTool::selectPrimitive(const PrimitiveRef& ref) {
  if (ref == selected_) return;
  selected_ = ref;
  updateHandles();
  window_->viewport()->requestRender();
  emit selectionChanged();
}

void HairTool::setHandlesVisible(bool visible) {
  handles_->setVisible(visible);
  window_->viewport()->requestRender();
}

// The next frame finds its shadow stale and asks the worker for the new one.
void HairTool::setOpacityShadowMaps(bool on) {
  render::HairShading shading = actor_->shading();
  shading.shadowMethod = on ? render::HairShadowMethod::OpacityMaps : render::HairShadowMethod::PointCount;
  actor_->setShading(shading);
  window_->viewport()->requestRender();
}

bool HairTool::opacityShadowMaps() const {
  return actor_->shading().shadowMethod == render::HairShadowMethod::OpacityMaps;
}

void HairTool::updateHandles() {
  if (style_ && groom_) handles_->update(*style_, worldFromHead(), selected_);
}

glm::vec3 HairTool::headCenter() const { return groom_ ? groom_->proxy().headCenter() : glm::vec3(0.0f); }

glm::mat4 HairTool::worldFromHead() const {
  glm::mat4 posedFromRest(1.0f);
  if (rig_) posedFromRest = rig_->posedFromRest(window_->document()->posed().worldFromBone());
  return posedFromRest * glm::translate(glm::mat4(1.0f), headCenter());
}

// ---- Display ----

// The strands where the character's head is now: baked, simulated, or
// carried rigidly by the head (on the GUI thread: the timeline's path).
void HairTool::showPosedStrands() {
  if (!style_ || !groom_) return;
  EditorDocument* document = window_->document();
  const glm::mat4 posedFromRest = this->posedFromRest();
  const Strands& all = groom_->strands();
  const size_t guideFloats = 3 * groom_->guideCount() * size_t(all.pointsPerStrand);
  std::vector<float> points;
  // Children are kept out of the body as in mannequin-cli's simulate/render.
  const PosedHairColliders body =
      rig_ ? rig_->body.posed(document->posed().worldFromBone(), characterHairParams().collisionMargin)
           : PosedHairColliders{};
  if (!guidesOnly_ && bake_ && bake_->frameAt(document->time())) {
    const std::vector<float>& guides = *bake_->frameAt(document->time());
    const Strands restGuides = leadingStrands(all, groom_->guideCount());
    followGuides(all, restGuides, guides, guideFrames(restGuides, guides, rotationOf(posedFromRest)), points, &body);
    std::copy(guides.begin(), guides.begin() + std::min(guideFloats, guides.size()), points.begin());
  } else if (!guidesOnly_ && simulating_ && simulator_) {
    poseGroomedStrands(all, *simulator_, points, &body);
  } else {
    if (posedFromRest == glm::mat4(1.0f) && !simulating_) {
      if (!bake_) return;  // setStrands already shows the rest shape
    }
    const std::vector<float>& rest = all.points;
    const size_t count = guidesOnly_ ? guideFloats : rest.size();
    points.resize(count);
    for (size_t k = 0; k < count; k += 3) {
      const glm::vec3 p = glm::vec3(posedFromRest * glm::vec4(rest[k], rest[k + 1], rest[k + 2], 1.0f));
      points[k] = p.x;
      points[k + 1] = p.y;
      points[k + 2] = p.z;
    }
  }
  actor_->updatePositions(points);
}

// ---- Dynamics ----

void HairTool::invalidateDynamics() {
  simulator_.reset();
  rig_.reset();
  bake_.reset();
}

void HairTool::ensureDynamics() {
  EditorDocument* document = window_->document();
  if (!rig_) rig_ = std::make_unique<HairRig>(HairRig::fromProxy(document->character(), groom_->proxy()));
  if (!simulator_) {
    simulator_ = std::make_unique<HairSimulator>(characterHairParams(style_->dynamics));
    simulator_->setRest(leadingStrands(groom_->strands(), groom_->guideCount()));
    lastTime_ = document->time();
  }
}

void HairTool::setSimulating(bool on) {
  finishBackgroundWork();  // the dynamics start from the current groom
  simulating_ = on && hasHair() && groom_;
  if (simulating_) {
    bake_.reset();
    ensureDynamics();
    simulator_->reset();
    onPoseChanged();
  } else if (hasHair() && groom_) {
    showPosedStrands();
    window_->viewport()->requestRender();
  }
}

void HairTool::onPoseChanged() {
  if (!style_ || !groom_) return;
  EditorDocument* document = window_->document();
  if (simulating_) {
    ensureDynamics();
    const float t = document->time();
    float dt = t - lastTime_;
    if (dt < 0.0f || dt > 0.5f) {  // scrubbed back or jumped: start again here
      simulator_->reset();
      dt = 1.0f / 60.0f;
    }
    lastTime_ = t;
    const auto& worldFromBone = document->posed().worldFromBone();
    const PosedHairColliders body = rig_->body.posed(worldFromBone, simulator_->params().collisionMargin);
    if (dt > 0.0f) simulator_->step(std::min(dt, 1.0f / 15.0f), rig_->posedFromRest(worldFromBone), &body);
  }
  showPosedStrands();
  updateHandles();
  window_->viewport()->requestRender();
}

bool HairTool::bake() {
  finishBackgroundWork();  // the bake simulates the current groom
  if (!style_ || !groom_) return false;
  EditorDocument* document = window_->document();
  ensureDynamics();
  StepProgress progress(window_, tr("Simulating the hair over the clip..."), 0);
  HairBakeCallbacks callbacks;
  callbacks.progress = [&](int done, int total) {
    window_->showProgress(tr("Baking hair"), total > 0 ? 100 * done / total : -1);
    progress.step(done, total);
  };
  callbacks.cancelled = [&] { return progress.cancelled(); };
  HairBake result =
      bakeHair(document->character(), document->clipIndex(), leadingStrands(groom_->strands(), groom_->guideCount()),
               characterHairParams(style_->dynamics), {}, callbacks, rig_.get());
  window_->hideProgress(result.cancelled ? tr("Hair bake cancelled") : tr("Hair baked"));
  if (result.cancelled) return false;
  simulating_ = false;
  bake_ = std::move(result);
  showPosedStrands();
  window_->viewport()->requestRender();
  return true;
}

// ---- Handle drags in the viewport ----

QPoint HairTool::toDisplay(const QPointF& position) const {
  const qreal ratio = window_->viewport()->devicePixelRatioF();
  const int height = int(window_->viewport()->height() * ratio);
  return QPoint(int(position.x() * ratio), height - 1 - int(position.y() * ratio));
}

bool HairTool::eventFilter(QObject* watched, QEvent* event) {
  if (watched != window_->viewport() || !style_ || !groom_) return false;
  return routeMouseEvent(this, event, &HairTool::onPress, &HairTool::onMove, &HairTool::onRelease);
}

// ---- Scalp painting ----

void HairTool::setPaintingScalp(bool on) {
  painting_ = on;
  stroke_.reset();
  if (on) {
    groomBrush_.reset();
    groomStroke_.reset();
  } else if (cursor_->visible()) {
    cursor_->hide();
    window_->viewport()->requestRender();
  }
  window_->statusBar()->showMessage(
      on ? tr("Paint the scalp: drag on the character to add, Ctrl+drag to erase; middle or Alt+drag orbits")
         : QString(),
      on ? 0 : 1);
}

bool HairTool::dab(const glm::vec3& world) {
  EditorDocument* document = window_->document();
  const Character& character = document->character();
  std::vector<std::vector<float>> shown;
  for (const PosedMesh& mesh : document->posed().meshes()) shown.push_back(mesh.positions);
  const int mesh = meshUnderBrush(shown, world);
  if (mesh < 0) return false;
  if (!stroke_) stroke_ = mq::scalpAsFaces(character, scalp_);
  stroke_ =
      paintScalp(*stroke_, mesh, character.meshes[mesh].triangles, shown[mesh], world, brushRadius_, strokeErases_);
  return true;
}

bool HairTool::paintScalpAt(const glm::vec3& world, bool erase, int mergeKey) {
  stroke_.reset();
  strokeErases_ = erase;
  const bool hit = dab(world) && editScalp(*stroke_, erase ? tr("Erase scalp") : tr("Paint scalp"), mergeKey);
  stroke_.reset();
  return hit;
}

bool HairTool::onPaintPress(QMouseEvent* event) {
  const bool erase = event->modifiers() == Qt::ControlModifier;
  if (event->button() != Qt::LeftButton || (event->modifiers() != Qt::NoModifier && !erase)) return false;
  const QPoint display = toDisplay(event->position());
  const std::optional<glm::vec3> hit = window_->sceneView()->pickSurface(display.x(), display.y());
  if (!hit) return false;  // off the character: the camera moves
  stroke_.reset();
  strokeErases_ = erase;
  strokeKey_ = HairStyleCommand::nextMergeKey();
  strokeClock_.start();
  strokeAppliedMs_ = -kPaintApplyMs;
  dab(*hit);
  return true;
}

// ---- Grooming brushes ----

void HairTool::setGroomBrush(std::optional<GroomBrush> brush) {
  groomBrush_ = brush;
  groomStroke_.reset();
  if (!brush && cursor_->visible()) {
    cursor_->hide();
    window_->viewport()->requestRender();
  }
  if (brush && painting_) setPaintingScalp(false);
  window_->statusBar()->showMessage(
      brush ? tr("Groom: drag over the hair (%1); Ctrl+drag shortens with the length brush and erases paint; middle or "
                 "Alt+drag orbits")
                  .arg(QString::fromStdString(groomBrushName(*brush)))
            : QString(),
      brush ? 0 : 1);
}

GroomStroke HairTool::newStroke(bool invert) const {
  GroomStroke stroke;
  stroke.brush = *groomBrush_;
  stroke.radius = groomRadius_;
  stroke.strength = (invert && stroke.brush == GroomBrush::Length ? -1.0f : 1.0f) * groomStrength_;
  stroke.mirror = groomMirror_;
  if (isPaintBrush(stroke.brush)) {
    const PaintRange range = paintRange(stroke.brush);
    const float unpainted = unpaintedValue(*style_, stroke.brush);
    stroke.value = std::clamp(invert ? unpainted : groomValue_, range.min, range.max);
  }
  return stroke;
}

QString HairTool::groomText() const {
  static const char* texts[] = {
      QT_TR_NOOP("Comb hair"),           QT_TR_NOOP("Cut hair"),           QT_TR_NOOP("Change hair length"),
      QT_TR_NOOP("Puff hair"),           QT_TR_NOOP("Smooth hair"),        QT_TR_NOOP("Clump hair"),
      QT_TR_NOOP("Frizz hair"),          QT_TR_NOOP("Paint hair density"), QT_TR_NOOP("Paint hair length"),
      QT_TR_NOOP("Paint hair clumping"), QT_TR_NOOP("Paint hair melanin"), QT_TR_NOOP("Paint hair pheomelanin")};
  return groomStroke_ ? tr(texts[size_t(groomStroke_->brush)]) : QString();
}

std::optional<glm::vec3> HairTool::groomAnchorAt(int x, int y) {
  auto* view = window_->sceneView();
  const std::optional<glm::vec3> surface = view->pickSurface(x, y);
  // A paint brush paints the scalp, where the strands grow.
  if (groomBrush_ && isPaintBrush(*groomBrush_)) return surface;
  const glm::vec3 camera = view->cameraPosition();
  const glm::vec3 through = handles_->displayToWorld(x, y, surface ? *surface : view->cameraFocus());
  if (glm::length(through - camera) < 1e-9f) return surface;
  const glm::vec3 ray = glm::normalize(through - camera);
  float nearest = surface ? glm::dot(*surface - camera, ray) : 1e30f;
  std::optional<glm::vec3> anchor = surface;
  const glm::mat4 shown = posedFromRest();
  const Strands& strands = groom_->strands();
  const size_t points = groom_->guideCount() * size_t(strands.pointsPerStrand);
  for (size_t i = 0; i < points; ++i) {
    const float* q = &strands.points[3 * i];
    const glm::vec3 p = glm::vec3(shown * glm::vec4(q[0], q[1], q[2], 1.0f)) - camera;
    const float depth = glm::dot(p, ray);
    if (depth <= 0.0f || depth >= nearest) continue;
    if (glm::length(p - depth * ray) < groomRadius_) {
      nearest = depth;
      anchor = camera + depth * ray;
    }
  }
  return anchor;
}

bool HairTool::onGroomPress(QMouseEvent* event) {
  const bool invert = event->modifiers() == Qt::ControlModifier;
  if (event->button() != Qt::LeftButton || (event->modifiers() != Qt::NoModifier && !invert)) return false;
  const QPoint display = toDisplay(event->position());
  const std::optional<glm::vec3> anchor = groomAnchorAt(display.x(), display.y());
  if (!anchor) return false;  // off the hair and the character: the camera moves
  const GroomStroke stroke = newStroke(invert);
  groomStroke_ = stroke;
  groomBefore_ = *style_;
  groomAnchor_ = *anchor;
  groomLast_ = glm::vec3(glm::inverse(worldFromHead()) * glm::vec4(*anchor, 1.0f));
  groomKey_ = HairStyleCommand::nextMergeKey();
  strokeClock_.start();
  groomAppliedMs_ = -kPaintApplyMs;
  // A press alone is a dab (a cut, a puff, paint); the comb needs a drag.
  if (stroke.brush != GroomBrush::Comb) groomStroke_->dabs.push_back({groomLast_, glm::vec3(0.0f)});
  pushGroomStroke(true);
  return true;
}

void HairTool::extendGroomStroke(const glm::vec3& world) {
  const glm::vec3 head = glm::vec3(glm::inverse(worldFromHead()) * glm::vec4(world, 1.0f));
  if (glm::length(head - groomLast_) < 0.25f * groomStroke_->radius) return;  // not yet a dab's spacing
  for (const GroomDab& dab : dabsAlong(groomLast_, head, groomStroke_->radius)) groomStroke_->dabs.push_back(dab);
  groomLast_ = head;
}

void HairTool::pushGroomStroke(bool live) {
  HairStyle after = groomBefore_;
  if (!groomStroke_->dabs.empty() && after.strokes.size() < kMaxGroomStrokes) after.strokes.push_back(*groomStroke_);
  editStyle(after, groomText(), groomKey_, live);
}

bool HairTool::groomStroke(const glm::vec3& from, const glm::vec3& to, bool invert) {
  if (!groomBrush_ || !style_ || !groom_) return false;
  const glm::mat4 headFromWorld = glm::inverse(worldFromHead());
  GroomStroke stroke = newStroke(invert);
  stroke.dabs = dabsAlong(glm::vec3(headFromWorld * glm::vec4(from, 1.0f)),
                          glm::vec3(headFromWorld * glm::vec4(to, 1.0f)), stroke.radius);
  groomStroke_ = stroke;
  groomBefore_ = *style_;
  groomKey_ = HairStyleCommand::nextMergeKey();
  pushGroomStroke(false);
  groomStroke_.reset();
  return true;
}

void HairTool::clearStrokes() {
  if (!style_ || style_->strokes.empty()) return;
  HairStyle after = *style_;
  after.strokes.clear();
  editStyle(after, tr("Clear brush strokes"));
}

bool HairTool::onPress(QMouseEvent* event) {
  if (groomBrush_ && dock_->isVisible()) return onGroomPress(event);
  if (painting_ && dock_->isVisible()) return onPaintPress(event);
  if (event->button() != Qt::LeftButton || event->modifiers() != Qt::NoModifier || !dock_->isVisible()) return false;
  const QPoint display = toDisplay(event->position());
  const HandleHit hit = handles_->pick(display.x(), display.y());
  if (!hit.valid()) return false;
  selectPrimitive(hit.ref);
  dragging_ = hit.ref;
  dragPart_ = hit.part;
  dragKey_ = HairStyleCommand::nextMergeKey();
  dragBefore_ = *style_;
  dragWorldFromHead_ = worldFromHead();
  const glm::vec3 grabbed =
      hit.part == HandleHit::AxisTip ? axisTipPosition(*style_, hit.ref) : handlePosition(*style_, hit.ref);
  dragWorld_ = glm::vec3(dragWorldFromHead_ * glm::vec4(grabbed, 1.0f));
  dragMoved_ = false;
  return true;
}

QString HairTool::dragText() const {
  return dragPart_ == HandleHit::AxisTip ? tr("Turn vortex axis") : tr("Move hair primitive");
}

void HairTool::updateBrushCursor(const QPoint& display) {
  const bool grooming = groomBrush_ && dock_->isVisible(), paintingScalp = painting_ && dock_->isVisible();
  std::optional<glm::vec3> at;
  if (grooming)
    at = groomStroke_ ? handles_->displayToWorld(display.x(), display.y(), groomAnchor_)
                      : groomAnchorAt(display.x(), display.y());
  else if (paintingScalp)
    at = window_->sceneView()->pickSurface(display.x(), display.y());
  const bool wasVisible = cursor_->visible();
  if (at && (grooming || paintingScalp)) {
    const glm::vec3 facing = window_->sceneView()->cameraPosition() - *at;
    if (glm::length(facing) > 1e-6f) cursor_->show(*at, facing, grooming ? groomRadius_ : brushRadius_);
  } else {
    cursor_->hide();
  }
  if (wasVisible || cursor_->visible()) window_->viewport()->requestRender();
}

bool HairTool::onMove(QMouseEvent* event) {
  // The brush circle follows the cursor (picking costs milliseconds: at most every 30 ms while hovering).
  if ((groomBrush_ || painting_) && (groomStroke_ || stroke_ || hoverClock_.elapsed() >= 30)) {
    hoverClock_.restart();
    updateBrushCursor(toDisplay(event->position()));
  }
  if (groomStroke_) {
    const QPoint display = toDisplay(event->position());
    extendGroomStroke(handles_->displayToWorld(display.x(), display.y(), groomAnchor_));
    if (strokeClock_.elapsed() - groomAppliedMs_ >= kPaintApplyMs) {
      groomAppliedMs_ = strokeClock_.elapsed();
      pushGroomStroke(true);
    }
    return true;
  }
  if (stroke_) {
    const QPoint display = toDisplay(event->position());
    if (const std::optional<glm::vec3> hit = window_->sceneView()->pickSurface(display.x(), display.y())) dab(*hit);
    if (strokeClock_.elapsed() - strokeAppliedMs_ >= kPaintApplyMs) {
      strokeAppliedMs_ = strokeClock_.elapsed();
      editScalp(*stroke_, strokeErases_ ? tr("Erase scalp") : tr("Paint scalp"), strokeKey_);
    }
    return true;
  }
  if (!dragging_.valid()) return false;
  const QPoint display = toDisplay(event->position());
  HairStyle after = *style_;
  const glm::vec3 world = handles_->displayToWorld(display.x(), display.y(), dragWorld_);
  const glm::vec3 headSpace = glm::vec3(glm::inverse(dragWorldFromHead_) * glm::vec4(world, 1.0f));
  if (dragPart_ == HandleHit::AxisTip)
    turnAxisToward(after, dragging_, headSpace);
  else
    moveHandle(after, dragging_, headSpace);
  editStyle(after, dragText(), dragKey_, true);
  dragMoved_ = true;
  return true;
}

bool HairTool::onRelease(QMouseEvent* event) {
  if (groomStroke_) {
    // The stroke's last step: not live, so the children regrow.
    pushGroomStroke(false);
    groomStroke_.reset();
    return true;
  }
  if (stroke_) {
    const ScalpRegion region = *stroke_;
    stroke_.reset();
    if (region.faces != scalp_.faces || region.mesh != scalp_.mesh || region.kind != scalp_.kind)
      editScalp(region, strokeErases_ ? tr("Erase scalp") : tr("Paint scalp"), strokeKey_);
    return true;
  }
  if (!dragging_.valid()) return false;
  // The drag's last step: same style, not live, so the children regrow.
  if (dragMoved_) editStyle(*style_, dragText(), dragKey_, false);
  dragging_ = {};
  return true;
}

}  // namespace mq::ui
