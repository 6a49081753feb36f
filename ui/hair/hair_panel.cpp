#include "ui/hair/hair_panel.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QVBoxLayout>

#include "core/hair/hair_groom.h"
#include "core/hair/head_fit.h"
#include "core/optics/hair_bsdf.h"
#include "ui/hair/hair_style_command.h"
#include "ui/hair/hair_tool.h"

namespace mq::ui {

namespace {

enum FieldKey {
  kStrength = 1,
  kRadius,
  kAxisX,
  kAxisY,
  kAxisZ,
  kPosX,
  kPosY,
  kPosZ,
  kDensity,
  kLength,
  kClumping,
  kFrizz,
  kRootColor,
  kTipColor,
  kScalpAxisX,
  kScalpAxisY,
  kScalpAxisZ,
  kScalpAngle,
  kShadingModel,
  kMelanin,
  kPheomelanin,
  kRoughness,
  kPigmentPreset,
  kVolume,
  kHairFriction,
  kAdaptiveWisps
};

// Scalp cone axes (world, rest pose; the character faces +Z).
const glm::vec3 kAxisUp(0.0f, 1.0f, 0.0f);
const glm::vec3 kAxisUpBack(0.0f, 0.906308f, -0.422618f);  // 25 degrees back from up
// A new cone: the top and back of the head, seen from the head bone's origin.
constexpr float kDefaultConeAngle = 60.0f;

bool sameDirection(const glm::vec3& a, const glm::vec3& b) {
  return glm::length(a) > 0.0f && glm::dot(glm::normalize(a), b) > 0.9999f;
}

QString kindName(PrimitiveRef::Kind kind) {
  switch (kind) {
    case PrimitiveRef::Stream:
      return QObject::tr("Stream");
    case PrimitiveRef::Source:
      return QObject::tr("Source");
    default:
      return QObject::tr("Vortex");
  }
}

QColor toQColor(const glm::vec3& c) { return QColor::fromRgbF(c.x, c.y, c.z); }
glm::vec3 fromQColor(const QColor& c) { return {float(c.redF()), float(c.greenF()), float(c.blueF())}; }

void paintSwatch(QPushButton* button, const glm::vec3& color) {
  button->setStyleSheet(QString("background-color: %1;").arg(toQColor(color).name()));
}

}  // namespace

HairPanel::HairPanel(HairTool* tool, QWidget* parent) : QWidget(parent), tool_(tool) {
  auto* layout = new QVBoxLayout(this);

  // Style
  styleCombo_ = new QComboBox;
  styleCombo_->addItem(tr("(no hair)"));
  for (const std::string& name : builtinHairStyleNames()) styleCombo_->addItem(QString::fromStdString(name));
  styleCombo_->addItem(tr("(custom)"));
  styleForm_ = new QFormLayout;
  makeGroomControls();
  layout->addLayout(styleForm_);
  connect(styleCombo_, &QComboBox::activated, this, [this](int index) {
    if (index == 0)
      tool_->removeHair();
    else if (index < styleCombo_->count() - 1)
      tool_->useBuiltinStyle(styleCombo_->itemText(index));
  });

  layout->addWidget(makePrimitiveGroup());
  layout->addWidget(makeStrandGroup());
  layout->addWidget(makeShadingGroup());
  layout->addWidget(makeDynamicsGroup());
  layout->addWidget(makeScalpGroup());

  status_ = new QLabel;
  status_->setWordWrap(true);
  layout->addWidget(status_);
  layout->addStretch(1);

  connect(tool_, &HairTool::styleChanged, this, &HairPanel::refresh);
  // Not a full refresh: the hair arrives while the user may be typing.
  connect(tool_, &HairTool::hairRegrown, this, &HairPanel::refreshStrandCounts);
  connect(tool_, &HairTool::selectionChanged, this, &HairPanel::refresh);
  connect(tool_, &HairTool::scalpChanged, this, &HairPanel::refreshScalp);
  refresh();
}

// The style and, on its row, the grooming brush (so the dock keeps its
// height until a brush is chosen; gui tests select things in screen space).
void HairPanel::makeGroomControls() {
  groomBrush_ = new QComboBox;
  groomBrush_->addItem(tr("No brush"));
  for (const std::string& name : groomBrushNames())
    groomBrush_->addItem(QString::fromStdString(name).replace('_', ' '));
  groomBrush_->setToolTip(
      tr("Groom with a brush: drag over the hair in the viewport. Comb drags it, cut shortens it where the brush "
         "passes, length grows it (Ctrl: shortens), puff lifts it from the scalp, smooth straightens curls, "
         "clump gathers it, frizz roughens it. The paint brushes paint maps over the scalp: the share of the hair "
         "that grows there (density), a length factor, the clumping, the colour as the fibre's pigments "
         "(melanin: less is lighter; pheomelanin: redder). Strokes stay when the flow primitives change."));
  auto* styleRow = new QWidget;
  auto* row = new QHBoxLayout(styleRow);
  row->setContentsMargins(0, 0, 0, 0);
  row->addWidget(styleCombo_, 1);
  row->addWidget(groomBrush_);
  styleForm_->addRow(tr("Hairstyle"), styleRow);

  groomRadius_ = addSpin(0.5, 30.0, 0.5, 1);
  groomRadius_->setSuffix(tr(" cm"));
  groomRadius_->setValue(tool_->groomRadius() * 100.0);
  groomRadius_->setToolTip(tr("The brush's radius around the point under the cursor"));
  groomStrength_ = addSpin(0.05, 1.0, 0.05, 2);
  groomStrength_->setValue(tool_->groomStrength());
  groomStrength_->setToolTip(tr("How strongly each dab of the brush acts (the comb: the share of the drag)"));
  groomValue_ = addSpin(0.0, 10.0, 0.05, 2);
  groomValue_->setValue(tool_->groomValue());
  groomValue_->setToolTip(
      tr("What the paint brush paints: the share of the hair kept (density), a length factor, "
         "the clumping, or a pigment's concentration (0 to 8; blond about 0.3, brown 1.3, black 8). "
         "Ctrl+drag paints the unpainted value back"));
  groomMirror_ = new QCheckBox(tr("Mirror"));
  groomMirror_->setToolTip(tr("Brush both sides of the head at once"));
  clearStrokes_ = new QPushButton(tr("Clear"));
  clearStrokes_->setToolTip(tr("Take every brush stroke away (the flow's hair comes back)"));
  groomSettings_ = new QWidget;
  auto* settings = new QHBoxLayout(groomSettings_);
  settings->setContentsMargins(0, 0, 0, 0);
  settings->addWidget(groomRadius_);
  settings->addWidget(groomStrength_);
  settings->addWidget(groomValue_);
  settings->addWidget(groomMirror_);
  settings->addWidget(clearStrokes_);
  styleForm_->addRow(tr("Brush"), groomSettings_);
  styleForm_->setRowVisible(groomSettings_, false);

  connect(groomBrush_, &QComboBox::currentIndexChanged, this, [this](int index) {
    const bool on = index > 0;
    if (on && scalpPaint_->isChecked()) scalpPaint_->setChecked(false);
    tool_->setGroomBrush(on ? std::optional<GroomBrush>(GroomBrush(index - 1)) : std::nullopt);
    styleForm_->setRowVisible(groomSettings_, on);
    const bool paint = on && isPaintBrush(GroomBrush(index - 1));
    groomValue_->setVisible(paint);
    if (paint) {
      const PaintRange range = paintRange(GroomBrush(index - 1));
      groomValue_->setRange(range.min, range.max);
      tool_->setGroomValue(float(groomValue_->value()));
    }
  });
  connect(groomRadius_, &QDoubleSpinBox::valueChanged, this,
          [this](double cm) { tool_->setGroomRadius(float(cm) / 100.0f); });
  connect(groomStrength_, &QDoubleSpinBox::valueChanged, this, [this](double v) { tool_->setGroomStrength(float(v)); });
  connect(groomMirror_, &QCheckBox::toggled, this, [this](bool on) { tool_->setGroomMirror(on); });
  connect(groomValue_, &QDoubleSpinBox::valueChanged, this, [this](double v) { tool_->setGroomValue(float(v)); });
  connect(clearStrokes_, &QPushButton::clicked, this, [this] { tool_->clearStrokes(); });
}

// The flow primitives: the list, add and delete, the selected one's fields.
QWidget* HairPanel::makePrimitiveGroup() {
  auto* primitives = new QGroupBox(tr("Flow primitives"));
  auto* primitiveLayout = new QVBoxLayout(primitives);
  list_ = new QListWidget;
  list_->setMaximumHeight(130);
  primitiveLayout->addWidget(list_);
  auto* buttons = new QHBoxLayout;
  addStream_ = new QPushButton(tr("+ Stream"));
  addSource_ = new QPushButton(tr("+ Source"));
  addVortex_ = new QPushButton(tr("+ Vortex"));
  delete_ = new QPushButton(tr("Delete"));
  for (QPushButton* b : {addStream_, addSource_, addVortex_, delete_}) buttons->addWidget(b);
  primitiveLayout->addLayout(buttons);
  connect(addStream_, &QPushButton::clicked, this, [this] { addPrimitive(PrimitiveRef::Stream); });
  connect(addSource_, &QPushButton::clicked, this, [this] { addPrimitive(PrimitiveRef::Source); });
  connect(addVortex_, &QPushButton::clicked, this, [this] { addPrimitive(PrimitiveRef::Vortex); });
  connect(delete_, &QPushButton::clicked, this, &HairPanel::deleteSelected);
  connect(list_, &QListWidget::currentRowChanged, this, [this](int row) {
    if (refreshing_ || !tool_->hasHair()) return;
    const auto all = primitivesOf(tool_->style());
    tool_->selectPrimitive(row >= 0 && row < int(all.size()) ? all[row] : PrimitiveRef{});
  });

  auto* primitiveForm = new QFormLayout;
  kindLabel_ = new QLabel("-");
  primitiveForm->addRow(tr("Type"), kindLabel_);
  strength_ = addSpin(-5.0, 5.0, 0.05, 3);
  radius_ = addSpin(0.005, 0.5, 0.005, 3);
  primitiveForm->addRow(tr("Strength"), strength_);
  primitiveForm->addRow(tr("Radius (m)"), radius_);
  auto vectorRow = [&](QDoubleSpinBox** spins, double range, const QString& label) {
    auto* row = new QHBoxLayout;
    for (int i = 0; i < 3; ++i) {
      spins[i] = addSpin(-range, range, 0.01, 3);
      row->addWidget(spins[i]);
    }
    primitiveForm->addRow(label, row);
  };
  vectorRow(axis_, 1.0, tr("Axis / direction"));
  vectorRow(position_, 0.6, tr("Position (m, head)"));
  primitiveLayout->addLayout(primitiveForm);

  connect(strength_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    editPrimitive(tr("Primitive strength"), kStrength, [&](HairStyle& s) {
      const PrimitiveRef r = tool_->selectedPrimitive();
      if (r.kind == PrimitiveRef::Stream) s.primitives.streams[r.index].strength = float(v);
      if (r.kind == PrimitiveRef::Source) s.primitives.sources[r.index].strength = float(v);
      if (r.kind == PrimitiveRef::Vortex) s.primitives.vortices[r.index].strength = float(v);
    });
  });
  connect(radius_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    editPrimitive(tr("Primitive radius"), kRadius, [&](HairStyle& s) {
      const PrimitiveRef r = tool_->selectedPrimitive();
      if (r.kind == PrimitiveRef::Source) s.primitives.sources[r.index].radius = float(v);
      if (r.kind == PrimitiveRef::Vortex) s.primitives.vortices[r.index].radius = float(v);
    });
  });
  for (int i = 0; i < 3; ++i) {
    connect(axis_[i], &QDoubleSpinBox::valueChanged, this, [this, i](double v) {
      editPrimitive(tr("Primitive axis"), kAxisX + i, [&](HairStyle& s) {
        const PrimitiveRef r = tool_->selectedPrimitive();
        if (r.kind == PrimitiveRef::Stream) s.primitives.streams[r.index].direction[i] = float(v);
        if (r.kind == PrimitiveRef::Vortex) s.primitives.vortices[r.index].axis[i] = float(v);
      });
    });
    connect(position_[i], &QDoubleSpinBox::valueChanged, this, [this, i](double v) {
      editPrimitive(tr("Primitive position"), kPosX + i, [&](HairStyle& s) {
        const PrimitiveRef r = tool_->selectedPrimitive();
        if (r.kind == PrimitiveRef::Source) s.primitives.sources[r.index].position[i] = float(v);
        if (r.kind == PrimitiveRef::Vortex) s.primitives.vortices[r.index].position[i] = float(v);
      });
    });
  }
  return primitives;
}

// The strands: density, length, their shape and colour.
QWidget* HairPanel::makeStrandGroup() {
  auto* strands = new QGroupBox(tr("Strands"));
  auto* strandForm = new QFormLayout(strands);
  density_ = addSpin(1.0, 400.0, 5.0, 0);
  length_ = addSpin(0.02, 1.2, 0.01, 2);
  clumping_ = addSpin(0.0, 1.0, 0.05, 2);
  frizz_ = addSpin(0.0, 0.05, 0.001, 3);
  strandForm->addRow(tr("Density (/cm²)"), density_);
  strandForm->addRow(tr("Length (m)"), length_);
  strandForm->addRow(tr("Clumping"), clumping_);
  strandForm->addRow(tr("Frizz (m)"), frizz_);
  rootColor_ = new QPushButton;
  tipColor_ = new QPushButton;
  auto* colors = new QHBoxLayout;
  colors->addWidget(rootColor_);
  colors->addWidget(tipColor_);
  strandForm->addRow(tr("Colour root / tip"), colors);
  displayLimit_ = new QSpinBox;
  displayLimit_->setRange(1000, int(HairGroom::kMaxStrands));
  displayLimit_->setSingleStep(5000);
  displayLimit_->setGroupSeparatorShown(true);
  displayLimit_->setKeyboardTracking(false);
  displayLimit_->setToolTip(
      tr("The viewport grows at most this many strands (an editor setting, not saved in the "
         "document; the document keeps its density). Software OpenGL draws about 40,000 "
         "fluidly."));
  displayCount_ = new QLabel;
  strandForm->addRow(tr("Display at most"), displayLimit_);
  strandForm->addRow(displayCount_);
  connect(displayLimit_, &QSpinBox::valueChanged, this, [this](int limit) {
    if (!refreshing_) tool_->setDisplayStrandLimit(size_t(limit));
  });
  connect(density_, &QDoubleSpinBox::valueChanged, this,
          [this](double v) { editField(tr("Hair density"), kDensity, [&](HairStyle& s) { s.density = float(v); }); });
  connect(length_, &QDoubleSpinBox::valueChanged, this,
          [this](double v) { editField(tr("Hair length"), kLength, [&](HairStyle& s) { s.length = float(v); }); });
  connect(clumping_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    editField(tr("Hair clumping"), kClumping, [&](HairStyle& s) { s.clumping = float(v); });
  });
  connect(frizz_, &QDoubleSpinBox::valueChanged, this,
          [this](double v) { editField(tr("Hair frizz"), kFrizz, [&](HairStyle& s) { s.frizz = float(v); }); });
  connect(rootColor_, &QPushButton::clicked, this, [this] { pickColor(true); });
  connect(tipColor_, &QPushButton::clicked, this, [this] { pickColor(false); });
  return strands;
}

// What the viewport shows and the strand dynamics.
QWidget* HairPanel::makeDynamicsGroup() {
  auto* dynamics = new QGroupBox(tr("View and dynamics"));
  auto* dynamicsLayout = new QVBoxLayout(dynamics);
  handles_ = new QCheckBox(tr("Show primitive handles"));
  handles_->setChecked(true);
  shadowMaps_ = new QCheckBox(tr("Opacity shadow maps"));
  shadowMaps_->setToolTip(
      tr("Self-shadowing from a stack of opacity maps along the light (faster) "
         "instead of the exact count of the hair in front of each point"));
  simulate_ = new QCheckBox(tr("Simulate while playing"));
  adaptiveWisps_ = new QCheckBox(tr("Adaptive wisps"));
  adaptiveWisps_->setToolTip(
      tr("Simulate one guide per wisp where the hair moves together; wisps split where it swings or meets "
         "the body and merge back when it calms down"));
  bake_ = new QPushButton(tr("Bake clip"));
  // Hair against hair; on the bake's row, labels inside the boxes and no
  // taller than the button, so the dock keeps its size (the garments' live
  // simulation tests are timed by the viewport's size).
  volume_ = addSpin(0.0, 1.0, 0.05, 2);
  volume_->setToolTip(
      tr("How strongly the hair holds its volume: strands pushed together spread back to the groom's "
         "density, so wisps do not pass through each other (0: off)"));
  hairFriction_ = addSpin(0.0, 1.0, 0.05, 2);
  hairFriction_->setToolTip(tr("Friction of hair on hair: sliding strands drag their neighbours (0: off)"));
  volume_->setPrefix(tr("Volume "));
  hairFriction_->setPrefix(tr("Friction "));
  for (QDoubleSpinBox* spin : {volume_, hairFriction_}) spin->setMaximumHeight(bake_->sizeHint().height());
  auto* bakeRow = new QHBoxLayout;
  bakeRow->addWidget(bake_);
  bakeRow->addWidget(volume_);
  bakeRow->addWidget(hairFriction_);
  dynamicsLayout->addWidget(handles_);
  dynamicsLayout->addWidget(shadowMaps_);
  // On the simulate row: the dock keeps its height.
  auto* simulateRow = new QHBoxLayout;
  simulateRow->addWidget(simulate_);
  simulateRow->addWidget(adaptiveWisps_);
  dynamicsLayout->addLayout(simulateRow);
  dynamicsLayout->addLayout(bakeRow);
  connect(adaptiveWisps_, &QCheckBox::toggled, this, [this](bool on) {
    editField(tr("Adaptive wisps"), kAdaptiveWisps, [&](HairStyle& s) { s.dynamics.adaptiveWisps = on; });
  });
  connect(volume_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    editField(tr("Hair volume"), kVolume, [&](HairStyle& s) { s.dynamics.volume = float(v); });
  });
  connect(hairFriction_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    editField(tr("Hair friction"), kHairFriction, [&](HairStyle& s) { s.dynamics.friction = float(v); });
  });
  connect(handles_, &QCheckBox::toggled, tool_, &HairTool::setHandlesVisible);
  connect(shadowMaps_, &QCheckBox::toggled, tool_, &HairTool::setOpacityShadowMaps);
  connect(simulate_, &QCheckBox::toggled, tool_, &HairTool::setSimulating);
  connect(bake_, &QPushButton::clicked, this, [this] {
    status_->setText(tool_->bake() ? tr("Baked: the clip plays the simulated hair.") : tr("Bake cancelled."));
  });
  return dynamics;
}

// The shading model and the physical fibre's pigments and roughness. Every
// change is one undo step (steps of one spin box merge, as for the strands).
QWidget* HairPanel::makeShadingGroup() {
  auto* group = new QGroupBox(tr("Shading"));
  auto* form = new QFormLayout(group);
  shadingModel_ = new QComboBox;
  shadingModel_->addItem(tr("Kajiya-Kay"));
  shadingModel_->addItem(tr("Physical (Marschner)"));
  shadingModel_->setToolTip(
      tr("Kajiya-Kay: the root and tip colours with shifted highlights. Physical: a fibre "
         "that reflects, transmits and absorbs (R, TT and TRT lobes), coloured by its "
         "melanin."));
  melanin_ = addSpin(0.0, 8.0, 0.1, 2);
  melanin_->setToolTip(tr("Eumelanin, the brown-black pigment: 0 white, 0.3 blond, 1.3 brown, 8 black"));
  pheomelanin_ = addSpin(0.0, 4.0, 0.1, 2);
  pheomelanin_->setToolTip(tr("Pheomelanin, the red-yellow pigment"));
  roughness_ = addSpin(0.05, 1.0, 0.05, 2);
  roughness_->setToolTip(tr("Fibre roughness: 0.1 sleek with sharp highlights, 0.6 coarse"));
  form->addRow(tr("Model"), shadingModel_);
  form->addRow(tr("Melanin"), melanin_);
  form->addRow(tr("Redness"), pheomelanin_);
  form->addRow(tr("Roughness"), roughness_);
  auto* presets = new QHBoxLayout;
  for (const std::string& name : optics::hairPigmentPresetNames()) {
    auto* button = new QPushButton(QString::fromStdString(name));
    button->setObjectName(QString::fromStdString("hairPigment_" + name));
    presets->addWidget(button);
    pigmentButtons_.push_back(button);
    connect(button, &QPushButton::clicked, this, [this, name] {
      const optics::HairPigment p = optics::hairPigmentPreset(name);
      lastFieldKey_ = 0;  // a preset is a step of its own
      editField(tr("Hair colour %1").arg(QString::fromStdString(name)), kPigmentPreset, [&](HairStyle& s) {
        s.shading.model = HairShadingModel::Physical;
        s.shading.melanin = float(p.eumelanin);
        s.shading.pheomelanin = float(p.pheomelanin);
      });
      lastFieldKey_ = 0;
    });
  }
  form->addRow(presets);
  connect(shadingModel_, &QComboBox::activated, this, [this](int index) {
    lastFieldKey_ = 0;
    editField(tr("Hair shading model"), kShadingModel, [&](HairStyle& s) {
      s.shading.model = index == 1 ? HairShadingModel::Physical : HairShadingModel::KajiyaKay;
    });
    lastFieldKey_ = 0;
  });
  connect(melanin_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    editField(tr("Hair melanin"), kMelanin, [&](HairStyle& s) { s.shading.melanin = float(v); });
  });
  connect(pheomelanin_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    editField(tr("Hair redness"), kPheomelanin, [&](HairStyle& s) { s.shading.pheomelanin = float(v); });
  });
  connect(roughness_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    editField(tr("Hair roughness"), kRoughness, [&](HairStyle& s) { s.shading.roughness = float(v); });
  });
  return group;
}

void HairPanel::refreshShading() {
  const bool hair = tool_->hasHair();
  const HairShadingParams shading = hair ? tool_->style().shading : HairShadingParams{};
  const bool physical = shading.model == HairShadingModel::Physical;
  shadingModel_->setEnabled(hair);
  for (QDoubleSpinBox* spin : {melanin_, pheomelanin_, roughness_}) spin->setEnabled(hair && physical);
  for (QPushButton* button : pigmentButtons_) button->setEnabled(hair);
  // Kajiya-Kay colours from the root and tip; the physical fibre from its pigments.
  rootColor_->setEnabled(hair && !physical);
  tipColor_->setEnabled(hair && !physical);
  QSignalBlocker blockModel(shadingModel_), blockM(melanin_), blockP(pheomelanin_), blockR(roughness_);
  shadingModel_->setCurrentIndex(physical ? 1 : 0);
  melanin_->setValue(shading.melanin);
  pheomelanin_->setValue(shading.pheomelanin);
  roughness_->setValue(shading.roughness);
}

QWidget* HairPanel::makeScalpGroup() {
  auto* group = new QGroupBox(tr("Scalp"));
  auto* form = new QFormLayout(group);
  scalpMode_ = new QComboBox;
  scalpMode_->addItem(tr("Tagged scalp"));
  scalpMode_->addItem(tr("Head bone cone"));
  scalpMode_->addItem(tr("Automatic"));
  scalpMode_->addItem(tr("Painted"));
  scalpMode_->setToolTip(
      tr("Tagged: the character's scalp vertices (the default mannequin). Head bone cone: the "
         "faces the bone drives within an angle of an axis. Automatic: the tagged scalp, else "
         "the top and back of the head. Painted: the faces painted with the brush."));
  scalpBone_ = new QComboBox;
  scalpAxisPreset_ = new QComboBox;
  scalpAxisPreset_->addItem(tr("Up"));
  scalpAxisPreset_->addItem(tr("Up-back"));
  scalpAxisPreset_->addItem(tr("Custom"));
  auto* axisRow = new QHBoxLayout;
  for (int i = 0; i < 3; ++i) {
    scalpAxis_[i] = addSpin(-1.0, 1.0, 0.05, 3);
    axisRow->addWidget(scalpAxis_[i]);
  }
  scalpAngle_ = addSpin(1.0, 180.0, 5.0, 1);
  scalpAngle_->setSuffix(QString::fromUtf8("°"));
  scalpPaint_ = new QPushButton(tr("Paint"));
  scalpPaint_->setCheckable(true);
  scalpPaint_->setToolTip(
      tr("Drag on the character to add faces to the scalp, Ctrl+drag to erase them "
         "(middle or Alt+drag orbits). One undo step a stroke."));
  brushRadius_ = addSpin(0.5, 20.0, 0.5, 1);
  brushRadius_->setSuffix(tr(" cm"));
  brushRadius_->setValue(tool_->brushRadius() * 100.0);
  brushRadius_->setToolTip(
      tr("The brush's radius: faces whose centre is this close to the cursor's point are painted"));
  brush_ = new QWidget;
  auto* brushRow = new QHBoxLayout(brush_);
  brushRow->setContentsMargins(0, 0, 0, 0);
  brushRow->addWidget(scalpPaint_);
  brushRow->addWidget(brushRadius_);
  scalpStatus_ = new QLabel;
  form->addRow(tr("Region"), scalpMode_);
  form->addRow(tr("Bone"), scalpBone_);
  form->addRow(tr("Axis"), scalpAxisPreset_);
  form->addRow(QString(), axisRow);
  form->addRow(tr("Angle"), scalpAngle_);
  form->addRow(tr("Brush"), brush_);
  scalpForm_ = form;
  form->setRowVisible(brush_, false);  // shown with the Painted region
  form->addRow(scalpStatus_);
  connect(scalpPaint_, &QPushButton::toggled, this, [this](bool on) {
    if (on) groomBrush_->setCurrentIndex(0);
    tool_->setPaintingScalp(on);
  });
  connect(brushRadius_, &QDoubleSpinBox::valueChanged, this,
          [this](double cm) { tool_->setBrushRadius(float(cm) / 100.0f); });

  connect(scalpMode_, &QComboBox::currentIndexChanged, this, [this](int mode) {
    if (!refreshing_) chooseScalpMode(mode);
  });
  connect(scalpBone_, &QComboBox::currentTextChanged, this, [this](const QString& name) {
    lastFieldKey_ = 0;
    editScalpField(tr("Scalp bone"), 0, [&](ScalpRegion& r) { r.bone = name.toStdString(); });
  });
  connect(scalpAxisPreset_, &QComboBox::currentIndexChanged, this, [this](int preset) {
    if (preset > 1) return;  // Custom: the spin boxes
    lastFieldKey_ = 0;
    editScalpField(tr("Scalp axis"), 0, [&](ScalpRegion& r) { r.axis = preset == 0 ? kAxisUp : kAxisUpBack; });
  });
  for (int i = 0; i < 3; ++i)
    connect(scalpAxis_[i], &QDoubleSpinBox::valueChanged, this, [this, i](double v) {
      editScalpField(tr("Scalp axis"), kScalpAxisX + i, [&](ScalpRegion& r) { r.axis[i] = float(v); });
    });
  connect(scalpAngle_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
    editScalpField(tr("Scalp angle"), kScalpAngle, [&](ScalpRegion& r) { r.angleDegrees = float(v); });
  });
  return group;
}

void HairPanel::chooseScalpMode(int mode) {
  if (!tool_->hasHair()) return;
  ScalpRegion after = tool_->scalp();
  const std::string head = tool_->headBoneName();
  if (mode == ScalpTagged) {
    after = ScalpRegion{};
    if (!head.empty()) after.bone = head;
  } else if (mode == ScalpBoneCone) {
    if (after.kind != ScalpRegion::Kind::BoneCone) {
      after = ScalpRegion{};
      after.kind = ScalpRegion::Kind::BoneCone;
      if (!head.empty()) after.bone = head;
      after.axis = kAxisUpBack;
      after.angleDegrees = kDefaultConeAngle;
    }
  } else if (mode == ScalpPainted) {
    after = tool_->scalpAsFaces();  // the same faces, ready for the brush
    scalpPaint_->setChecked(true);
  } else {
    after = tool_->automaticScalp();
  }
  lastFieldKey_ = 0;
  tool_->editScalp(after, tr("Scalp region"));
}

void HairPanel::editScalpField(const QString& text, int fieldKey, const std::function<void(ScalpRegion&)>& change) {
  if (refreshing_ || !tool_->hasHair() || tool_->scalp().kind != ScalpRegion::Kind::BoneCone) return;
  ScalpRegion after = tool_->scalp();
  change(after);
  if (glm::length(after.axis) <= 0.0f) {
    refreshScalp();  // a zero axis has no direction: keep the last one
    return;
  }
  int mergeKey = 0;
  if (fieldKey != 0) {
    if (fieldKey != lastFieldKey_) {
      lastFieldKey_ = fieldKey;
      lastMergeKey_ = HairStyleCommand::nextMergeKey();
    }
    mergeKey = lastMergeKey_;
  }
  tool_->editScalp(after, text, mergeKey);
}

void HairPanel::refreshScalp() {
  const bool wasRefreshing = refreshing_;
  refreshing_ = true;
  const ScalpRegion& scalp = tool_->scalp();
  const bool hair = tool_->hasHair();
  const bool cone = scalp.kind == ScalpRegion::Kind::BoneCone;
  {
    QSignalBlocker block(scalpMode_);
    if (auto* model = qobject_cast<QStandardItemModel*>(scalpMode_->model()))
      model->item(ScalpTagged)->setEnabled(tool_->characterHasTaggedScalp());
    // Faces are Painted while the brush is on, or when they are not the automatic region's.
    const bool painted =
        scalp.kind == ScalpRegion::Kind::Faces && (tool_->paintingScalp() || !tool_->scalpIsAutomatic());
    scalpMode_->setCurrentIndex(scalp.kind == ScalpRegion::Kind::Tagged ? ScalpTagged
                                : cone                                  ? ScalpBoneCone
                                : painted                               ? ScalpPainted
                                                                        : ScalpAutomatic);
  }
  {
    QSignalBlocker block(scalpBone_);
    scalpBone_->clear();
    for (const std::string& name : tool_->boneNames()) scalpBone_->addItem(QString::fromStdString(name));
    scalpBone_->setCurrentIndex(scalpBone_->findText(QString::fromStdString(scalp.bone)));
  }
  {
    QSignalBlocker block(scalpAxisPreset_);
    scalpAxisPreset_->setCurrentIndex(sameDirection(scalp.axis, kAxisUp)       ? 0
                                      : sameDirection(scalp.axis, kAxisUpBack) ? 1
                                                                               : 2);
  }
  for (int i = 0; i < 3; ++i) {
    QSignalBlocker block(scalpAxis_[i]);
    scalpAxis_[i]->setValue(scalp.axis[i]);
  }
  {
    QSignalBlocker block(scalpAngle_);
    scalpAngle_->setValue(scalp.angleDegrees);
  }
  scalpMode_->setEnabled(hair);
  const bool painted = scalpMode_->currentIndex() == ScalpPainted;
  scalpForm_->setRowVisible(brush_, hair && painted);
  if ((!hair || !painted) && scalpPaint_->isChecked()) scalpPaint_->setChecked(false);
  for (QWidget* w : std::initializer_list<QWidget*>{scalpBone_, scalpAxisPreset_, scalpAxis_[0], scalpAxis_[1],
                                                    scalpAxis_[2], scalpAngle_})
    w->setEnabled(hair && cone);
  refreshScalpStatus();
  refreshing_ = wasRefreshing;
}

void HairPanel::refreshScalpStatus() {
  if (!tool_->hasHair())
    scalpStatus_->setText(tr("Pick a hairstyle first."));
  else if (!tool_->lastError().isEmpty())
    scalpStatus_->setText(tool_->lastError());
  else
    scalpStatus_->setText(tr("%1 roots on %2 cm²").arg(tool_->strandCount()).arg(tool_->scalpArea() * 1e4f, 0, 'f', 0));
}

QDoubleSpinBox* HairPanel::addSpin(double min, double max, double step, int decimals) {
  auto* spin = new QDoubleSpinBox;
  spin->setRange(min, max);
  spin->setSingleStep(step);
  spin->setDecimals(decimals);
  spin->setKeyboardTracking(false);
  // A typed value (Enter or leaving the field) ends the undo step: the next
  // one is a step of its own, while arrow clicks in a row merge.
  connect(spin, &QDoubleSpinBox::editingFinished, this, [this] { lastFieldKey_ = 0; });
  return spin;
}

void HairPanel::editField(const QString& text, int fieldKey, const std::function<void(HairStyle&)>& change) {
  if (refreshing_ || !tool_->hasHair()) return;
  HairStyle after = tool_->style();
  change(after);
  if (fieldKey != lastFieldKey_) {
    lastFieldKey_ = fieldKey;
    lastMergeKey_ = HairStyleCommand::nextMergeKey();
  }
  tool_->editStyle(after, text, lastMergeKey_);
}

void HairPanel::editPrimitive(const QString& text, int fieldKey, const std::function<void(HairStyle&)>& change) {
  if (!tool_->selectedPrimitive().valid()) return;
  editField(text, fieldKey, change);
}

void HairPanel::addPrimitive(int kind) {
  if (!tool_->hasHair()) return;
  HairStyle after = tool_->style();
  PrimitiveRef ref{PrimitiveRef::Kind(kind), 0};
  // New primitives sit where they would on the default mannequin's head,
  // scaled to this head.
  const float k = tool_->groom() && headSize(tool_->groom()->proxy()) > 0.0f
                      ? headSize(tool_->groom()->proxy()) / kReferenceHeadSize
                      : 1.0f;
  if (kind == PrimitiveRef::Stream) {
    after.primitives.streams.push_back({});
    ref.index = int(after.primitives.streams.size()) - 1;
  } else if (kind == PrimitiveRef::Source) {
    after.primitives.sources.push_back({k * glm::vec3(0.0f, 0.05f, 0.12f), 0.3f * k, 0.05f * k});
    ref.index = int(after.primitives.sources.size()) - 1;
  } else {
    after.primitives.vortices.push_back(
        {k * glm::vec3(0.0f, -0.15f, -0.12f), glm::vec3(0.0f, -1.0f, 0.0f), 0.5f, 0.05f * k});
    ref.index = int(after.primitives.vortices.size()) - 1;
  }
  lastFieldKey_ = 0;
  tool_->editStyle(after, tr("Add %1").arg(kindName(ref.kind)));
  tool_->selectPrimitive(ref);
}

void HairPanel::deleteSelected() {
  const PrimitiveRef r = tool_->selectedPrimitive();
  if (!tool_->hasHair() || !r.valid()) return;
  HairStyle after = tool_->style();
  if (r.kind == PrimitiveRef::Stream) after.primitives.streams.erase(after.primitives.streams.begin() + r.index);
  if (r.kind == PrimitiveRef::Source) after.primitives.sources.erase(after.primitives.sources.begin() + r.index);
  if (r.kind == PrimitiveRef::Vortex) after.primitives.vortices.erase(after.primitives.vortices.begin() + r.index);
  lastFieldKey_ = 0;
  tool_->selectPrimitive({});
  tool_->editStyle(after, tr("Delete %1").arg(kindName(r.kind)));
}

void HairPanel::pickColor(bool root) {
  if (!tool_->hasHair()) return;
  const glm::vec3 current = root ? tool_->style().rootColor : tool_->style().tipColor;
  const QColor chosen = QColorDialog::getColor(toQColor(current), this, root ? tr("Root colour") : tr("Tip colour"));
  if (!chosen.isValid()) return;
  editField(root ? tr("Hair root colour") : tr("Hair tip colour"), root ? kRootColor : kTipColor,
            [&](HairStyle& s) { (root ? s.rootColor : s.tipColor) = fromQColor(chosen); });
}

void HairPanel::refresh() {
  refreshing_ = true;
  const bool hair = tool_->hasHair();
  {
    QSignalBlocker block(styleCombo_);
    if (!hair) {
      styleCombo_->setCurrentIndex(0);
    } else {
      const int index = styleCombo_->findText(QString::fromStdString(tool_->style().name));
      styleCombo_->setCurrentIndex(index > 0 ? index : styleCombo_->count() - 1);
    }
  }
  {
    QSignalBlocker block(list_);
    list_->clear();
    if (hair) {
      const auto all = primitivesOf(tool_->style());
      int counts[3] = {0, 0, 0};
      for (const PrimitiveRef& r : all) {
        list_->addItem(QString("%1 %2").arg(kindName(r.kind)).arg(++counts[r.kind]));
        if (r == tool_->selectedPrimitive()) list_->setCurrentRow(list_->count() - 1);
      }
    }
  }
  for (QWidget* w :
       std::initializer_list<QWidget*>{addStream_, addSource_, addVortex_, density_, length_, clumping_, frizz_,
                                       rootColor_, tipColor_, simulate_, bake_, volume_, hairFriction_, adaptiveWisps_})
    w->setEnabled(hair);
  delete_->setEnabled(hair && tool_->selectedPrimitive().valid());
  groomBrush_->setEnabled(hair);
  clearStrokes_->setEnabled(hair && !tool_->style().strokes.empty());
  const size_t strokes = hair ? tool_->style().strokes.size() : 0;
  clearStrokes_->setText(strokes == 0   ? tr("Clear")
                         : strokes == 1 ? tr("Clear 1 stroke")
                                        : tr("Clear %1 strokes").arg(strokes));
  if (hair) {
    const HairStyle& s = tool_->style();
    for (auto [spin, value] : {std::pair{density_, s.density}, std::pair{length_, s.length},
                               std::pair{clumping_, s.clumping}, std::pair{frizz_, s.frizz},
                               std::pair{volume_, s.dynamics.volume}, std::pair{hairFriction_, s.dynamics.friction}}) {
      QSignalBlocker block(spin);
      spin->setValue(value);
    }
    {
      QSignalBlocker block(adaptiveWisps_);
      adaptiveWisps_->setChecked(s.dynamics.adaptiveWisps);
    }
    paintSwatch(rootColor_, s.rootColor);
    paintSwatch(tipColor_, s.tipColor);
  }
  {
    QSignalBlocker block(displayLimit_);
    displayLimit_->setValue(int(tool_->displayStrandLimit()));
  }
  refreshShading();
  refreshStrandCounts();
  refreshPrimitiveFields();
  refreshScalp();
  refreshing_ = false;
}

// The counts of the hair on screen (it follows the edits once regrown).
void HairPanel::refreshStrandCounts() {
  if (tool_->hasHair()) {
    status_->setText(tr("%1 strands, %2 flow primitives").arg(tool_->strandCount()).arg(list_->count()));
    const size_t wanted = tool_->documentStrandCount();
    const size_t shown = std::min(wanted, tool_->displayStrandLimit());
    const QLocale locale;
    displayCount_->setText(shown < wanted
                               ? tr("Displaying %1 of %2 strands")
                                     .arg(locale.toString(qulonglong(shown)), locale.toString(qulonglong(wanted)))
                               : tr("Displaying all %1 strands").arg(locale.toString(qulonglong(wanted))));
  } else {
    status_->setText(tool_->lastError().isEmpty() ? tr("No hair: pick a hairstyle.") : tool_->lastError());
    displayCount_->clear();
  }
  refreshScalpStatus();
}

void HairPanel::refreshPrimitiveFields() {
  const PrimitiveRef r = tool_->selectedPrimitive();
  const bool valid = tool_->hasHair() && r.valid();
  float strength = 0.0f, radius = 0.0f;
  glm::vec3 axis(0.0f), position(0.0f);
  if (valid) {
    const FlowPrimitives& p = tool_->style().primitives;
    if (r.kind == PrimitiveRef::Stream) {
      strength = p.streams[r.index].strength;
      axis = p.streams[r.index].direction;
    } else if (r.kind == PrimitiveRef::Source) {
      strength = p.sources[r.index].strength;
      radius = p.sources[r.index].radius;
      position = p.sources[r.index].position;
    } else {
      strength = p.vortices[r.index].strength;
      radius = p.vortices[r.index].radius;
      axis = p.vortices[r.index].axis;
      position = p.vortices[r.index].position;
    }
  }
  kindLabel_->setText(valid ? kindName(r.kind) : QString("-"));
  auto set = [](QDoubleSpinBox* spin, float value, bool enabled) {
    QSignalBlocker block(spin);
    spin->setValue(value);
    spin->setEnabled(enabled);
  };
  set(strength_, strength, valid);
  set(radius_, radius, valid && r.kind != PrimitiveRef::Stream);
  for (int i = 0; i < 3; ++i) {
    set(axis_[i], axis[i], valid && r.kind != PrimitiveRef::Source);
    set(position_[i], position[i], valid && r.kind != PrimitiveRef::Stream);
  }
}

}  // namespace mq::ui
