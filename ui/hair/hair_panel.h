#pragma once
// The hair tool's dock: the built-in style, the flow primitives of the style
// (list with add/delete and the selected one's fields), the strand
// parameters (density, length, clumping, frizz, colours), the view (handles,
// opacity shadow maps) and the dynamics (simulate while playing, bake the
// clip). Every change goes to HairTool::editStyle as an undoable edit; the
// panel refreshes from the tool's signals.

#include <vector>

#include <QWidget>

#include <glm/glm.hpp>

#include "core/hair/hairstyle.h"
#include "core/hair/scalp.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QFormLayout;
class QPushButton;
class QSpinBox;

namespace mq::ui {

class HairTool;

class HairPanel : public QWidget {
  Q_OBJECT

 public:
  explicit HairPanel(HairTool* tool, QWidget* parent = nullptr);

  // For tests and scripts.
  QListWidget* primitiveList() const { return list_; }
  QPushButton* addSourceButton() const { return addSource_; }
  QPushButton* addVortexButton() const { return addVortex_; }
  QDoubleSpinBox* strengthBox() const { return strength_; }
  QDoubleSpinBox* densityBox() const { return density_; }
  QDoubleSpinBox* volumeBox() const { return volume_; }
  QDoubleSpinBox* hairFrictionBox() const { return hairFriction_; }
  QDoubleSpinBox* positionBox(int axis) const { return position_[axis]; }
  QCheckBox* shadowMapsBox() const { return shadowMaps_; }
  QCheckBox* adaptiveWispsBox() const { return adaptiveWisps_; }
  QSpinBox* displayLimitBox() const { return displayLimit_; }
  QLabel* displayCountLabel() const { return displayCount_; }
  // Scalp group: mode (ScalpMode order), bone, axis preset, axis, angle,
  // and, with the Painted region, the brush: Paint (checkable) and its radius (cm).
  enum ScalpMode { ScalpTagged, ScalpBoneCone, ScalpAutomatic, ScalpPainted };
  // Grooming: the brush (Off, then groomBrushNames() in order) beside the
  // style; its radius (cm), strength, mirror and Clear strokes show while one is on.
  QComboBox* groomBrushCombo() const { return groomBrush_; }
  QDoubleSpinBox* groomRadiusBox() const { return groomRadius_; }
  QDoubleSpinBox* groomStrengthBox() const { return groomStrength_; }
  QCheckBox* groomMirrorBox() const { return groomMirror_; }
  QDoubleSpinBox* groomValueBox() const { return groomValue_; }  // paint brushes only
  QPushButton* clearStrokesButton() const { return clearStrokes_; }
  QPushButton* scalpPaintButton() const { return scalpPaint_; }
  QDoubleSpinBox* brushRadiusBox() const { return brushRadius_; }
  QComboBox* scalpModeCombo() const { return scalpMode_; }
  QComboBox* scalpBoneCombo() const { return scalpBone_; }
  QComboBox* scalpAxisPresetCombo() const { return scalpAxisPreset_; }
  QDoubleSpinBox* scalpAxisBox(int axis) const { return scalpAxis_[axis]; }
  QDoubleSpinBox* scalpAngleBox() const { return scalpAngle_; }
  QLabel* scalpStatusLabel() const { return scalpStatus_; }
  // Shading group: model (0 Kajiya-Kay, 1 physical), pigments, roughness, presets.
  QComboBox* shadingModelCombo() const { return shadingModel_; }
  QDoubleSpinBox* melaninBox() const { return melanin_; }
  QDoubleSpinBox* pheomelaninBox() const { return pheomelanin_; }
  QDoubleSpinBox* roughnessBox() const { return roughness_; }
  const std::vector<QPushButton*>& pigmentButtons() const { return pigmentButtons_; }

 private:
  void refresh();
  void refreshStrandCounts();
  void refreshPrimitiveFields();
  void refreshScalp();
  void refreshScalpStatus();
  // The dock's groups.
  QWidget* makePrimitiveGroup();
  QWidget* makeStrandGroup();
  QWidget* makeShadingGroup();
  QWidget* makeDynamicsGroup();
  QWidget* makeScalpGroup();
  void refreshShading();
  void chooseScalpMode(int mode);
  // Applies `change` to a copy of the scalp region and pushes it (merging
  // with the previous change of the same field).
  void editScalpField(const QString& text, int fieldKey, const std::function<void(ScalpRegion&)>& change);
  QDoubleSpinBox* addSpin(double min, double max, double step, int decimals);
  // Applies `change` to a copy of the style and pushes it (merging with the
  // previous change of the same field).
  void editField(const QString& text, int fieldKey, const std::function<void(HairStyle&)>& change);
  void editPrimitive(const QString& text, int fieldKey, const std::function<void(HairStyle&)>& change);
  void addPrimitive(int kind);
  void deleteSelected();
  void pickColor(bool root);

  HairTool* tool_;
  QComboBox* styleCombo_;
  QListWidget* list_;
  QPushButton *addStream_, *addSource_, *addVortex_, *delete_;
  QLabel* kindLabel_;
  QDoubleSpinBox *strength_, *radius_;
  QDoubleSpinBox* axis_[3];
  QDoubleSpinBox* position_[3];
  QDoubleSpinBox *density_, *length_, *clumping_, *frizz_;
  QDoubleSpinBox *volume_, *hairFriction_;  // hair against hair (the style's dynamics)
  QPushButton *rootColor_, *tipColor_;
  QSpinBox* displayLimit_;
  QLabel* displayCount_;
  QCheckBox *handles_, *simulate_, *shadowMaps_;
  QCheckBox* adaptiveWisps_;  // the style's dynamics
  QPushButton* bake_;
  QComboBox *scalpMode_, *scalpBone_, *scalpAxisPreset_;
  QDoubleSpinBox* scalpAxis_[3];
  QDoubleSpinBox* scalpAngle_;
  QComboBox* groomBrush_;
  QDoubleSpinBox* groomRadius_;
  QDoubleSpinBox* groomStrength_;
  QCheckBox* groomMirror_;
  QDoubleSpinBox* groomValue_;
  QPushButton* clearStrokes_;
  QWidget* groomSettings_;
  QFormLayout* styleForm_;
  void makeGroomControls();
  QPushButton* scalpPaint_;
  QDoubleSpinBox* brushRadius_;
  QWidget* brush_;  // the Paint button and the radius: shown with the Painted region
  QFormLayout* scalpForm_;
  QLabel* scalpStatus_;
  QComboBox* shadingModel_;
  QDoubleSpinBox *melanin_, *pheomelanin_, *roughness_;
  std::vector<QPushButton*> pigmentButtons_;
  QLabel* status_;
  bool refreshing_ = false;
  int lastFieldKey_ = 0, lastMergeKey_ = 0;
};

}  // namespace mq::ui
