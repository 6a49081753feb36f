#pragma once
// The garment tool's dock: the garments (list with their layers, add a
// built-in one, remove, the current one's layer),
// the current garment's measurements (one field per parameter the garment
// type declares, rebuilt when the type changes), its fabric (preset or
// values), the simulation (integrator, self collisions, Simulate, Bake clip;
// with no character: the bake length in frames), the pins (vertex-select
// mode, Pin selected, Unpin, attach to body or space),
// the colliders (list, add a sphere, capsule or plane, edit its centre or
// ends or point and normal, radius and friction, remove) and the display
// (stretch overlay, pin dots, colliders). Every change goes to the
// GarmentTool as an undoable edit; the panel refreshes from its signals.

#include <functional>
#include <vector>

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QListWidget;
class QPushButton;
class QSpinBox;
class QVBoxLayout;

namespace mq {
struct Fabric;
}

namespace mq::ui {

class GarmentTool;

class GarmentPanel : public QWidget {
  Q_OBJECT

 public:
  explicit GarmentPanel(GarmentTool* tool, QWidget* parent = nullptr);

  // For tests and scripts.
  QListWidget* garmentList() const { return list_; }
  QComboBox* typeCombo() const { return typeCombo_; }
  QSpinBox* layerField() const { return layer_; }
  QPushButton* addButton() const { return add_; }
  QPushButton* patternButton() const { return pattern_; }
  const QList<QAction*>& patternExportActions() const { return patternExports_; }
  QComboBox* fabricCombo() const { return fabricCombo_; }
  QComboBox* integratorCombo() const { return integratorCombo_; }
  QSpinBox* clothFpsField() const { return clothFps_; }
  // Frames to bake when there is no clip (no character); shown only then.
  QSpinBox* bakeFramesField() const { return bakeFrames_; }
  // The measurement field named `name` of the current garment, or null.
  QDoubleSpinBox* measurementField(const QString& name) const;
  QDoubleSpinBox* particleDistanceField() const { return particleDistance_; }
  QPushButton* simulateButton() const { return simulate_; }
  QPushButton* bakeButton() const { return bake_; }
  QPushButton* exportBakeButton() const { return exportBake_; }
  QString statusText() const;  // the status lines at the dock's foot
  QPushButton* selectButton() const { return select_; }
  QPushButton* pinButton() const { return pin_; }
  QPushButton* unpinButton() const { return unpin_; }
  QCheckBox* stretchCheck() const { return stretch_; }
  QListWidget* colliderList() const { return colliderList_; }
  QComboBox* colliderShapeCombo() const { return colliderShape_; }
  QPushButton* addColliderButton() const { return addCollider_; }
  QPushButton* removeColliderButton() const { return removeCollider_; }
  // The current collider's fields: point a (centre, end A or a point on the
  // plane) and b (end B or the normal), x/y/z each; radius; friction.
  QDoubleSpinBox* colliderField(int vector, int axis) const { return colliderVectors_[vector][axis]; }
  QDoubleSpinBox* colliderRadiusField() const { return colliderRadius_; }
  QDoubleSpinBox* colliderFrictionField() const { return colliderFriction_; }

 private:
  void refresh();
  void rebuildMeasurements();
  void refreshFabric();
  void refreshStatus();
  void editFabric(int field, const std::function<void(Fabric&, double)>& change, double value);
  // The dock's groups, top to bottom.
  void buildGarmentGroup(QVBoxLayout* layout);
  void buildMeasurementGroup(QVBoxLayout* layout);
  void buildFabricGroup(QVBoxLayout* layout);
  void buildSimulationGroup(QVBoxLayout* layout);
  void buildPinGroup(QVBoxLayout* layout);
  void buildColliderGroup(QVBoxLayout* layout);
  void buildDisplayGroup(QVBoxLayout* layout);
  // The undo merge key for an edit of `field` (a spin box's steps merge;
  // another field starts a new key).
  int mergeKeyFor(int field);
  void refreshColliders();
  void editCollider(int field);

  GarmentTool* tool_;
  QListWidget* list_;
  QComboBox* typeCombo_;
  QPushButton *add_, *remove_, *pattern_;
  QList<QAction*> patternExports_;  // need a garment; importing does not
  QSpinBox* layer_;
  QWidget* measurements_;
  QFormLayout* measurementForm_;
  std::vector<QDoubleSpinBox*> measurementFields_;
  QString measuredType_;
  int measuredGarment_ = -2;
  QDoubleSpinBox* particleDistance_;
  QComboBox* fabricCombo_;
  std::vector<QDoubleSpinBox*> fabricFields_;
  QComboBox* integratorCombo_;
  QCheckBox* selfCollisions_;
  QSpinBox* clothFps_;
  QSpinBox* bakeFrames_;
  QFormLayout* simForm_;
  QPushButton *simulate_, *bake_, *clearBake_, *exportBake_, *resetDrapes_;
  QPushButton *select_, *pin_, *unpin_, *clearPins_;
  QComboBox* attach_;
  QListWidget* colliderList_;
  QComboBox* colliderShape_;
  QPushButton *addCollider_, *removeCollider_;
  QFormLayout* colliderForm_;
  QDoubleSpinBox* colliderVectors_[2][3];
  QDoubleSpinBox* colliderRadius_;
  QDoubleSpinBox* colliderFriction_;
  QCheckBox *stretch_, *showPins_, *showColliders_;
  QLabel* pinStatus_;
  QLabel* status_;
  bool refreshing_ = false;
  int lastField_ = 0, lastMergeKey_ = 0;
};

}  // namespace mq::ui
