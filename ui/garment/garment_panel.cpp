#include "ui/garment/garment_panel.h"

#include <cmath>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include "core/garment/fabric.h"
#include "core/garment/garment.h"
#include "core/garment/parametric_garments.h"
#include "ui/garment/garment_edit_command.h"
#include "ui/garment/garment_tool.h"

namespace mq::ui {

namespace {

// Fabric values as the panel shows them: in units that keep the numbers readable.
struct FabricField {
  const char* label;
  float Fabric::*member;
  double scale;  // shown = value * scale
  double min, max, step;
  int decimals;
  const char* help;
};

const FabricField kFabricFields[] = {
    {"Mass (kg/m²)", &Fabric::massPerArea, 1.0, 0.01, 3.0, 0.01, 3, "Mass per unit area"},
    {"Stretch (kN/m)", &Fabric::stretchStiffness, 1e-3, 0.01, 1000.0, 1.0, 2, "Membrane tension per unit strain"},
    {"Shear (N/m)", &Fabric::shearStiffness, 1.0, 0.01, 10000.0, 5.0, 2, "In-plane shear stiffness per radian"},
    {"Bend (µN·m)", &Fabric::bendStiffness, 1e6, 0.001, 100000.0, 1.0, 3,
     "Bending moment per unit width per unit curvature"},
    {"Damping (ms)", &Fabric::damping, 1e3, 0.0, 100.0, 0.5, 3,
     "Rayleigh damping: spring damping = damping x stiffness"},
    {"Friction", &Fabric::friction, 1.0, 0.0, 2.0, 0.05, 2, "Coulomb coefficient against the body"},
    {"Thickness (mm)", &Fabric::thickness, 1e3, 0.01, 10.0, 0.05, 2, "Cloth thickness"},
};

const cloth::IntegratorKind kIntegrators[] = {cloth::IntegratorKind::ImplicitEuler,
                                              cloth::IntegratorKind::SymplecticEuler, cloth::IntegratorKind::Verlet,
                                              cloth::IntegratorKind::RK4};

QString integratorLabel(cloth::IntegratorKind kind) {
  switch (kind) {
    case cloth::IntegratorKind::ImplicitEuler:
      return QObject::tr("Implicit Euler (stable, default)");
    case cloth::IntegratorKind::SymplecticEuler:
      return QObject::tr("Symplectic Euler");
    case cloth::IntegratorKind::Verlet:
      return QObject::tr("Verlet");
    default:
      return QObject::tr("Runge-Kutta 4");
  }
}

QString typeLabel(const std::string& type) {
  if (type == "tshirt") return QObject::tr("T-shirt");
  if (type == "skirt") return QObject::tr("Skirt");
  if (type == "trousers") return QObject::tr("Trousers");
  return QString::fromStdString(type);
}

}  // namespace

GarmentPanel::GarmentPanel(GarmentTool* tool, QWidget* parent) : QWidget(parent), tool_(tool) {
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  auto* scroll = new QScrollArea;
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  auto* content = new QWidget;
  auto* layout = new QVBoxLayout(content);
  scroll->setWidget(content);
  outer->addWidget(scroll);

  buildGarmentGroup(layout);
  buildMeasurementGroup(layout);
  buildFabricGroup(layout);
  buildSimulationGroup(layout);
  buildPinGroup(layout);
  buildColliderGroup(layout);
  buildDisplayGroup(layout);

  status_ = new QLabel;
  status_->setWordWrap(true);
  layout->addWidget(status_);
  layout->addStretch(1);

  connect(tool_, &GarmentTool::sceneChanged, this, &GarmentPanel::refresh);
  connect(tool_, &GarmentTool::currentGarmentChanged, this, &GarmentPanel::refresh);
  connect(tool_, &GarmentTool::selectionChanged, this, &GarmentPanel::refreshStatus);
  connect(tool_, &GarmentTool::simulationChanged, this, &GarmentPanel::refreshStatus);
  refresh();
}

// The garment list, add and remove, the layer.
void GarmentPanel::buildGarmentGroup(QVBoxLayout* layout) {
  auto* garments = new QGroupBox(tr("Garments"));
  auto* garmentLayout = new QVBoxLayout(garments);
  list_ = new QListWidget;
  list_->setMaximumHeight(90);
  garmentLayout->addWidget(list_);
  auto* addRow = new QHBoxLayout;
  typeCombo_ = new QComboBox;
  for (const std::string& type : parametricGarmentTypes())
    typeCombo_->addItem(typeLabel(type), QString::fromStdString(type));
  add_ = new QPushButton(tr("Add"));
  add_->setToolTip(tr("Add a built-in garment sized to the character"));
  remove_ = new QPushButton(tr("Remove"));
  pattern_ = new QPushButton(tr("Pattern"));
  pattern_->setToolTip(
      tr("Export the garment's sewing pattern as SVG or DXF at 1:1 (millimetres), or import a DXF pattern"));
  addRow->addWidget(typeCombo_, 1);
  addRow->addWidget(add_);
  addRow->addWidget(remove_);
  addRow->addWidget(pattern_);
  garmentLayout->addLayout(addRow);
  auto* patternMenu = new QMenu(pattern_);
  patternMenu->addAction(tr("Show the pattern"), this, [this] { tool_->showPatternDock(); });
  patternMenu->addSeparator();
  const auto exportPattern = [this](const QString& filter, float seamAllowance) {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the sewing pattern"), QString(), filter);
    if (!path.isEmpty() && !tool_->exportPattern(tool_->currentGarment(), path, seamAllowance))
      QMessageBox::warning(this, tr("Export pattern"), tool_->lastError());
  };
  const QString svg = tr("SVG pattern (*.svg)"), dxf = tr("DXF pattern, AAMA layers (*.dxf)");
  patternExports_ = {
      patternMenu->addAction(tr("SVG, sewing lines..."), this, [=] { exportPattern(svg, 0.0f); }),
      patternMenu->addAction(tr("SVG with a 1 cm seam allowance..."), this, [=] { exportPattern(svg, 0.01f); }),
      patternMenu->addAction(tr("DXF, sewing lines..."), this, [=] { exportPattern(dxf, 0.0f); }),
      patternMenu->addAction(tr("DXF with a 1 cm seam allowance..."), this, [=] { exportPattern(dxf, 0.01f); })};
  patternMenu->addSeparator();
  patternMenu->addAction(tr("Import a DXF pattern..."), this, [this, dxf] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Import a sewing pattern"), QString(), dxf);
    if (!path.isEmpty() && !tool_->importPattern(path))
      QMessageBox::warning(this, tr("Import pattern"), tool_->lastError());
  });
  pattern_->setMenu(patternMenu);
  auto* layerForm = new QFormLayout;
  layer_ = new QSpinBox;
  layer_->setRange(0, Garment::kMaxLayer);
  layer_->setKeyboardTracking(false);
  layer_->setToolTip(
      tr("Worn over the garments of lower layers (and those above it in the list on the same "
         "layer): it collides with them, they do not feel it"));
  layerForm->addRow(tr("Layer"), layer_);
  garmentLayout->addLayout(layerForm);
  connect(layer_, &QSpinBox::valueChanged, this, [this](int layer) {
    if (!refreshing_) tool_->setLayer(tool_->currentGarment(), layer);
  });
  layout->addWidget(garments);
  connect(add_, &QPushButton::clicked, this,
          [this] { tool_->addGarment(typeCombo_->currentData().toString().toStdString()); });
  connect(remove_, &QPushButton::clicked, this, [this] { tool_->removeGarment(tool_->currentGarment()); });
  connect(list_, &QListWidget::currentRowChanged, this, [this](int row) {
    if (!refreshing_) tool_->setCurrentGarment(row);
  });
}

// The measurements (rebuilt per garment type) and the particle distance.
void GarmentPanel::buildMeasurementGroup(QVBoxLayout* layout) {
  auto* measurementBox = new QGroupBox(tr("Measurements"));
  auto* measurementLayout = new QVBoxLayout(measurementBox);
  measurements_ = new QWidget;
  measurementForm_ = new QFormLayout(measurements_);
  measurementForm_->setContentsMargins(0, 0, 0, 0);
  measurementLayout->addWidget(measurements_);
  auto* resolutionForm = new QFormLayout;
  particleDistance_ = new QDoubleSpinBox;
  particleDistance_->setRange(5.0, 100.0);
  particleDistance_->setDecimals(1);
  particleDistance_->setSingleStep(1.0);
  particleDistance_->setSuffix(tr(" mm"));
  particleDistance_->setKeyboardTracking(false);
  particleDistance_->setToolTip(tr("Edge length of the cloth mesh: smaller is finer and slower (clears the pins)"));
  resolutionForm->addRow(tr("Particle distance"), particleDistance_);
  measurementLayout->addLayout(resolutionForm);
  layout->addWidget(measurementBox);
  connect(particleDistance_, &QDoubleSpinBox::valueChanged, this, [this](double mm) {
    if (refreshing_) return;
    tool_->setParticleDistance(tool_->currentGarment(), float(mm / 1000.0), mergeKeyFor(50));
  });
}

// The fabric preset and its fields (kFabricFields).
void GarmentPanel::buildFabricGroup(QVBoxLayout* layout) {
  auto* fabricBox = new QGroupBox(tr("Fabric"));
  auto* fabricForm = new QFormLayout(fabricBox);
  fabricCombo_ = new QComboBox;
  for (const std::string& name : fabricPresetNames()) fabricCombo_->addItem(QString::fromStdString(name));
  fabricCombo_->addItem(tr("(custom)"));
  fabricForm->addRow(tr("Preset"), fabricCombo_);
  connect(fabricCombo_, &QComboBox::activated, this, [this](int index) {
    if (index < fabricCombo_->count() - 1)
      tool_->setFabricPreset(tool_->currentGarment(), fabricCombo_->itemText(index).toStdString());
  });
  for (size_t f = 0; f < std::size(kFabricFields); ++f) {
    const FabricField& field = kFabricFields[f];
    auto* spin = new QDoubleSpinBox;
    spin->setRange(field.min, field.max);
    spin->setSingleStep(field.step);
    spin->setDecimals(field.decimals);
    spin->setKeyboardTracking(false);
    spin->setToolTip(tr(field.help));
    fabricForm->addRow(tr(field.label), spin);
    fabricFields_.push_back(spin);
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this, f](double shown) {
      editFabric(
          int(f) + 100,
          [f](Fabric& fabric, double v) { fabric.*(kFabricFields[f].member) = float(v / kFabricFields[f].scale); },
          shown);
    });
  }
  layout->addWidget(fabricBox);
}

// The integrator, self collisions, frames, and Simulate, Bake, Export and Reset.
void GarmentPanel::buildSimulationGroup(QVBoxLayout* layout) {
  auto* simBox = new QGroupBox(tr("Simulation"));
  auto* simLayout = new QVBoxLayout(simBox);
  auto* simForm = new QFormLayout;
  integratorCombo_ = new QComboBox;
  for (cloth::IntegratorKind kind : kIntegrators) integratorCombo_->addItem(integratorLabel(kind));
  simForm->addRow(tr("Integrator"), integratorCombo_);
  selfCollisions_ = new QCheckBox(tr("Self collisions"));
  simForm->addRow(QString(), selfCollisions_);
  clothFps_ = new QSpinBox;
  clothFps_->setRange(1, 240);
  clothFps_->setSuffix(tr(" fps"));
  clothFps_->setKeyboardTracking(false);
  clothFps_->setToolTip(tr("Cloth steps per second of the clip (Simulate and Bake); baked frames at this rate"));
  simForm->addRow(tr("Cloth frames"), clothFps_);
  connect(clothFps_, &QSpinBox::valueChanged, this, [this](int fps) {
    if (refreshing_) return;
    tool_->setClothFps(float(fps), mergeKeyFor(51));
  });
  bakeFrames_ = new QSpinBox;
  bakeFrames_->setRange(1, 100000);
  bakeFrames_->setSuffix(tr(" frames"));
  bakeFrames_->setKeyboardTracking(false);
  bakeFrames_->setToolTip(
      tr("With no character there is no clip to follow: Bake simulates this many frames "
         "(at the cloth's fps) from the placed cloth; the timeline scrubs them"));
  simForm->addRow(tr("Bake length"), bakeFrames_);
  connect(bakeFrames_, &QSpinBox::valueChanged, this, [this](int frames) {
    if (refreshing_) return;
    tool_->setBakeFrames(frames, mergeKeyFor(52));
  });
  simForm->setRowVisible(bakeFrames_, false);
  simForm_ = simForm;
  simLayout->addLayout(simForm);
  connect(integratorCombo_, &QComboBox::activated, this,
          [this](int index) { tool_->setIntegrator(kIntegrators[index]); });
  connect(selfCollisions_, &QCheckBox::toggled, this, [this](bool on) {
    if (!refreshing_) tool_->setSelfCollisions(on);
  });
  auto* simButtons = new QHBoxLayout;
  simulate_ = new QPushButton(tr("Simulate"));
  simulate_->setCheckable(true);
  // Running is obvious at a glance: a red button that says how to stop it.
  simulate_->setStyleSheet("QPushButton:checked { background-color: #b03a2e; color: white; font-weight: bold; }");
  simulate_->setToolTip(tr("Simulate live while the clip plays (press Space to play)"));
  bake_ = new QPushButton(tr("Bake clip"));
  bake_->setToolTip(tr("Simulate the whole clip; the timeline then scrubs the baked frames"));
  clearBake_ = new QPushButton(tr("Clear bake"));
  exportBake_ = new QPushButton(tr("Export bake..."));
  exportBake_->setToolTip(
      tr("Write the baked frames into a folder: OBJ sequences (one file per frame per garment) "
         "or Point Cache 2 files (one .pc2 per garment and the mesh it deforms)"));
  resetDrapes_ = new QPushButton(tr("Reset drape"));
  resetDrapes_->setToolTip(
      tr("Back to the flat placed panels: the next Simulate or Bake sews the garments anew "
         "(edits otherwise keep the drape on screen and continue from it)"));
  for (QPushButton* b : {simulate_, bake_, clearBake_}) simButtons->addWidget(b);
  simLayout->addLayout(simButtons);
  auto* moreButtons = new QHBoxLayout;
  moreButtons->addWidget(exportBake_);
  moreButtons->addWidget(resetDrapes_);
  simLayout->addLayout(moreButtons);
  connect(simulate_, &QPushButton::toggled, this, [this](bool on) {
    if (!refreshing_) tool_->setSimulating(on);
  });
  connect(bake_, &QPushButton::clicked, this, [this] { tool_->bake(-1.0f, -1.0f, /*askIfLong=*/true); });
  connect(clearBake_, &QPushButton::clicked, this, [this] { tool_->clearBake(); });
  connect(resetDrapes_, &QPushButton::clicked, this, [this] { tool_->resetDrapes(); });
  auto* exportMenu = new QMenu(exportBake_);
  const auto exportInto = [this](bool pointCache) {
    const QString dir = QFileDialog::getExistingDirectory(
        this, pointCache ? tr("Export the bake as point caches into") : tr("Export the bake as OBJ sequences into"));
    if (!dir.isEmpty() && !tool_->exportBake(dir, pointCache))
      QMessageBox::warning(this, tr("Export bake"), tool_->lastError());
  };
  exportMenu->addAction(tr("OBJ sequence (one file per frame)..."), this, [exportInto] { exportInto(false); });
  exportMenu->addAction(tr("Point Cache 2 (.pc2, Blender's Mesh Cache)..."), this, [exportInto] { exportInto(true); });
  exportBake_->setMenu(exportMenu);
  layout->addWidget(simBox);
}

// Vertex selection and pins.
void GarmentPanel::buildPinGroup(QVBoxLayout* layout) {
  auto* pinBox = new QGroupBox(tr("Pins"));
  auto* pinLayout = new QVBoxLayout(pinBox);
  select_ = new QPushButton(tr("Select vertices"));
  select_->setCheckable(true);
  select_->setToolTip(
      tr("Drag a rectangle in the viewport: Shift adds, Ctrl removes.\n"
         "Ctrl+Alt+drag selects without this mode."));
  pin_ = new QPushButton(tr("Pin selected"));
  unpin_ = new QPushButton(tr("Unpin"));
  clearPins_ = new QPushButton(tr("Clear"));
  auto* pinButtons = new QHBoxLayout;
  for (QPushButton* b : {pin_, unpin_, clearPins_}) pinButtons->addWidget(b);
  pinLayout->addWidget(select_);
  pinLayout->addLayout(pinButtons);
  attach_ = new QComboBox;
  attach_->addItem(tr("Follow the body"));
  attach_->addItem(tr("Fixed in space"));
  auto* attachForm = new QFormLayout;
  attachForm->addRow(tr("Pins"), attach_);
  pinLayout->addLayout(attachForm);
  pinStatus_ = new QLabel;
  pinLayout->addWidget(pinStatus_);
  connect(select_, &QPushButton::toggled, this, [this](bool on) { tool_->setSelectMode(on); });
  connect(pin_, &QPushButton::clicked, this, [this] { tool_->pinSelected(); });
  connect(unpin_, &QPushButton::clicked, this, [this] { tool_->unpinSelected(); });
  connect(clearPins_, &QPushButton::clicked, this, [this] { tool_->clearPins(); });
  connect(attach_, &QComboBox::activated, this,
          [this](int index) { tool_->setPinsFollowBody(tool_->currentGarment(), index == 0); });
  layout->addWidget(pinBox);
}

// Overlays.
void GarmentPanel::buildDisplayGroup(QVBoxLayout* layout) {
  auto* displayBox = new QGroupBox(tr("Display"));
  auto* displayLayout = new QVBoxLayout(displayBox);
  stretch_ = new QCheckBox(tr("Stretch overlay (grey 1.0 to red 1.1)"));
  showPins_ = new QCheckBox(tr("Show pins and selection"));
  showPins_->setChecked(true);
  displayLayout->addWidget(stretch_);
  displayLayout->addWidget(showPins_);
  showColliders_ = new QCheckBox(tr("Show colliders"));
  showColliders_->setChecked(true);
  displayLayout->addWidget(showColliders_);
  connect(showColliders_, &QCheckBox::toggled, tool_, &GarmentTool::setCollidersVisible);
  connect(stretch_, &QCheckBox::toggled, tool_, &GarmentTool::setStretchVisible);
  connect(showPins_, &QCheckBox::toggled, tool_, &GarmentTool::setPinsVisible);
  layout->addWidget(displayBox);
}

int GarmentPanel::mergeKeyFor(int field) {
  if (lastField_ != field) lastMergeKey_ = GarmentEditCommand::nextMergeKey();
  lastField_ = field;
  return lastMergeKey_;
}

QDoubleSpinBox* GarmentPanel::measurementField(const QString& name) const {
  for (QDoubleSpinBox* spin : measurementFields_)
    if (spin->objectName() == name) return spin;
  return nullptr;
}

void GarmentPanel::refresh() {
  refreshing_ = true;
  const GarmentScene& scene = tool_->scene();
  const int current = tool_->currentGarment();
  {
    const QSignalBlocker block(list_);
    list_->clear();
    for (const Garment& g : scene.garments)
      list_->addItem(tr("%1 (layer %2)").arg(QString::fromStdString(g.name)).arg(g.layer));
    list_->setCurrentRow(current);
  }
  remove_->setEnabled(current >= 0);
  for (QAction* action : patternExports_) action->setEnabled(current >= 0);
  particleDistance_->setEnabled(current >= 0);
  layer_->setEnabled(current >= 0);
  if (current >= 0) {
    const QSignalBlocker block(layer_);
    layer_->setValue(scene.garments[current].layer);
  }
  if (current >= 0) {
    const QSignalBlocker block(particleDistance_);
    particleDistance_->setValue(scene.garments[current].targetEdgeLength * 1000.0);
  }
  rebuildMeasurements();
  refreshFabric();
  {
    const QSignalBlocker block(integratorCombo_);
    for (int i = 0; i < int(std::size(kIntegrators)); ++i)
      if (kIntegrators[i] == scene.cloth.settings.integrator) integratorCombo_->setCurrentIndex(i);
  }
  selfCollisions_->setChecked(scene.cloth.settings.selfCollisions);
  {
    const QSignalBlocker block(clothFps_);
    clothFps_->setValue(int(std::lround(scene.cloth.fps)));
  }
  {
    const QSignalBlocker block(bakeFrames_);
    bakeFrames_->setValue(scene.cloth.bakeFrames);
  }
  simForm_->setRowVisible(bakeFrames_, tool_->bakesWithoutClip());
  bake_->setText(tool_->bakesWithoutClip() ? tr("Bake") : tr("Bake clip"));
  bake_->setToolTip(
      tool_->bakesWithoutClip()
          ? tr("Simulate the bake length from the placed cloth; the timeline then scrubs the baked frames")
          : tr("Simulate the whole clip; the timeline then scrubs the baked frames"));
  {
    const QSignalBlocker block(attach_);
    attach_->setCurrentIndex(current >= 0 && scene.garments[current].pins.attach == GarmentPins::Attach::Space ? 1 : 0);
  }
  refreshColliders();
  refreshing_ = false;
  refreshStatus();
}

// One field per measurement of the current garment's type; the fields are
// rebuilt when the garment (or its type) changes, else only their values.
void GarmentPanel::rebuildMeasurements() {
  const int current = tool_->currentGarment();
  const GarmentScene& scene = tool_->scene();
  const QString type = current >= 0 ? QString::fromStdString(scene.garments[current].recipe.type) : QString();
  if (current != measuredGarment_ || type != measuredType_) {
    while (measurementForm_->rowCount() > 0) measurementForm_->removeRow(0);
    measurementFields_.clear();
    measuredGarment_ = current;
    measuredType_ = type;
    if (!type.isEmpty()) {
      for (const GarmentParameter& p : garmentParameters(type.toStdString())) {
        auto* spin = new QDoubleSpinBox;
        spin->setObjectName(QString::fromStdString(p.name));
        spin->setRange(p.min, p.max);
        spin->setDecimals(3);
        spin->setSingleStep(0.01);
        spin->setSuffix(tr(" m"));
        spin->setKeyboardTracking(false);
        spin->setToolTip(QString::fromStdString(p.help));
        const std::string name = p.name;
        connect(spin, &QDoubleSpinBox::valueChanged, this,
                [this, name, index = int(measurementFields_.size())](double v) {
                  if (refreshing_) return;
                  tool_->setMeasurement(tool_->currentGarment(), name, float(v), mergeKeyFor(index + 1));
                });
        auto* label = new QLabel(QString::fromStdString(p.name).replace('_', ' '));
        label->setToolTip(QString::fromStdString(p.help));
        measurementForm_->addRow(label, spin);
        measurementFields_.push_back(spin);
      }
    } else if (current >= 0) {
      measurementForm_->addRow(new QLabel(tr("Hand-made panels: no measurements")));
    } else {
      measurementForm_->addRow(new QLabel(tr("Add a garment to edit it")));
    }
  }
  if (current < 0 || type.isEmpty()) return;
  const auto& values = scene.garments[current].recipe.parameters;
  const auto parameters = garmentParameters(type.toStdString());
  for (size_t i = 0; i < parameters.size() && i < measurementFields_.size(); ++i) {
    const auto found = values.find(parameters[i].name);
    const QSignalBlocker block(measurementFields_[i]);
    measurementFields_[i]->setValue(found != values.end() ? found->second : parameters[i].value);
  }
}

void GarmentPanel::refreshFabric() {
  const int current = tool_->currentGarment();
  fabricCombo_->setEnabled(current >= 0);
  for (QDoubleSpinBox* spin : fabricFields_) spin->setEnabled(current >= 0);
  if (current < 0) return;
  const Garment& g = tool_->scene().garments[current];
  const Fabric values = g.solverFabric();
  {
    const QSignalBlocker block(fabricCombo_);
    const int preset = fabricCombo_->findText(QString::fromStdString(g.fabric));
    fabricCombo_->setCurrentIndex(fabricIsPreset(g) && preset >= 0 ? preset : fabricCombo_->count() - 1);
  }
  for (size_t f = 0; f < fabricFields_.size(); ++f) {
    const QSignalBlocker block(fabricFields_[f]);
    fabricFields_[f]->setValue(values.*(kFabricFields[f].member) * kFabricFields[f].scale);
  }
}

void GarmentPanel::editFabric(int field, const std::function<void(Fabric&, double)>& change, double value) {
  const int current = tool_->currentGarment();
  if (refreshing_ || current < 0) return;
  Fabric fabric = tool_->scene().garments[current].solverFabric();
  change(fabric, value);
  tool_->setFabric(current, fabric, mergeKeyFor(field));
}

// ---- Colliders ----

namespace {

constexpr cloth::PrimitiveCollider::Shape kShapes[] = {cloth::PrimitiveCollider::Shape::Sphere,
                                                       cloth::PrimitiveCollider::Shape::Capsule,
                                                       cloth::PrimitiveCollider::Shape::Plane};

QString colliderLabel(const cloth::PrimitiveCollider& c, int index) {
  const glm::vec3& p = c.a;
  const QString at = QString("(%1, %2, %3)").arg(p.x, 0, 'f', 2).arg(p.y, 0, 'f', 2).arg(p.z, 0, 'f', 2);
  switch (c.shape) {
    case cloth::PrimitiveCollider::Shape::Sphere:
      return QObject::tr("%1. Sphere r %2 at %3").arg(index + 1).arg(c.radius, 0, 'f', 2).arg(at);
    case cloth::PrimitiveCollider::Shape::Capsule:
      return QObject::tr("%1. Capsule r %2 from %3").arg(index + 1).arg(c.radius, 0, 'f', 2).arg(at);
    default:
      return QObject::tr("%1. Plane through %2").arg(index + 1).arg(at);
  }
}

}  // namespace

void GarmentPanel::buildColliderGroup(QVBoxLayout* layout) {
  auto* box = new QGroupBox(tr("Colliders"));
  box->setToolTip(tr("Spheres, capsules and planes the cloth collides with (besides the character)"));
  auto* boxLayout = new QVBoxLayout(box);
  colliderList_ = new QListWidget;
  colliderList_->setMaximumHeight(80);
  boxLayout->addWidget(colliderList_);
  auto* addRow = new QHBoxLayout;
  colliderShape_ = new QComboBox;
  colliderShape_->addItem(tr("Sphere"));
  colliderShape_->addItem(tr("Capsule"));
  colliderShape_->addItem(tr("Plane"));
  addCollider_ = new QPushButton(tr("Add"));
  addCollider_->setToolTip(tr("Add a collider near the character (or under the sheet)"));
  removeCollider_ = new QPushButton(tr("Remove"));
  addRow->addWidget(colliderShape_, 1);
  addRow->addWidget(addCollider_);
  addRow->addWidget(removeCollider_);
  boxLayout->addLayout(addRow);
  connect(addCollider_, &QPushButton::clicked, this,
          [this] { tool_->addCollider(kShapes[colliderShape_->currentIndex()]); });
  connect(removeCollider_, &QPushButton::clicked, this, [this] { tool_->removeCollider(tool_->currentCollider()); });
  connect(colliderList_, &QListWidget::currentRowChanged, this, [this](int row) {
    if (!refreshing_) tool_->setCurrentCollider(row);
  });

  colliderForm_ = new QFormLayout;
  for (int vector = 0; vector < 2; ++vector) {
    auto* row = new QHBoxLayout;
    for (int axis = 0; axis < 3; ++axis) {
      auto* spin = new QDoubleSpinBox;
      spin->setRange(-100.0, 100.0);
      spin->setDecimals(3);
      spin->setSingleStep(0.01);
      spin->setKeyboardTracking(false);
      spin->setPrefix(QString("xyz"[axis]) + " ");
      spin->setButtonSymbols(QAbstractSpinBox::NoButtons);  // three in a row: keep the dock narrow
      spin->setMinimumWidth(40);
      connect(spin, &QDoubleSpinBox::valueChanged, this,
              [this, vector, axis] { editCollider(300 + 3 * vector + axis); });
      colliderVectors_[vector][axis] = spin;
      row->addWidget(spin);
    }
    colliderForm_->addRow(vector == 0 ? tr("Centre") : tr("End B"), row);
  }
  colliderRadius_ = new QDoubleSpinBox;
  colliderRadius_->setRange(0.001, 10.0);
  colliderRadius_->setDecimals(3);
  colliderRadius_->setSingleStep(0.01);
  colliderRadius_->setSuffix(tr(" m"));
  colliderRadius_->setKeyboardTracking(false);
  colliderForm_->addRow(tr("Radius"), colliderRadius_);
  colliderFriction_ = new QDoubleSpinBox;
  colliderFriction_->setRange(-0.05, 2.0);
  colliderFriction_->setSingleStep(0.05);
  colliderFriction_->setDecimals(2);
  colliderFriction_->setSpecialValueText(tr("the cloth's"));
  colliderFriction_->setKeyboardTracking(false);
  colliderFriction_->setToolTip(tr("Coulomb friction against this collider; lowest value: the cloth's own friction"));
  colliderForm_->addRow(tr("Friction"), colliderFriction_);
  connect(colliderRadius_, &QDoubleSpinBox::valueChanged, this, [this] { editCollider(306); });
  connect(colliderFriction_, &QDoubleSpinBox::valueChanged, this, [this] { editCollider(307); });
  boxLayout->addLayout(colliderForm_);
  layout->addWidget(box);
}

void GarmentPanel::refreshColliders() {
  const auto& colliders = tool_->scene().cloth.colliders;
  const int current = tool_->currentCollider();
  {
    const QSignalBlocker block(colliderList_);
    colliderList_->clear();
    for (size_t i = 0; i < colliders.size(); ++i) colliderList_->addItem(colliderLabel(colliders[i], int(i)));
    colliderList_->setCurrentRow(current);
  }
  removeCollider_->setEnabled(current >= 0);
  const bool has = current >= 0 && current < int(colliders.size());
  const cloth::PrimitiveCollider c = has ? colliders[current] : cloth::PrimitiveCollider{};
  const bool plane = c.shape == cloth::PrimitiveCollider::Shape::Plane;
  const bool capsule = c.shape == cloth::PrimitiveCollider::Shape::Capsule;
  if (auto* label = qobject_cast<QLabel*>(colliderForm_->itemAt(0, QFormLayout::LabelRole)->widget()))
    label->setText(plane ? tr("Point") : capsule ? tr("End A") : tr("Centre"));
  if (auto* label = qobject_cast<QLabel*>(colliderForm_->itemAt(1, QFormLayout::LabelRole)->widget()))
    label->setText(plane ? tr("Normal") : tr("End B"));
  colliderForm_->setRowVisible(0, has);
  colliderForm_->setRowVisible(1, has && (plane || capsule));
  colliderForm_->setRowVisible(2, has && !plane);
  colliderForm_->setRowVisible(3, has);
  if (!has) return;
  for (int vector = 0; vector < 2; ++vector)
    for (int axis = 0; axis < 3; ++axis) {
      const QSignalBlocker block(colliderVectors_[vector][axis]);
      colliderVectors_[vector][axis]->setValue((vector == 0 ? c.a : c.b)[axis]);
    }
  {
    const QSignalBlocker block(colliderRadius_);
    colliderRadius_->setValue(c.radius);
  }
  const QSignalBlocker block(colliderFriction_);
  colliderFriction_->setValue(c.friction < 0.0f ? colliderFriction_->minimum() : c.friction);
}

// The current collider with the fields' values, as one undoable edit (a
// spun or typed field merges into one step).
void GarmentPanel::editCollider(int field) {
  const int current = tool_->currentCollider();
  if (refreshing_ || current < 0) return;
  cloth::PrimitiveCollider c = tool_->scene().cloth.colliders[current];
  for (int axis = 0; axis < 3; ++axis) {
    c.a[axis] = float(colliderVectors_[0][axis]->value());
    if (c.shape != cloth::PrimitiveCollider::Shape::Sphere) c.b[axis] = float(colliderVectors_[1][axis]->value());
  }
  if (c.shape != cloth::PrimitiveCollider::Shape::Plane) c.radius = float(colliderRadius_->value());
  const double friction = colliderFriction_->value();
  c.friction = friction <= colliderFriction_->minimum() ? -1.0f : float(friction);
  if (!tool_->setCollider(current, c, mergeKeyFor(field))) refresh();
}

QString GarmentPanel::statusText() const { return status_->text(); }

void GarmentPanel::refreshStatus() {
  const int current = tool_->currentGarment();
  const bool any = tool_->garmentCount() > 0 || tool_->hasSheet();
  {
    const QSignalBlocker block(simulate_);
    simulate_->setChecked(tool_->simulating());
    simulate_->setText(tool_->simulating() ? tr("Stop simulating") : tr("Simulate"));
  }
  {
    const QSignalBlocker block(select_);
    select_->setChecked(tool_->selectMode());
  }
  {
    const QSignalBlocker block(stretch_);
    stretch_->setChecked(tool_->stretchVisible());
  }
  simulate_->setEnabled(any);
  bake_->setEnabled(any);
  clearBake_->setEnabled(tool_->hasBake());
  resetDrapes_->setEnabled(any);
  exportBake_->setEnabled(tool_->hasBake());
  const size_t selected = tool_->selectedVertices().size();
  const size_t pinned = current >= 0 ? tool_->scene().garments[current].pins.vertices.size() : 0;
  pin_->setEnabled(selected > 0);
  unpin_->setEnabled(selected > 0 && pinned > 0);
  clearPins_->setEnabled(pinned > 0);
  pinStatus_->setText(tr("%1 pinned, %2 selected").arg(pinned).arg(selected));

  QStringList lines;
  if (const GarmentMesh* mesh = tool_->garmentMesh(current))
    lines << tr("%1 vertices, %2 triangles").arg(mesh->vertexCount()).arg(mesh->triangleCount());
  if (tool_->hasBake())
    lines << tr("Baked: %1 frames (scrub the timeline)").arg(tool_->bakedFrameCount());
  else if (!tool_->bakeOutOfDate().isEmpty())
    lines << tr("Bake out of date: %1").arg(tool_->bakeOutOfDate());
  if (tool_->hasSheet()) lines << tr("Sheet: %1 vertices").arg(tool_->shownSheetPositions().size() / 3);
  if (tool_->simulating()) {
    lines << tr("Simulating: %1 steps (%2)").arg(tool_->simulatedSteps()).arg(tool_->simulationPhase());
    // Whether the cloth keeps up with the clip played in real time.
    const double rate = tool_->simulatedFramesPerSecond(), wanted = tool_->scene().cloth.fps;
    if (rate > 0.0)
      lines << (rate + 0.5 >= wanted ? tr("%1 of %2 frames/s: keeps up with playback")
                                     : tr("%1 of %2 frames/s: slower than playback (bake for real time)"))
                   .arg(rate, 0, 'f', 1)
                   .arg(wanted, 0, 'f', 0);
  }
  if (current >= 0 && !tool_->shownStretch(current).empty()) {
    float worst = 1.0f;
    for (float s : tool_->shownStretch(current)) worst = std::max(worst, s);
    if (tool_->simulating() || tool_->hasBake()) lines << tr("Largest stretch: %1").arg(worst, 0, 'f', 3);
  }
  if (!tool_->lastError().isEmpty()) lines << tool_->lastError();
  status_->setText(lines.join('\n'));
}

}  // namespace mq::ui
