#include "ui/hair/hair_tool.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include <QCoreApplication>
#include <QDockWidget>
#include <QMouseEvent>
#include <QProgressDialog>
#include <QStatusBar>
#include <QUndoStack>

#include "core/hair/character_groom.h"
#include "core/hair/hair_groom.h"
#include "core/hair/hairstyle_json.h"
#include "core/hair/head_fit.h"
#include "core/hair/root_sampling.h"
#include "core/util/error.h"
#include "render/hair_actor.h"
#include "render/scene_view.h"
#include "sim/hair/child_follow.h"
#include "sim/hair/hair_simulator.h"
#include "ui/document/editor_document.h"
#include "ui/hair/hair_panel.h"
#include "ui/hair/hair_style_command.h"
#include "ui/main_window.h"
#include "ui/viewport/vtk_viewport_widget.h"

namespace mq::ui {

namespace {

// The viewport grooms at most this many strands (the document may ask for
// up to 150,000; software GL draws fewer interactively).
constexpr size_t kViewportMaxStrands = 40000;

bool rootsDiffer(const HairStyle& a, const HairStyle& b) {
  return a.density != b.density || a.maxStrands != b.maxStrands || a.guideCount != b.guideCount ||
         a.seed != b.seed || a.pointsPerStrand != b.pointsPerStrand;
}

bool onlyColorsDiffer(HairStyle a, const HairStyle& b) {
  a.rootColor = b.rootColor;
  a.tipColor = b.tipColor;
  return toJson(a) == toJson(b);
}

glm::quat rotationOf(const glm::mat4& m) {
  return glm::normalize(glm::quat_cast(glm::mat3(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])),
                                                 glm::normalize(glm::vec3(m[2])))));
}

}  // namespace

HairTool::HairTool(MainWindow* window) : QObject(window), window_(window) {
  actor_ = std::make_unique<render::HairActor>();
  actor_->setVisible(false);
  window->sceneView()->addProp(actor_->actor());
  handles_ = std::make_unique<HairHandles>(window->sceneView()->renderer());
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

HairTool::~HairTool() = default;

size_t HairTool::strandCount() const { return groom_ ? groom_->strands().strandCount() : 0; }

// ---- Document ----

void HairTool::onCharacterReplaced() {
  groom_.reset();
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
  window_->document()->undoStack()->push(new HairStyleCommand(this, style_, after, text, mergeKey, live));
}

void HairTool::useBuiltinStyle(const QString& name) {
  try {
    HairStyle style = builtinHairStyle(name.toStdString());
    // Built-ins are made for the default mannequin's head.
    if (groom_ || makeGroom()) style = fitHairStyleToHead(style, groom_->proxy());
    window_->document()->undoStack()->push(
        new HairStyleCommand(this, style_, style, tr("Hairstyle %1").arg(name)));
  } catch (const Error& e) {
    lastError_ = QString::fromStdString(e.what());
  }
}

void HairTool::removeHair() {
  if (style_) window_->document()->undoStack()->push(new HairStyleCommand(this, style_, std::nullopt, tr("Remove hair")));
}

bool HairTool::makeGroom() {
  try {
    groom_ = makeCharacterGroom(window_->document()->character(), scalp_);
    return true;
  } catch (const Error& e) {
    lastError_ = QString::fromStdString(e.what());
    groom_.reset();
    return false;
  }
}

void HairTool::applyStyle(const std::optional<HairStyle>& style, bool live) {
  const std::optional<HairStyle> before = style_;
  style_ = style;
  invalidateDynamics();
  if (!style_) {
    actor_->setVisible(false);
    handles_->update(HairStyle{}, glm::mat4(1.0f), {});
    selected_ = {};
  } else if (groom_ || makeGroom()) {
    if (before && groom_->strands().strandCount() > 0)
      regrow(*before, *style_, live);
    else
      groom_->grow(*style_, viewportStrandCount(*style_));
    const auto all = primitivesOf(*style_);
    if (std::find(all.begin(), all.end(), selected_) == all.end()) selected_ = {};
    showStrands(live);
    updateHandles();
  }
  storeSection();
  window_->viewport()->requestRender();
  emit styleChanged();
}

// The document's count, else the style's density on this scalp (so a
// smaller scalp grows fewer strands), at most kViewportMaxStrands.
size_t HairTool::viewportStrandCount(const HairStyle& style) const {
  const size_t wanted = requestedStrands_ ? requestedStrands_
                                          : rootCountForDensity(groom_->scalp(), style.density,
                                                                size_t(std::max(0, style.maxStrands)));
  return std::clamp<size_t>(wanted, 1, kViewportMaxStrands);
}

void HairTool::regrow(const HairStyle& before, const HairStyle& after, bool live) {
  if (rootsDiffer(before, after)) {
    groom_->grow(after, viewportStrandCount(after));
  } else if (!onlyColorsDiffer(before, after) || !live) {
    groom_->regrowGuides(after);
    if (!live) groom_->growChildren(after);
  }
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
  window_->document()->undoStack()->push(new HairScalpCommand(this, scalp_, after, text, mergeKey));
  return true;
}

void HairTool::applyScalp(const ScalpRegion& region) {
  scalp_ = region;
  groom_.reset();
  invalidateDynamics();
  if (style_ && makeGroom()) {
    groom_->grow(*style_, viewportStrandCount(*style_));
    showStrands(false);
    updateHandles();
    window_->statusBar()->showMessage(
        tr("Scalp: %1 roots on %2 cm²").arg(strandCount()).arg(scalpArea() * 1e4f, 0, 'f', 0), 10000);
    emit hairRegrown();
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

void HairTool::showStrands(bool guidesOnly) {
  guidesOnly_ = guidesOnly;
  const Strands& all = groom_->strands();
  actor_->setStrands(guidesOnly ? leadingStrands(all, groom_->guideCount()) : all);
  actor_->setColors(style_->rootColor, style_->tipColor);
  actor_->setVisible(true);
  showPosedStrands();
}

// The strands where the character's head is now: baked, simulated, or
// carried rigidly by the head.
void HairTool::showPosedStrands() {
  if (!style_ || !groom_) return;
  EditorDocument* document = window_->document();
  if (!rig_) rig_ = std::make_unique<HairRig>(HairRig::fromProxy(document->character(), groom_->proxy()));
  const glm::mat4 posedFromRest = rig_->posedFromRest(document->posed().worldFromBone());
  const Strands& all = groom_->strands();
  const size_t guideFloats = 3 * groom_->guideCount() * size_t(all.pointsPerStrand);
  std::vector<float> points;
  if (!guidesOnly_ && bake_ && bake_->frameAt(document->time())) {
    const std::vector<float>& guides = *bake_->frameAt(document->time());
    const Strands restGuides = leadingStrands(all, groom_->guideCount());
    followGuides(all, restGuides, guides, guideFrames(restGuides, guides, rotationOf(posedFromRest)), points);
    std::copy(guides.begin(), guides.begin() + std::min(guideFloats, guides.size()), points.begin());
  } else if (!guidesOnly_ && simulating_ && simulator_) {
    poseGroomedStrands(all, *simulator_, points);
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
    simulator_ = std::make_unique<HairSimulator>(characterHairParams());
    simulator_->setRest(leadingStrands(groom_->strands(), groom_->guideCount()));
    lastTime_ = document->time();
  }
}

void HairTool::setSimulating(bool on) {
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
  if (!style_ || !groom_) return false;
  EditorDocument* document = window_->document();
  ensureDynamics();
  QProgressDialog progress(tr("Simulating the hair over the clip..."), tr("Cancel"), 0, 100, window_);
  progress.setWindowModality(Qt::WindowModal);
  progress.setMinimumDuration(0);
  HairBakeCallbacks callbacks;
  callbacks.progress = [&](int done, int total) {
    progress.setMaximum(total);
    progress.setValue(done);
    window_->showProgress(tr("Baking hair"), total > 0 ? 100 * done / total : -1);
    QCoreApplication::processEvents();
  };
  callbacks.cancelled = [&] { return progress.wasCanceled(); };
  HairBake result = bakeHair(document->character(), document->clipIndex(),
                             leadingStrands(groom_->strands(), groom_->guideCount()), characterHairParams(), {}, callbacks,
                             rig_.get());
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
  switch (event->type()) {
    case QEvent::MouseButtonPress: return onPress(static_cast<QMouseEvent*>(event));
    case QEvent::MouseMove: return onMove(static_cast<QMouseEvent*>(event));
    case QEvent::MouseButtonRelease: return onRelease(static_cast<QMouseEvent*>(event));
    default: return false;
  }
}

bool HairTool::onPress(QMouseEvent* event) {
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

bool HairTool::onMove(QMouseEvent* event) {
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
  if (!dragging_.valid()) return false;
  // The drag's last step: same style, not live, so the children regrow.
  if (dragMoved_) editStyle(*style_, dragText(), dragKey_, false);
  dragging_ = {};
  return true;
}

}  // namespace mq::ui
