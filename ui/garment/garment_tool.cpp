#include "ui/garment/garment_tool.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <string_view>
#include <unordered_map>

#include <QDockWidget>
#include <QEventLoop>
#include <QMouseEvent>
#include <QProgressDialog>
#include <QRubberBand>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>
#include <QtConcurrent/QtConcurrentRun>

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>

#include "core/character/posed_character.h"
#include "core/garment/fabric_color.h"
#include "core/garment/garment_json.h"
#include "core/garment/parametric_garments.h"
#include "core/garment/pattern_dxf.h"
#include "core/garment/pattern_svg.h"
#include "core/garment/pin_remap.h"
#include "core/geometry/nearest_points.h"
#include "core/util/error.h"
#include "core/util/memory_budget.h"
#include "core/util/thread_pool.h"
#include "render/cloth_shading.h"
#include "render/collider_actors.h"
#include "render/garment_overlay.h"
#include "render/scene_view.h"
#include "sim/cloth/bake_cache.h"
#include "sim/cloth/baked_cloth.h"
#include "sim/garment/drape_schedule.h"
#include "sim/garment/dressing.h"
#include "sim/garment/garment_layers.h"
#include "sim/garment/garment_scene.h"
#include "sim/garment/garment_simulation.h"
#include "ui/document/autosave.h"
#include "ui/document/editor_document.h"
#include "ui/garment/collider_drag_tool.h"
#include "ui/garment/garment_edit_command.h"
#include "ui/garment/garment_panel.h"
#include "ui/garment/held_drape.h"
#include "ui/garment/pattern_view.h"
#include "ui/jobs/long_job.h"
#include "ui/main_window.h"
#include "ui/viewport/mouse_routing.h"
#include "ui/viewport/vtk_viewport_widget.h"

namespace mq::ui {

namespace {

std::unique_ptr<cloth::GarmentSimulation> makeSimulation(const GarmentScene& scene, size_t garment,
                                                         const std::vector<float>& body,
                                                         const std::vector<uint32_t>& bodyTriangles) {
  return cloth::makeGarmentSimulation(scene.garments[garment], scene.cloth, body, bodyTriangles,
                                      "garments[" + std::to_string(garment) + "]");
}

// What the mesh depends on: the garment without its name, fabric and pins.
nlohmann::json geometryOf(const Garment& garment) {
  nlohmann::json json = garmentToJson(garment);
  for (const char* key : {"name", "fabric", "pins", "layer"}) json.erase(key);
  return json;
}

std::vector<uint32_t> sortedUnique(std::vector<uint32_t> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// A short fingerprint of a float or index array (for cache keys).
template <typename T>
std::string fingerprint(const std::vector<T>& values) {
  const std::string_view bytes(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  return std::to_string(values.size()) + ":" + std::to_string(std::hash<std::string_view>{}(bytes));
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

QString shapeLabel(cloth::PrimitiveCollider::Shape shape) {
  switch (shape) {
    case cloth::PrimitiveCollider::Shape::Sphere:
      return QObject::tr("sphere");
    case cloth::PrimitiveCollider::Shape::Capsule:
      return QObject::tr("capsule");
    default:
      return QObject::tr("plane");
  }
}

QString displayName(const std::string& type) {
  if (type == "tshirt") return QObject::tr("T-shirt");
  if (type == "skirt") return QObject::tr("Skirt");
  if (type == "trousers") return QObject::tr("Trousers");
  return QString::fromStdString(type);
}

}  // namespace

// ---- Per-garment display and simulation ----

struct GarmentTool::View {
  render::SceneView* scene;
  GarmentMesh mesh;
  nlohmann::json builtFrom;  // garmentToJson of the garment the mesh was built from
  render::ClothActor actor;
  render::GarmentOverlay overlay;
  std::unique_ptr<cloth::GarmentSimulation> simulation;
  cloth::DrapeSchedule drape;
  std::vector<float> positions, stretch;  // what is shown
  std::vector<uint32_t> nearestBody;      // per garment vertex, for the unsimulated preview

  explicit View(render::SceneView* sceneView) : scene(sceneView) {
    scene->addProp(actor.actor());
    scene->addProp(overlay.stretchActor());
    scene->addProp(overlay.pinActor());
    scene->addProp(overlay.selectionActor());
  }
  ~View() {
    scene->removeProp(actor.actor());
    scene->removeProp(overlay.stretchActor());
    scene->removeProp(overlay.pinActor());
    scene->removeProp(overlay.selectionActor());
  }

  void build(const Garment& garment, const std::vector<float>& restBody) {
    mesh = buildGarmentMesh(garment);
    nearestBody = nearestPoints(mesh.positions, restBody, 1);
    builtFrom = geometryOf(garment);
    actor.setMesh(mesh.positions, mesh.triangles, mesh.restUvs);
    overlay.setTriangles(mesh.triangles);
    simulation.reset();
  }

  void buildSheet(const cloth::ClothSceneSpec& spec) {
    mesh = cloth::sheetGarmentMesh(spec);
    nearestBody.clear();  // a sheet does not follow the body before it is simulated
    cloth::buildClothMesh(spec, sheetPins);
    actor.setMesh(mesh.positions, mesh.triangles, mesh.restUvs);
    overlay.setTriangles(mesh.triangles);
    simulation.reset();
  }

  std::vector<uint32_t> sheetPins;  // the sheet's pinned vertices (garments keep theirs in the scene)
  // The last drape shown, kept across edits while the cloth does not run.
  std::optional<HeldDrape> held;
  // Where `positions` come from: a simulated or baked drape becomes the held
  // drape at the next edit.
  enum class Shown { Placed, Held, Simulated, Baked } shown = Shown::Placed;
  std::string sewingKey;  // the kept-state key of the running simulation
  bool sewnKept = false;  // its sewn state is kept (or came from there)
};

struct GarmentTool::Bake {
  std::string key;  // bakeKey() when it was baked
  int clip = -1;
  float start = 0.0f;
  std::vector<cloth::BakedCloth> garments;
  std::vector<std::vector<std::vector<float>>> stretch;  // [garment][frame] (the sheet last)

  size_t frameIndex(float time) const {
    if (garments.empty() || garments[0].frameCount() == 0) return 0;
    const double f = std::floor((time - start) * garments[0].fps() + 1e-4);
    return size_t(std::clamp(f, 0.0, double(garments[0].frameCount() - 1)));
  }
};

GarmentTool::GarmentTool(MainWindow* window) : QObject(window), window_(window) {
  panel_ = new GarmentPanel(this);
  dock_ = new QDockWidget(tr("Garments"), window);
  dock_->setObjectName("GarmentToolDock");
  dock_->setWidget(panel_);
  window->addToolDock(dock_);
  patternView_ = new PatternView;
  patternDock_ = new QDockWidget(tr("Pattern"), window);
  patternDock_->setObjectName("GarmentPatternDock");
  patternDock_->setWidget(patternView_);
  window->addToolDock(patternDock_, Qt::BottomDockWidgetArea);
  patternDock_->hide();  // opened from the Pattern menu or View > Panels: it takes room from the viewport
  auto showPattern = [this] {
    const int current = currentGarment();
    patternView_->setGarment(current >= 0 && current < garmentCount()
                                 ? std::optional<Garment>(scene_.garments[size_t(current)])
                                 : std::nullopt);
  };
  connect(this, &GarmentTool::sceneChanged, this, showPattern);
  connect(this, &GarmentTool::currentGarmentChanged, this, showPattern);
  colliderActors_ = std::make_unique<render::ColliderActors>(window->sceneView());
  rubberBand_ = new QRubberBand(QRubberBand::Rectangle, window->viewport());
  window->viewport()->installEventFilter(this);
  colliderDrag_ = new ColliderDragTool(this, window);  // filters the viewport's events before this tool
  connect(&stepWatcher_, &QFutureWatcher<QString>::finished, this, &GarmentTool::onStepFinished);
  connect(window->document(), &EditorDocument::characterReplaced, this, &GarmentTool::onCharacterReplaced);
  connect(window, &MainWindow::documentSaved, this, &GarmentTool::saveBakeBeside);
  connect(window->document(), &EditorDocument::poseChanged, this, &GarmentTool::showGarments);
  connect(window->document(), &EditorDocument::clipChanged, this, [this] {
    if (bake_ && bake_->clip != window_->document()->clipIndex()) clearBake();
  });
  onCharacterReplaced();
}

GarmentTool::~GarmentTool() {
  simulating_ = false;
  cancelBake_ = true;
  waitForStep();
  views_.clear();
  sheet_.reset();
  colliderActors_.reset();
}

// ---- Document ----

void GarmentTool::onCharacterReplaced() {
  setSimulating(false);
  waitForStep();
  const Character& character = window_->document()->character();
  PosedCharacter rest;
  rest.evaluate(character, -1, 0.0f, nullptr, &ThreadPool::shared());
  restBody_ = concatenatedPositions(rest.meshes());
  bodyTriangles_ = concatenatedTriangles(character);
  bodyKey_ = fingerprint(restBody_) + "/" + fingerprint(bodyTriangles_);
  kept_.clear();
  drapes_.clear();
  bakeOutOfDate_.clear();
  lastError_.clear();
  selection_.clear();
  views_.clear();
  sheet_.reset();
  currentCollider_ = -1;
  scene_ = GarmentScene{};
  loadSections();
  loadBakeBeside(window_->document()->documentPath());
  emit selectionChanged();
}

void GarmentTool::loadSections() {
  SceneDocument& sections = window_->document()->sceneSections();
  GarmentScene loaded;
  try {
    loaded = garmentSceneFromSections(sections.garments, sections.cloth, sections.colliders,
                                      window_->document()->documentPath().toStdString());
  } catch (const Error& e) {
    lastError_ = tr("The document's garments could not be read: %1").arg(e.what());
    window_->reportError(tr("Garments"), lastError_);
  }
  loading_ = true;
  applyScene(loaded);
  loading_ = false;
  // A document with cloth opens on the Garments dock.
  if (!scene_.garments.empty() || sheet_ || !scene_.cloth.colliders.empty()) dock_->raise();
}

void GarmentTool::storeSections() {
  if (loading_) return;
  SceneDocument& sections = window_->document()->sceneSections();
  garmentSceneToSections(scene_, sections.garments, sections.cloth, sections.colliders);
  window_->document()->notifyChanged();
}

// ---- Editing ----

void GarmentTool::edit(const GarmentScene& after, const QString& text, int mergeKey) {
  window_->document()->undoStack()->push(
      new GarmentEditCommand([this](const GarmentScene& scene) { applyScene(scene); }, scene_, after, text, mergeKey));
}

void GarmentTool::addGarment(const std::string& type) {
  try {
    GarmentScene after = scene_;
    Garment added = makeParametricGarment(type, window_->document()->character());
    added.name = displayName(type).toStdString();
    after.garments.push_back(std::move(added));
    edit(after, tr("Add %1").arg(displayName(type)));
    setCurrentGarment(garmentCount() - 1);
  } catch (const Error& e) {
    // Not only in the panel's status lines (often scrolled out of view): a
    // dialog (stderr in batch mode) and the status bar.
    lastError_ = tr("Could not add the %1: %2").arg(displayName(type), QString::fromStdString(e.what()));
    window_->statusBar()->showMessage(lastError_);
    if (window_->reportError) window_->reportError(tr("Garments"), lastError_);
    emit sceneChanged();
  }
}

void GarmentTool::removeGarment(int index) {
  if (index < 0 || index >= garmentCount()) return;
  GarmentScene after = scene_;
  const QString name = QString::fromStdString(after.garments[index].name);
  after.garments.erase(after.garments.begin() + index);
  edit(after, tr("Remove %1").arg(name));
}

void GarmentTool::setMeasurement(int garment, const std::string& name, float value, int mergeKey) {
  if (garment < 0 || garment >= garmentCount()) return;
  try {
    GarmentScene after = scene_;
    Garment& g = after.garments[garment];
    g.recipe.parameters[name] = value;
    const GarmentPins pins = g.pins;
    g = rebuildParametricGarment(g, window_->document()->character());
    // Pins are vertex indices of the old mesh: carry them to the rebuilt one.
    g.pins = pins;
    g.pins.vertices = remapPins(views_[garment]->mesh, pins.vertices, buildGarmentMesh(g));
    edit(after, tr("%1 %2").arg(QString::fromStdString(g.name), QString::fromStdString(name)), mergeKey);
  } catch (const Error& e) {
    lastError_ = QString::fromStdString(e.what());
    emit sceneChanged();
  }
}

void GarmentTool::setParticleDistance(int garment, float metres, int mergeKey) {
  if (garment < 0 || garment >= garmentCount() || scene_.garments[garment].targetEdgeLength == metres) return;
  GarmentScene after = scene_;
  Garment& g = after.garments[garment];
  g.targetEdgeLength = metres;
  try {
    // A new mesh: carry the pins to its nearest vertices.
    g.pins.vertices = remapPins(views_[garment]->mesh, g.pins.vertices, buildGarmentMesh(g));
  } catch (const Error& e) {
    lastError_ = QString::fromStdString(e.what());
    emit sceneChanged();
    return;
  }
  edit(after, tr("%1 particle distance").arg(QString::fromStdString(g.name)), mergeKey);
}

void GarmentTool::setLayer(int garment, int layer) {
  if (garment < 0 || garment >= garmentCount() || layer < 0 || layer > Garment::kMaxLayer ||
      scene_.garments[garment].layer == layer)
    return;
  GarmentScene after = scene_;
  after.garments[garment].layer = layer;
  edit(after, tr("%1 layer %2").arg(QString::fromStdString(after.garments[garment].name)).arg(layer));
}

std::vector<size_t> GarmentTool::layerOrder() const {
  std::vector<size_t> order = cloth::layerOrder(scene_.garments);
  if (sheet_) order.push_back(scene_.garments.size());  // the sheet: on its own, after the garments
  return order;
}

void GarmentTool::setFabricPreset(int garment, const std::string& preset) {
  if (garment < 0 || garment >= garmentCount() || !hasFabricPreset(preset)) return;
  GarmentScene after = scene_;
  after.garments[garment].fabric = preset;
  after.garments[garment].customFabric.reset();
  edit(after, tr("Fabric %1").arg(QString::fromStdString(preset)));
}

void GarmentTool::setFabric(int garment, const Fabric& fabric, int mergeKey) {
  if (garment < 0 || garment >= garmentCount()) return;
  try {
    fabric.validate();
  } catch (const Error& e) {
    lastError_ = QString::fromStdString(e.what());
    emit sceneChanged();
    return;
  }
  GarmentScene after = scene_;
  setFabricValues(after.garments[garment], fabric);
  edit(after, tr("Fabric values"), mergeKey);
}

void GarmentTool::setIntegrator(cloth::IntegratorKind integrator) {
  if (integrator == scene_.cloth.settings.integrator) return;
  GarmentScene after = scene_;
  after.cloth.settings.integrator = integrator;
  after.writeCloth = true;
  edit(after, tr("Integrator %1").arg(cloth::integratorName(integrator)));
}

void GarmentTool::setSelfCollisions(bool on) {
  if (on == scene_.cloth.settings.selfCollisions) return;
  GarmentScene after = scene_;
  after.cloth.settings.selfCollisions = on;
  after.writeCloth = true;
  edit(after, on ? tr("Self collisions on") : tr("Self collisions off"));
}

void GarmentTool::setClothFps(float fps, int mergeKey) {
  if (fps == scene_.cloth.fps || !(fps >= 1.0f && fps <= 240.0f)) return;
  GarmentScene after = scene_;
  after.cloth.fps = fps;
  after.writeCloth = true;
  edit(after, tr("Cloth %1 fps").arg(fps), mergeKey);
}

void GarmentTool::setBakeFrames(int frames, int mergeKey) {
  if (frames == scene_.cloth.bakeFrames || frames < 1) return;
  GarmentScene after = scene_;
  after.cloth.bakeFrames = frames;
  after.writeCloth = true;
  edit(after, tr("Bake %1 frames").arg(frames), mergeKey);
}

void GarmentTool::setPinsFollowBody(int garment, bool followBody) {
  const auto attach = followBody ? GarmentPins::Attach::Body : GarmentPins::Attach::Space;
  if (garment < 0 || garment >= garmentCount() || scene_.garments[garment].pins.attach == attach) return;
  GarmentScene after = scene_;
  after.garments[garment].pins.attach = attach;
  edit(after, followBody ? tr("Pins follow the body") : tr("Pins fixed in space"));
}

void GarmentTool::pinSelected() {
  if (current_ < 0 || selection_.empty()) return;
  GarmentScene after = scene_;
  std::vector<uint32_t>& pins = after.garments[current_].pins.vertices;
  pins.insert(pins.end(), selection_.begin(), selection_.end());
  pins = sortedUnique(pins);
  if (pins == scene_.garments[current_].pins.vertices) return;
  edit(after, tr("Pin %n vertices", "", int(selection_.size())));
}

void GarmentTool::unpinSelected() {
  if (current_ < 0 || selection_.empty()) return;
  GarmentScene after = scene_;
  std::vector<uint32_t>& pins = after.garments[current_].pins.vertices;
  std::vector<uint32_t> kept;
  std::set_difference(pins.begin(), pins.end(), selection_.begin(), selection_.end(), std::back_inserter(kept));
  if (kept.size() == pins.size()) return;
  pins = kept;
  edit(after, tr("Unpin vertices"));
}

void GarmentTool::clearPins() {
  if (current_ < 0 || scene_.garments[current_].pins.vertices.empty()) return;
  GarmentScene after = scene_;
  after.garments[current_].pins.vertices.clear();
  edit(after, tr("Clear pins"));
}

// ---- Colliders ----

void GarmentTool::setCurrentCollider(int index) {
  if (index < -1 || index >= colliderCount()) return;
  colliderDeselected_ = index < 0;
  if (index == currentCollider_) return;
  currentCollider_ = index;
  showColliders();
  emit sceneChanged();
}

// Where a new collider goes: in front of the character's chest (a sphere or
// a capsule across it) or under the sheet, and a plane at the feet or below
// the sheet; the user moves it from there.
cloth::PrimitiveCollider GarmentTool::placedCollider(cloth::PrimitiveCollider::Shape shape) const {
  glm::vec3 centre(0.0f, 0.5f, 0.0f), floor(0.0f);
  float size = 0.3f;
  if (!restBody_.empty()) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (size_t v = 0; v < restBody_.size() / 3; ++v) {
      const glm::vec3 p(restBody_[3 * v], restBody_[3 * v + 1], restBody_[3 * v + 2]);
      lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    size = 0.1f * (hi.y - lo.y);
    centre = glm::vec3(0.5f * (lo.x + hi.x), lo.y + 0.7f * (hi.y - lo.y), hi.z + size);
    floor = glm::vec3(0.5f * (lo.x + hi.x), lo.y, 0.5f * (lo.z + hi.z));
  } else if (scene_.cloth.hasSheet) {
    const cloth::SheetGarmentSpec& sheet = scene_.cloth.sheet;
    size = 0.25f * std::min(sheet.width, sheet.height);
    centre = sheet.center - glm::vec3(0.0f, sheet.vertical ? 0.0f : 1.5f * size, sheet.vertical ? -size : 0.0f);
    floor = sheet.center - glm::vec3(0.0f, sheet.vertical ? sheet.height : 0.5f, 0.0f);
  }
  switch (shape) {
    case cloth::PrimitiveCollider::Shape::Sphere:
      return cloth::PrimitiveCollider::sphere(centre, size);
    case cloth::PrimitiveCollider::Shape::Capsule:
      return cloth::PrimitiveCollider::capsule(centre - glm::vec3(1.5f * size, 0, 0),
                                               centre + glm::vec3(1.5f * size, 0, 0), 0.4f * size);
    default:
      return cloth::PrimitiveCollider::plane(floor, {0.0f, 1.0f, 0.0f});
  }
}

void GarmentTool::addCollider(cloth::PrimitiveCollider::Shape shape) {
  GarmentScene after = scene_;
  after.cloth.colliders.push_back(placedCollider(shape));
  edit(after, tr("Add %1 collider").arg(shapeLabel(shape)));
  setCurrentCollider(colliderCount() - 1);
}

bool GarmentTool::setCollider(int index, const cloth::PrimitiveCollider& collider, int mergeKey, const QString& text) {
  if (index < 0 || index >= colliderCount()) return false;
  const bool isPlane = collider.shape == cloth::PrimitiveCollider::Shape::Plane;
  QString problem;
  if (!finite(collider.a) || !finite(collider.b) || !std::isfinite(collider.radius) ||
      !std::isfinite(collider.friction))
    problem = tr("collider values must be finite numbers");
  else if (isPlane && !(glm::length(collider.b) > 0.0f))
    problem = tr("a plane's normal must not be zero");
  else if (!isPlane && !(collider.radius > 0.0f))
    problem = tr("a collider's radius must be positive");
  if (!problem.isEmpty()) {
    lastError_ = problem;
    emit sceneChanged();
    return false;
  }
  const cloth::PrimitiveCollider& now = scene_.cloth.colliders[index];
  if (now.shape == collider.shape && now.a == collider.a && now.b == collider.b && now.radius == collider.radius &&
      now.friction == collider.friction)
    return true;
  GarmentScene after = scene_;
  after.cloth.colliders[index] = collider;
  lastError_.clear();
  edit(after, text.isEmpty() ? tr("Edit %1 collider").arg(shapeLabel(collider.shape)) : text, mergeKey);
  return true;
}

void GarmentTool::removeCollider(int index) {
  if (index < 0 || index >= colliderCount()) return;
  GarmentScene after = scene_;
  const auto shape = after.cloth.colliders[index].shape;
  after.cloth.colliders.erase(after.cloth.colliders.begin() + index);
  edit(after, tr("Remove %1 collider").arg(shapeLabel(shape)));
}

void GarmentTool::setCollidersVisible(bool visible) {
  collidersVisible_ = visible;
  colliderActors_->setVisible(visible);
  colliderDrag_->updateGizmo();
  window_->viewport()->requestRender();
}

void GarmentTool::showColliders() {
  colliderActors_->set(scene_.cloth.colliders, currentCollider_);
  colliderActors_->setVisible(collidersVisible_);
  colliderDrag_->updateGizmo();
  window_->viewport()->requestRender();
}

// Only the colliders changed while the cloth runs (a drag moves a collider
// under it): the simulation goes on with them where they are now. No wait
// for the step in flight (a garment's step can take a second): the next
// step takes them. The bake no longer fits.
void GarmentTool::moveCollidersLive(const GarmentScene& scene) {
  scene_ = scene;
  bake_.reset();
  collidersMoved_ = true;
  for (View* view : simulatedViews()) view->sewnKept = true;  // sewn among moving colliders: not a state to reuse
  if (!stepWatcher_.isRunning()) applyMovedColliders();
  if (currentCollider_ >= colliderCount()) currentCollider_ = colliderCount() - 1;
  showColliders();
  storeSections();
  emit sceneChanged();
  emit simulationChanged();
}

// Between steps only (the worker owns the simulations during one).
void GarmentTool::applyMovedColliders() {
  if (!collidersMoved_) return;
  collidersMoved_ = false;
  for (View* view : simulatedViews())
    if (view->simulation) view->simulation->setColliders(scene_.cloth.colliders);
}

// Without a character the document's time axis is the bake's length.
void GarmentTool::updateTimeAxis() {
  const bool axis = bakesWithoutClip() && !simulatedViews().empty() && scene_.cloth.bakeFrames > 1;
  window_->document()->setNoClipDuration(axis ? float(scene_.cloth.bakeFrames - 1) / scene_.cloth.fps : 0.0f);
}

int GarmentTool::pickCollider(int x, int y) const {
  std::vector<vtkActor*> cloth;
  auto add = [&](View& view) { cloth.push_back(view.actor.actor()), cloth.push_back(view.overlay.stretchActor()); };
  for (const auto& view : views_) add(*view);
  if (sheet_) add(*sheet_);
  return colliderActors_->pick(x, y, cloth);
}

const std::vector<float>& GarmentTool::shownSheetPositions() const {
  static const std::vector<float> none;
  return sheet_ ? sheet_->positions : none;
}

void GarmentTool::applyScene(const GarmentScene& scene) {
  GarmentScene withTheseColliders = scene_;
  withTheseColliders.cloth.colliders = scene.cloth.colliders;
  if (simulating_ && withTheseColliders == scene) {
    moveCollidersLive(scene);
    return;
  }
  waitForStep();
  const GarmentScene before = scene_;
  const std::string bakeChange = bake_ && !loading_ ? bakeInvalidatedBy(before, scene) : std::string();
  holdShownDrapes();
  scene_ = scene;
  rebuildViews(before);
  recallDrapes();
  dropDynamics(/*keepBake=*/bake_ && !loading_ && bakeChange.empty());
  if (!bakeChange.empty()) bakeOutOfDate_ = QString::fromStdString(bakeChange);
  if (current_ >= garmentCount()) current_ = garmentCount() - 1;
  if (current_ < 0 && garmentCount() > 0) current_ = 0;
  if (currentCollider_ >= colliderCount()) currentCollider_ = colliderCount() - 1;
  // The dock shows the first collider unless the selection was cleared (a click on nothing).
  if (loading_) colliderDeselected_ = false;
  if (currentCollider_ < 0 && colliderCount() > 0 && !colliderDeselected_) currentCollider_ = 0;
  showColliders();
  storeSections();
  updateTimeAxis();
  if (simulating_) restartSimulation();
  showGarments();
  emit sceneChanged();
  emit simulationChanged();
}

// Rebuilds the meshes of the garments whose panels changed; keeps the others.
void GarmentTool::rebuildViews(const GarmentScene& before) {
  std::vector<std::unique_ptr<View>> old = std::move(views_);
  views_.clear();
  bool selectionValid = true;
  for (size_t i = 0; i < scene_.garments.size(); ++i) {
    const nlohmann::json wanted = geometryOf(scene_.garments[i]);
    std::unique_ptr<View> view;
    for (auto& candidate : old)
      if (candidate && candidate->builtFrom == wanted) {
        view = std::move(candidate);
        break;
      }
    if (!view) {
      view = std::make_unique<View>(window_->sceneView());
      try {
        view->build(scene_.garments[i], restBody_);
      } catch (const Error& e) {
        lastError_ = QString::fromStdString(e.what());
      }
      if (int(i) == current_) selectionValid = false;
      // The same garment rebuilt (a measurement, the particle distance): its drape comes along.
      const bool sameGarment = i < before.garments.size() && before.garments[i].name == scene_.garments[i].name;
      if (sameGarment && i < old.size() && old[i] && old[i]->held && old[i]->held->fits(old[i]->mesh) &&
          view->mesh.vertexCount() > 0)
        view->held = old[i]->held->rebuiltAs(old[i]->mesh, view->mesh);
    }
    view->actor.setShading(render::clothShadingForFabric(scene_.garments[i].fabric));
    views_.push_back(std::move(view));
  }
  if (!selectionValid && !selection_.empty()) {
    selection_.clear();
    emit selectionChanged();
  }
  rebuildSheet();
}

// The sheet's mesh when the sheet's own values changed (not for its fabric or the colliders).
void GarmentTool::rebuildSheet() {
  if (!scene_.cloth.hasSheet) {
    sheet_.reset();
    return;
  }
  nlohmann::json section, colliders;
  cloth::writeClothScene(scene_.cloth, section, colliders);
  const nlohmann::json wanted = {section["garment"], section["pins"]};
  if (sheet_ && sheet_->builtFrom == wanted) return;
  sheet_ = std::make_unique<View>(window_->sceneView());
  try {
    sheet_->buildSheet(scene_.cloth);
  } catch (const Error& e) {
    lastError_ = QString::fromStdString(e.what());
  }
  sheet_->builtFrom = wanted;
  sheet_->actor.setShading(
      render::clothShadingForFabric(scene_.cloth.fabricPreset.empty() ? "cotton" : scene_.cloth.fabricPreset));
}

void GarmentTool::setCurrentGarment(int index) {
  if (index < -1 || index >= garmentCount() || index == current_) return;
  current_ = index;
  selection_.clear();
  showGarments();
  emit currentGarmentChanged();
  emit selectionChanged();
}

const GarmentMesh* GarmentTool::garmentMesh(int garment) const {
  return garment >= 0 && garment < int(views_.size()) ? &views_[garment]->mesh : nullptr;
}

const std::vector<float>& GarmentTool::shownPositions(int garment) const { return views_.at(garment)->positions; }
const std::vector<float>& GarmentTool::shownStretch(int garment) const { return views_.at(garment)->stretch; }

// ---- Display ----

// Each garment (and the sheet) where it is now: the baked frame of the
// current time, the live simulation, or as placed around the rest body.
void GarmentTool::showGarments() {
  const float time = window_->document()->time();
  std::vector<float> posed;
  const std::vector<View*> views = simulatedViews();
  for (size_t i = 0; i < views.size(); ++i) {
    View& view = *views[i];
    const bool isGarment = i < scene_.garments.size();
    view.shown = View::Shown::Baked;
    if (bake_ && bake_->clip == window_->document()->clipIndex() && i < bake_->garments.size()) {
      const size_t frame = bake_->frameIndex(time);
      view.positions = bake_->garments[i].frame(frame);
      view.stretch = bake_->stretch[i][frame];
    } else if (view.simulation) {
      view.positions = view.simulation->positions();
      view.stretch = view.simulation->vertexStretch();
      view.shown = view.simulation->welded() ? View::Shown::Simulated : View::Shown::Placed;
    } else if (view.held && view.held->fits(view.mesh)) {
      if (posed.empty()) posed = posedBody();
      view.positions = view.held->carriedTo(posed);
      view.stretch.assign(view.mesh.vertexCount(), 1.0f);
      view.shown = View::Shown::Held;
    } else {
      view.shown = View::Shown::Placed;
      // Not simulated: the placed panels, carried by the body's nearest
      // vertices from the rest pose to the pose shown.
      if (posed.empty()) posed = posedBody();
      view.positions = view.mesh.positions;
      if (posed.size() == restBody_.size() && view.nearestBody.size() == view.mesh.vertexCount())
        for (size_t v = 0; v < view.nearestBody.size(); ++v)
          for (int k = 0; k < 3; ++k) {
            const size_t b = 3 * size_t(view.nearestBody[v]) + k;
            view.positions[3 * v + k] += posed[b] - restBody_[b];
          }
      view.stretch.assign(view.mesh.vertexCount(), 1.0f);
    }
    view.actor.updatePositions(view.positions);
    view.actor.setVisible(!stretchVisible_);
    view.overlay.setPositions(view.positions);
    view.overlay.setStretch(view.stretch);
    view.overlay.setStretchVisible(stretchVisible_);
    view.overlay.setPinned(isGarment ? scene_.garments[i].pins.vertices : view.sheetPins);
    view.overlay.setSelected(int(i) == current_ ? selection_ : std::vector<uint32_t>{});
    view.overlay.setDotsVisible(pinsVisible_);
  }
  window_->viewport()->requestRender();
}

std::vector<GarmentTool::View*> GarmentTool::simulatedViews() const {
  std::vector<View*> out;
  for (const auto& view : views_) out.push_back(view.get());
  if (sheet_) out.push_back(sheet_.get());
  return out;
}

std::unique_ptr<cloth::GarmentSimulation> GarmentTool::makeViewSimulation(size_t view) const {
  if (view < scene_.garments.size()) return makeSimulation(scene_, view, restBody_, bodyTriangles_);
  return cloth::makeSheetSimulation(scene_.cloth, restBody_, bodyTriangles_);
}

// Everything the sewn state depends on: the garment (mesh, fabric, pins) or
// the sheet, the solver settings and fps, the colliders and the rest body.
std::string GarmentTool::sewingKey(size_t view) const {
  nlohmann::json cloth, colliders;
  cloth::writeClothScene(scene_.cloth, cloth, colliders);
  cloth.erase("bake_frames");  // what is baked afterwards, not how the cloth is sewn
  nlohmann::json key = {{"cloth", cloth}, {"colliders", colliders}};
  if (view < scene_.garments.size()) {
    key["garment"] = garmentToJson(scene_.garments[view]);
    key["garment"].erase("layer");  // garments sew and drape each on its own (layering starts after)
  }
  return key.dump() + "|" + bodyKey_;
}

const cloth::GarmentSimulation::Snapshot* GarmentTool::keptState(const std::string& key) const {
  for (const KeptState& kept : kept_)
    if (kept.key == key) return &kept.snapshot;
  return nullptr;
}

void GarmentTool::keepState(std::string key, cloth::GarmentSimulation::Snapshot snapshot) {
  constexpr size_t kKept = 12;  // a few garments' sewn and draped states
  kept_.erase(std::remove_if(kept_.begin(), kept_.end(), [&](const KeptState& k) { return k.key == key; }),
              kept_.end());
  kept_.insert(kept_.begin(), KeptState{std::move(key), std::move(snapshot)});
  if (kept_.size() > kKept) kept_.resize(kKept);
}

void GarmentTool::setStretchVisible(bool visible) {
  stretchVisible_ = visible;
  showGarments();
  emit simulationChanged();  // the panel's checkbox follows
}

void GarmentTool::setPinsVisible(bool visible) {
  pinsVisible_ = visible;
  showGarments();
}

// ---- Live simulation ----

void GarmentTool::dropDynamics(bool keepBake) {
  waitForStep();
  for (View* view : simulatedViews()) view->simulation.reset();
  steps_ = 0;
  simulatedSeconds_ = 0.0f;
  if (!keepBake) bake_.reset();
}

// What each garment shows now, if it is a drape, becomes its held drape,
// remembered under the garment's state for an undo to find.
void GarmentTool::holdShownDrapes() {
  const std::vector<View*> views = simulatedViews();
  std::vector<float> posed;
  for (size_t i = 0; i < views.size(); ++i) {
    View& view = *views[i];
    const bool drape = view.shown == View::Shown::Simulated || view.shown == View::Shown::Baked;
    if (drape && view.positions.size() == 3 * view.mesh.vertexCount()) {
      if (posed.empty()) posed = posedBody();
      view.held = HeldDrape(view.positions, posed);
    }
    if (view.held) drapes_.remember(sewingKey(i), *view.held);
  }
}

// A garment back in a state it had (an undo, a redo) takes that state's drape.
void GarmentTool::recallDrapes() {
  const std::vector<View*> views = simulatedViews();
  for (size_t i = 0; i < views.size(); ++i)
    if (const HeldDrape* drape = drapes_.recall(sewingKey(i)); drape && drape->fits(views[i]->mesh))
      views[i]->held = *drape;
}

void GarmentTool::clearBake() {
  if (!bake_) return;
  holdShownDrapes();  // the frame on screen stays
  bake_.reset();
  showGarments();
  emit simulationChanged();
}

bool GarmentTool::exportBake(const QString& dir, bool pointCache) {
  if (!bake_) {
    lastError_ = tr("There is no bake to export: bake the clip first");
    return false;
  }
  try {
    for (size_t g = 0; g < bake_->garments.size(); ++g) {
      const bool garment = g < scene_.garments.size();
      const std::string stem = garment ? cloth::garmentFileStem(scene_.garments[g].name, g) : "sheet";
      if (pointCache)
        bake_->garments[g].exportPointCache(dir.toStdString(), stem);
      else
        bake_->garments[g].exportObjSequence(dir.toStdString(), stem);
    }
  } catch (const std::exception& e) {
    lastError_ = QString::fromStdString(e.what());
    return false;
  }
  lastError_.clear();
  return true;
}

bool GarmentTool::exportPattern(int garment, const QString& path, float seamAllowance) {
  if (garment < 0 || garment >= garmentCount()) {
    lastError_ = tr("Choose a garment first");
    return false;
  }
  try {
    const Garment& chosen = scene_.garments[size_t(garment)];
    if (path.endsWith(".dxf", Qt::CaseInsensitive))
      writePatternDxf(path.toStdString(), chosen, {seamAllowance});
    else
      writePatternSvg(path.toStdString(), chosen, {seamAllowance});
  } catch (const std::exception& e) {
    lastError_ = QString::fromStdString(e.what());
    return false;
  }
  lastError_.clear();
  return true;
}

void GarmentTool::showPatternDock() {
  const bool wasHidden = patternDock_->isHidden();
  patternDock_->show();
  patternDock_->raise();
  if (wasHidden) window_->resizeDocks({patternDock_}, {300}, Qt::Vertical);
}

bool GarmentTool::importPattern(const QString& path) {
  try {
    Garment imported = readPatternDxf(path.toStdString());
    GarmentScene after = scene_;
    const std::string base = imported.name;
    for (int n = 2; std::any_of(after.garments.begin(), after.garments.end(),
                                [&](const Garment& g) { return g.name == imported.name; });
         ++n)
      imported.name = base + " " + std::to_string(n);
    const QString name = QString::fromStdString(imported.name);
    after.garments.push_back(std::move(imported));
    edit(after, tr("Import %1").arg(name));
    setCurrentGarment(garmentCount() - 1);
  } catch (const std::exception& e) {
    lastError_ = QString::fromStdString(e.what());
    return false;
  }
  lastError_.clear();
  return true;
}

// What a bake depends on: every garment's sewing key (garment, fabric,
// pins, solver settings, colliders, rest body), the layers, the clip and
// the baked range, and the body at the first, middle and last frames (the
// pose edits).
std::string GarmentTool::bakeKey(int clip, float start, int frames) const {
  std::string key;
  for (size_t i = 0; i < simulatedViews().size(); ++i) key += sewingKey(i) + "\n";
  for (const Garment& garment : scene_.garments) key += std::to_string(garment.layer) + ",";
  EditorDocument* document = window_->document();
  key += "\nclip " + std::to_string(clip) + " from " + std::to_string(start) + " frames " + std::to_string(frames) +
         " at " + std::to_string(scene_.cloth.fps);
  if (clip < 0 || frames <= 0) return key;
  key += " " + document->character().clips.at(size_t(clip)).name;
  PosedCharacter posed;
  for (int frame : {0, frames / 2, frames - 1}) {
    posed.evaluate(document->character(), clip, start + frame / scene_.cloth.fps, &document->poseEdits(),
                   &ThreadPool::shared());
    key += " " + fingerprint(concatenatedPositions(posed.meshes()));
  }
  return key;
}

void GarmentTool::saveBakeBeside(const QString& documentPath) {
  const std::string path = cloth::bakeCachePath(documentPath.toStdString());
  try {
    if (bake_) {
      cloth::writeBakeCache(path, {bake_->key, bake_->clip, bake_->start, bake_->garments, bake_->stretch});
    } else {
      std::error_code ignored;
      std::filesystem::remove(path, ignored);  // a bake of an older state would only be refused
    }
  } catch (const std::exception& e) {
    lastError_ = tr("The bake was not saved beside the document: %1").arg(e.what());
    window_->hideProgress(lastError_);
    emit simulationChanged();
  }
}

void GarmentTool::loadBakeBeside(const QString& documentPath) {
  if (documentPath.isEmpty()) return;
  const std::string path = cloth::bakeCachePath(documentPath.toStdString());
  if (!std::filesystem::exists(path)) return;
  try {
    cloth::BakeCache cache = cloth::readBakeCache(path);
    const std::vector<View*> views = simulatedViews();
    bool fits = cache.garments.size() == views.size() && !cache.garments.empty();
    for (size_t i = 0; fits && i < views.size(); ++i)
      fits =
          cache.garments[i].frameCount() > 0 && cache.garments[i].frame(0).size() == 3 * views[i]->mesh.vertexCount();
    const int frames = fits ? int(cache.garments[0].frameCount()) : 0;
    const bool clipExists = cache.clip < int(window_->document()->character().clips.size());
    if (!fits || !clipExists || cache.key != bakeKey(cache.clip, cache.start, frames)) {
      bakeOutOfDate_ = tr("the saved bake is of another state of the scene");
      return;
    }
    auto bake = std::make_unique<Bake>();
    bake->key = std::move(cache.key);
    bake->clip = cache.clip;
    bake->start = cache.start;
    bake->garments = std::move(cache.garments);
    bake->stretch = std::move(cache.stretch);
    bake_ = std::move(bake);
    showGarments();
    emit simulationChanged();
  } catch (const std::exception& e) {
    lastError_ = tr("The saved bake could not be read: %1").arg(e.what());
    emit simulationChanged();
  }
}

std::optional<GarmentTool::BakeForExport> GarmentTool::bakeForExport() const {
  if (!bake_ || bakedFrameCount() == 0) return std::nullopt;
  BakeForExport out;
  out.clip = bake_->clip;
  out.start = bake_->start;
  out.fps = bake_->garments[0].fps();
  out.frames = bakedFrameCount();
  for (size_t g = 0; g < bake_->garments.size(); ++g) {
    const bool garment = g < scene_.garments.size();
    BakedSurface s;
    s.name = garment ? scene_.garments[g].name : "sheet";
    s.triangles = bake_->garments[g].triangles();
    for (size_t f = 0; f < bake_->garments[g].frameCount(); ++f) s.frames.push_back(bake_->garments[g].frame(f));
    s.color = glm::vec4(fabricColor(garment ? scene_.garments[g].fabric : scene_.cloth.fabricPreset), 1.0f);
    out.surfaces.push_back(std::move(s));
  }
  return out;
}

int GarmentTool::bakedFrameCount() const {
  return bake_ && !bake_->garments.empty() ? int(bake_->garments[0].frameCount()) : 0;
}

std::vector<float> GarmentTool::posedBody() const {
  return concatenatedPositions(window_->document()->posed().meshes());
}

// Every garment starts from its kept sewn state when there is one, else from
// the placed panels (its sewn state is kept once the seams are done).
void GarmentTool::restartSimulation() {
  waitForStep();
  steps_ = 0;
  framesPerSecond_ = 0.0;
  stepClock_.invalidate();
  simulatedSeconds_ = 0.0f;
  lastError_.clear();
  const std::vector<View*> views = simulatedViews();
  const std::vector<float> posed = posedBody();
  try {
    for (size_t i = 0; i < views.size(); ++i) {
      View& view = *views[i];
      view.simulation = makeViewSimulation(i);
      view.drape = cloth::DrapeSchedule{};
      view.sewingKey = sewingKey(i);
      view.sewnKept = false;
      if (view.held && view.held->fits(view.mesh)) {
        // From the held drape as shown, on the body as posed now: no sewing,
        // no draping. (Moving the body from the drape's pose instead would
        // drag body pins re-anchored in that pose through the cloth.)
        view.simulation->startFromDrape(view.held->carriedTo(posed), posed);
        view.drape.skipToPose();
        view.sewnKept = true;  // not a sewn state on the rest body: nothing to keep
        ++warmStarts_;
      } else if (const auto* sewn = keptState(view.sewingKey)) {
        view.simulation->restore(*sewn);
        view.drape.skipSewing();
        view.sewnKept = true;
        ++reusedSewings_;
      } else {
        ++sewingRuns_;
      }
    }
  } catch (const Error& e) {
    lastError_ = QString::fromStdString(e.what());
    simulating_ = false;
    for (View* view : views) view->simulation.reset();
    return;
  }
  QTimer::singleShot(0, this, &GarmentTool::startStep);
}

void GarmentTool::setSimulating(bool on) {
  on = on && !simulatedViews().empty();
  if (on == simulating_) return;
  simulating_ = on;
  if (on) {
    holdShownDrapes();  // the run continues from what is on screen
    bake_.reset();
    restartSimulation();
  } else {
    waitForStep();
    if (sewingShown_) window_->hideProgress(QString());
    sewingShown_ = false;
  }
  showGarments();
  emit simulationChanged();
}

void GarmentTool::resetDrapes() {
  setSimulating(false);
  if (bake_) bakeOutOfDate_ = tr("drapes reset");
  for (View* view : simulatedViews()) view->held.reset();
  dropDynamics();
  drapes_.clear();
  showGarments();
  emit simulationChanged();
}

void GarmentTool::waitForStep() { stepWatcher_.waitForFinished(); }

QString GarmentTool::simulationPhase() const {
  if (!simulating_) return QString();
  for (View* view : simulatedViews())
    if (view->simulation && !view->simulation->welded()) return tr("Sewing");
  if (restBody_.empty()) return tr("Simulating");  // a sheet without a character: nothing to drape onto
  for (View* view : simulatedViews())
    if (view->simulation && !view->drape.draped()) return tr("Draping");
  return tr("Following the clip");
}

// One step of every garment on a worker thread, with the body where the
// timeline has it now; the next step starts when this one has been shown.
void GarmentTool::startStep() {
  if (!simulating_ || stepWatcher_.isRunning()) return;
  applyMovedColliders();
  struct Job {
    cloth::GarmentSimulation* simulation;
    cloth::DrapeSchedule* drape;
  };
  // Inner garments first; a garment is worn over the ones before it once
  // both are draped (while they sew and drape, the body is in a different
  // pose for each).
  std::vector<Job> jobs;
  const std::vector<View*> views = simulatedViews();
  std::vector<cloth::GarmentSimulation*> simulations;
  for (View* view : views) simulations.push_back(view->simulation.get());
  cloth::wearInLayers(simulations, layerOrder(),
                      [&](size_t i) { return i < scene_.garments.size() && views[i]->drape.draped(); });
  for (size_t i : layerOrder())
    if (views[i]->simulation) jobs.push_back({views[i]->simulation.get(), &views[i]->drape});
  if (jobs.empty()) return;
  const float dt = 1.0f / scene_.cloth.fps;
  stepWatcher_.setFuture(QtConcurrent::run([jobs, dt, rest = restBody_, target = posedBody()]() -> QString {
    try {
      std::vector<float> body;
      for (const Job& job : jobs) {
        cloth::blendBody(rest, target, job.drape->advance(*job.simulation, dt), body);
        job.simulation->step(dt, body.empty() ? nullptr : &body);  // no character: nothing to collide with
      }
      return QString();
    } catch (const std::exception& e) {
      return QString::fromStdString(e.what());
    }
  }));
}

void GarmentTool::onStepFinished() {
  const QString error = stepWatcher_.future().resultCount() > 0 ? stepWatcher_.result() : QString();
  if (!error.isEmpty()) {
    lastError_ = tr("The simulation stopped: %1").arg(error);
    simulating_ = false;
    window_->hideProgress(lastError_);
    emit simulationChanged();
    return;
  }
  if (!simulating_) return;
  ++steps_;
  // Smoothed over about ten steps; the first step's time includes starting up.
  if (steps_ > 1 && stepClock_.isValid()) {
    const double rate = 1000.0 / std::max<qint64>(1, stepClock_.elapsed());
    framesPerSecond_ = framesPerSecond_ > 0.0 ? 0.9 * framesPerSecond_ + 0.1 * rate : rate;
  }
  stepClock_.start();
  simulatedSeconds_ += 1.0f / scene_.cloth.fps;
  // Keep each garment's sewn state (the worker is idle now) for the next run or bake.
  for (View* view : simulatedViews())
    if (view->simulation && !view->sewnKept && view->simulation->welded() &&
        view->drape.sewingDone(*view->simulation)) {
      keepState(view->sewingKey, view->simulation->snapshot());
      view->sewnKept = true;
    }
  // The status bar's busy bar while the seams close (the first seconds of a new garment).
  const bool sewing = simulationPhase() == tr("Sewing");
  if (sewing) {
    // Sewing ends by the weld, at the latest after the sewing time limit.
    const float limit = cloth::GarmentSimulationSettings{}.maxSewingSeconds + 0.25f;
    window_->showProgress(tr("Sewing the garments"), std::min(99, int(100.0f * simulatedSeconds_ / limit)));
  } else if (sewingShown_)
    window_->hideProgress(tr("Garments sewn"));
  sewingShown_ = sewing;
  showGarments();
  emit simulationChanged();
  QTimer::singleShot(0, this, &GarmentTool::startStep);
}

// ---- Bake ----

// One garment of a bake: where it starts, and the states the worker reached.
struct GarmentTool::BakeGarment {
  std::unique_ptr<cloth::GarmentSimulation> simulation;
  std::string sewnKey, drapedKey;
  bool sewn = false, draped = false;  // from a kept sewn / draped state (sewn: also once the worker sewed it)
  bool warm = false;                  // from the held drape carried to the first frame: settles there
  int settleSteps = 0;                // at most this many steps before the first frame
  std::optional<cloth::GarmentSimulation::Snapshot> sewnState, drapedState;  // to keep
};

namespace {

// Worker time by phase: sewing, draping onto the first frame, the frames.
class PhaseClock {
 public:
  enum Phase { Sewing, Draping, Frames };
  void restart() { mark_ = std::chrono::steady_clock::now(); }
  void charge(Phase phase) {
    const auto now = std::chrono::steady_clock::now();
    seconds[phase] += std::chrono::duration<double>(now - mark_).count();
    mark_ = now;
  }
  double seconds[3] = {0.0, 0.0, 0.0};

 private:
  std::chrono::steady_clock::time_point mark_ = std::chrono::steady_clock::now();
};

const std::vector<float>* bodyOrNull(const std::vector<float>& body) { return body.empty() ? nullptr : &body; }

}  // namespace

// Each garment starts from its kept draped state for this bake's first
// frame, or its kept sewn state (then drapes), or the placed panels (sews,
// then drapes). Throws mq::Error.
// A drape carried to the first frame settles this long on it before the frames.
constexpr float kWarmSettleSeconds = 0.25f;

std::vector<GarmentTool::BakeGarment> GarmentTool::prepareBake(const std::vector<float>& firstBody, float fps) const {
  const std::string firstFrame = fingerprint(firstBody) + "@" + std::to_string(fps);
  const int fullSettle = cloth::DrapeSchedule{}.maxSteps(1.0f / fps);
  const int blendSteps = int(std::ceil(cloth::DrapeSchedule::kBlendSeconds * fps)) + 2;
  std::vector<BakeGarment> garments(simulatedViews().size());
  for (size_t i = 0; i < garments.size(); ++i) {
    BakeGarment& g = garments[i];
    g.simulation = makeViewSimulation(i);
    g.sewnKey = sewingKey(i);
    g.drapedKey = g.sewnKey + "|draped:" + firstFrame;
    const View& view = *simulatedViews()[i];
    if (const auto* draped = keptState(g.drapedKey)) {
      g.simulation->restore(*draped);
      g.sewn = g.draped = true;
    } else if (view.held && view.held->fits(view.mesh)) {
      g.simulation->startFromDrape(view.held->carriedTo(firstBody), firstBody);
      g.sewn = g.warm = true;
      g.settleSteps = int(std::ceil(kWarmSettleSeconds * fps));
    } else if (const auto* sewn = keptState(g.sewnKey)) {
      g.simulation->restore(*sewn);
      g.sewn = true;
      g.settleSteps = blendSteps;
    } else {
      g.settleSteps = fullSettle;
    }
  }
  return garments;
}

// No body to drape onto: every garment (the sheet) starts as placed, its
// first frame is the placed state (nothing kept is reused: a kept state has
// already fallen).
std::vector<GarmentTool::BakeGarment> GarmentTool::prepareBakeWithoutClip() const {
  std::vector<BakeGarment> garments(simulatedViews().size());
  for (size_t i = 0; i < garments.size(); ++i) {
    garments[i].simulation = makeViewSimulation(i);
    garments[i].draped = true;  // no settling before the first frame
  }
  return garments;
}

namespace {

// Sews the garment (unless it starts sewn) on the rest body, then moves the
// body to the first frame. False when cancelled.
bool settle(GarmentTool::BakeGarment& g, const std::vector<float>& rest, const std::vector<float>& first, float dt,
            const std::atomic<bool>& cancel, const std::function<void(int)>& stepped, PhaseClock& clock) {
  cloth::GarmentSimulation& simulation = *g.simulation;
  cloth::DrapeSchedule drape;
  if (g.warm)
    drape.skipToPose();  // on the first frame's body already: it only settles
  else if (g.sewn)
    drape.skipSewing();
  std::vector<float> body;
  for (int step = 0; step < g.settleSteps && (g.warm || !drape.draped()); ++step) {
    if (cancel) return false;
    if (!g.sewn && simulation.welded() && drape.sewingDone(simulation)) {
      g.sewnState = simulation.snapshot();
      g.sewn = true;
    }
    const bool sewing = !g.sewn;
    cloth::blendBody(rest, first, drape.advance(simulation, dt), body);
    simulation.step(dt, bodyOrNull(body));
    clock.charge(sewing ? PhaseClock::Sewing : PhaseClock::Draping);
    stepped(step + 1);
  }
  if (simulation.welded()) g.drapedState = simulation.snapshot();
  return true;
}

// The frames of the clip for every garment, the first where they are now,
// stepped together in `order` (inner to outer): an outer garment is worn
// over the ones before it. Before the first frame they settle together on the
// first body, as every path dresses (sim/garment/dressing.h). False when
// cancelled.
bool bakeFrames(std::vector<GarmentTool::BakeGarment>& garments, const std::vector<size_t>& order, size_t layered,
                const std::vector<std::vector<float>>& bodies, float fps, const std::atomic<bool>& cancel,
                const std::function<void(int)>& stepped, std::vector<cloth::BakedCloth>& baked,
                std::vector<std::vector<std::vector<float>>>& stretch) {
  std::vector<cloth::GarmentSimulation*> simulations;
  for (GarmentTool::BakeGarment& g : garments) simulations.push_back(g.simulation.get());
  cloth::wearInLayers(simulations, order, [&](size_t g) { return g < layered; });
  const bool withBody = !bodies.empty() && !bodies[0].empty();  // no character: frame 1 is the placed cloth
  if (withBody && !cloth::settleTogether(simulations, order, bodies[0], 1.0f / fps, [&] { return bool(cancel); }))
    return false;
  for (size_t f = 0; f < bodies.size(); ++f) {
    if (cancel) return false;
    for (size_t g : order) {
      cloth::GarmentSimulation& simulation = *garments[g].simulation;
      if (f > 0) simulation.step(1.0f / fps, bodyOrNull(bodies[f]));
      baked[g].addFrame(simulation.positions());
      stretch[g].push_back(simulation.vertexStretch());
    }
    stepped(int(f) + 1);
  }
  return true;
}

// A bake's work: each garment's vertices stepped while it settles, then
// through every frame (and the layers' settling).
double bakeVertexSteps(const std::vector<GarmentTool::BakeGarment>& garments, int frames, float fps) {
  double steps = 0.0;
  const int layerSettle = int(std::ceil(cloth::kDressingSettleSeconds * fps));
  for (const GarmentTool::BakeGarment& g : garments)
    steps += double(g.simulation->vertexCount()) * (g.settleSteps + layerSettle + frames);
  return steps;
}

}  // namespace

// The states reached are kept for the next bake or run.
bool GarmentTool::bake(float from, float to, bool askIfLong) {
  if (baking_) return false;
  // A bake runs for minutes: keep the unsaved work first.
  if (Autosave* autosave = window_->autosave()) autosave->saveNow();
  EditorDocument* document = window_->document();
  if (simulatedViews().empty()) {
    lastError_ = tr("There are no garments to bake");
    return false;
  }
  const int clip = document->clipIndex();
  // No character: no clip to follow; bake_frames from the placed cloth, on the document's own time axis.
  const bool withoutClip = clip < 0 && bakesWithoutClip();
  if (clip < 0 && !withoutClip) {
    lastError_ = tr("Choose a clip to bake (the rest pose has no time axis)");
    return false;
  }
  setSimulating(false);
  // The previous bake comes back if this one fails or is cancelled.
  std::unique_ptr<Bake> previousBake = std::move(bake_);
  auto keepPreviousBake = [&] { bake_ = std::move(previousBake); };
  const auto started = std::chrono::steady_clock::now();
  const float fps = scene_.cloth.fps;
  const float start = withoutClip ? 0.0f : from >= 0.0f ? std::max(from, document->clipStart()) : document->clipStart();
  const float end = to >= 0.0f ? std::min(to, document->clipEnd()) : document->clipEnd();
  const int frames =
      withoutClip ? scene_.cloth.bakeFrames : std::max(1, int(std::floor((end - start) * fps + 1e-3f)) + 1);

  // Every frame of the body is kept for the worker, and of each garment for
  // the bake (its positions and stretch).
  double clothVertices = 0.0;
  for (const View* view : simulatedViews()) clothVertices += view->mesh.positions.size() / 3.0;
  try {
    checkMemoryBudget("a bake of " + std::to_string(frames) + " frames",
                      frames * (12.0 * document->character().vertexCount() + 16.0 * clothVertices));
  } catch (const Error& e) {
    lastError_ = QString::fromStdString(e.what());
    keepPreviousBake();
    return false;
  }
  // The body at every frame, posed here (the worker only simulates); none without a character.
  std::vector<std::vector<float>> bodies(frames);
  PosedCharacter posed;
  auto poseFrame = [&](int f) {
    posed.evaluate(document->character(), clip, start + f / fps, &document->poseEdits(), &ThreadPool::shared());
    bodies[f] = concatenatedPositions(posed.meshes());
  };
  if (!withoutClip) poseFrame(0);
  std::vector<BakeGarment> garments;
  try {
    garments = withoutClip ? prepareBakeWithoutClip() : prepareBake(bodies[0], fps);
  } catch (const Error& e) {
    lastError_ = QString::fromStdString(e.what());
    keepPreviousBake();
    return false;
  }
  const double vertexSteps = bakeVertexSteps(garments, frames, fps);
  lastBakeEstimate_ = bakeRate_.seconds(vertexSteps);
  const QString what = tr("Baking %1 frames of %2 cloth vertices").arg(frames).arg(std::llround(clothVertices));
  if (askIfLong && !confirmLongJob(window_, what, lastBakeEstimate_)) {
    keepPreviousBake();
    lastError_ = tr("Bake not started");
    return false;
  }
  for (int f = 1; f < frames && !withoutClip; ++f) poseFrame(f);

  int total = 0;
  std::vector<int> base;  // progress before each garment
  for (const BakeGarment& g : garments) base.push_back(total), total += g.settleSteps;
  total += frames * int(garments.size());
  std::atomic<int> done{0};
  cancelBake_ = false;
  baking_ = true;
  auto result = std::make_unique<Bake>();
  result->clip = clip;
  result->start = start;
  PhaseClock clock;

  const std::vector<size_t> order = layerOrder();
  const size_t garmentViews = scene_.garments.size();  // the views after them: the sheet
  auto work = [&]() -> QString {
    try {
      clock.restart();
      // Each garment sews and drapes onto the first frame on its own...
      for (size_t g = 0; g < garments.size(); ++g) {
        BakeGarment& garment = garments[g];
        if (!garment.draped &&
            !settle(
                garment, restBody_, bodies[0], 1.0f / fps, cancelBake_, [&](int s) { done = base[g] + s; }, clock))
          return QString();
      }
      // ... then they go through the clip together, in layers.
      clock.restart();
      std::vector<cloth::BakedCloth> baked;
      for (const BakeGarment& g : garments) baked.emplace_back(g.simulation->triangles(), fps);
      std::vector<std::vector<std::vector<float>>> stretch(garments.size());
      const int settled = total - frames * int(garments.size());
      if (!bakeFrames(
              garments, order, garmentViews, bodies, fps, cancelBake_,
              [&](int f) { done = settled + f * int(garments.size()); }, baked, stretch))
        return QString();
      clock.charge(PhaseClock::Frames);
      result->garments = std::move(baked);
      result->stretch = std::move(stretch);
      return QString();
    } catch (const std::exception& e) {
      return QString::fromStdString(e.what());
    }
  };

  QProgressDialog progress(tr("Simulating the garments over the clip..."), tr("Cancel"), 0, total, window_);
  progress.setWindowModality(Qt::WindowModal);
  progress.setMinimumDuration(0);
  connect(&progress, &QProgressDialog::canceled, this, [this] { cancelBake_ = true; });
  QFutureWatcher<QString> watcher;
  QEventLoop loop;
  connect(&watcher, &QFutureWatcher<QString>::finished, &loop, &QEventLoop::quit);
  QTimer poll;
  connect(&poll, &QTimer::timeout, this, [&] {
    progress.setValue(done);
    window_->showProgress(tr("Baking garments"), total > 0 ? 100 * done / total : -1);
  });
  poll.start(50);
  watcher.setFuture(QtConcurrent::run(work));
  if (!watcher.isFinished()) loop.exec();
  poll.stop();
  const QString error = watcher.result();
  baking_ = false;
  progress.reset();

  // What was sewn or draped is kept, even when the bake was cancelled later.
  for (BakeGarment& g : garments) {
    if (g.sewn && !g.sewnState)
      ++reusedSewings_;
    else
      ++sewingRuns_;
    if (g.sewnState) keepState(g.sewnKey, std::move(*g.sewnState));
    if (g.drapedState) keepState(g.drapedKey, std::move(*g.drapedState));
  }

  if (!error.isEmpty()) {
    keepPreviousBake();
    lastError_ = tr("The bake stopped: %1").arg(error);
    window_->hideProgress(lastError_);
    emit simulationChanged();
    return false;
  }
  if (cancelBake_) {
    keepPreviousBake();
    lastError_ = tr("Bake cancelled");
    window_->hideProgress(tr("Garment bake cancelled"));
    emit simulationChanged();
    return false;
  }
  result->key = bakeKey(clip, start, frames);
  bake_ = std::move(result);
  bakeOutOfDate_.clear();
  lastBakeSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  bakeRate_.measured(vertexSteps, clock.seconds[0] + clock.seconds[1] + clock.seconds[2]);
  for (int phase = 0; phase < 3; ++phase) lastBakePhases_[phase] = clock.seconds[phase];
  window_->hideProgress(tr("Garments baked: %1 frames in %2 s (sewing %3 s, draping %4 s, frames %5 s)")
                            .arg(frames)
                            .arg(lastBakeSeconds_, 0, 'f', 1)
                            .arg(clock.seconds[0], 0, 'f', 1)
                            .arg(clock.seconds[1], 0, 'f', 1)
                            .arg(clock.seconds[2], 0, 'f', 1));
  showGarments();
  emit simulationChanged();
  return true;
}

// ---- Vertex selection ----

QPointF GarmentTool::toWidget(const glm::vec3& world) const {
  vtkRenderer* renderer = window_->sceneView()->renderer();
  VtkViewportWidget* viewport = window_->viewport();
  const double aspect = renderer->GetTiledAspectRatio();
  vtkMatrix4x4* m = renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect, -1, 1);
  double in[4] = {world.x, world.y, world.z, 1.0}, out[4];
  m->MultiplyPoint(in, out);
  if (out[3] <= 0.0) return QPointF(-1e9, -1e9);
  const double x = out[0] / out[3], y = out[1] / out[3];
  return QPointF((x + 1.0) * 0.5 * viewport->width(), (1.0 - y) * 0.5 * viewport->height());
}

void GarmentTool::setSelectedVertices(std::vector<uint32_t> vertices) {
  selection_ = sortedUnique(std::move(vertices));
  showGarments();
  emit selectionChanged();
}

void GarmentTool::selectInRect(const QRect& rect, SelectOp op) {
  if (current_ < 0 || current_ >= int(views_.size())) return;
  const View& view = *views_[current_];
  const std::vector<float>& p = view.positions;
  std::vector<float> normals;
  computeVertexNormals(p, view.mesh.triangles, normals);
  vtkCamera* camera = window_->sceneView()->renderer()->GetActiveCamera();
  double eye[3];
  camera->GetPosition(eye);
  std::vector<uint32_t> hits;
  const QRectF area = QRectF(rect).normalized();
  for (size_t v = 0; v < p.size() / 3; ++v) {
    const glm::vec3 x(p[3 * v], p[3 * v + 1], p[3 * v + 2]);
    const glm::vec3 toEye = glm::vec3(eye[0], eye[1], eye[2]) - x;
    const glm::vec3 n(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
    if (glm::dot(n, toEye) < 0.0f) continue;  // faces away: on the far side
    if (area.contains(toWidget(x))) hits.push_back(uint32_t(v));
  }
  std::vector<uint32_t> result;
  if (op == SelectOp::Replace) {
    result = hits;
  } else if (op == SelectOp::Add) {
    result = selection_;
    result.insert(result.end(), hits.begin(), hits.end());
  } else {
    std::set_difference(selection_.begin(), selection_.end(), hits.begin(), hits.end(), std::back_inserter(result));
  }
  setSelectedVertices(result);
}

void GarmentTool::setSelectMode(bool on) {
  selectMode_ = on;
  colliderDrag_->updateGizmo();  // the gizmo stands aside for the rubber band
  window_->viewport()->setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
  emit selectionChanged();
}

bool GarmentTool::eventFilter(QObject* watched, QEvent* event) {
  if (watched != window_->viewport() || current_ < 0) return false;
  return routeMouseEvent(this, event, &GarmentTool::onPress, &GarmentTool::onMove, &GarmentTool::onRelease);
}

// Rubber band: a plain left drag in select mode, or Ctrl+Alt+left drag at
// any time (Shift adds to the selection, Ctrl removes in select mode).
bool GarmentTool::onPress(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return false;
  const Qt::KeyboardModifiers mods = event->modifiers();
  const bool chord = (mods & Qt::ControlModifier) && (mods & Qt::AltModifier);
  if (!selectMode_ && !chord) return false;
  dragging_ = true;
  dragStart_ = event->position().toPoint();
  rubberBand_->setGeometry(QRect(dragStart_, QSize()));
  rubberBand_->show();
  return true;
}

bool GarmentTool::onMove(QMouseEvent* event) {
  if (!dragging_) return false;
  rubberBand_->setGeometry(QRect(dragStart_, event->position().toPoint()).normalized());
  return true;
}

bool GarmentTool::onRelease(QMouseEvent* event) {
  if (!dragging_ || event->button() != Qt::LeftButton) return false;
  dragging_ = false;
  rubberBand_->hide();
  QRect rect = QRect(dragStart_, event->position().toPoint()).normalized();
  if (rect.width() < 4 && rect.height() < 4) rect = QRect(rect.center() - QPoint(6, 6), QSize(13, 13));  // a click
  const Qt::KeyboardModifiers mods = event->modifiers();
  const bool chord = (mods & Qt::ControlModifier) && (mods & Qt::AltModifier);
  SelectOp op = SelectOp::Replace;
  if (mods & Qt::ShiftModifier)
    op = SelectOp::Add;
  else if ((mods & Qt::ControlModifier) && !chord)
    op = SelectOp::Remove;
  selectInRect(rect, op);
  return true;
}

}  // namespace mq::ui
