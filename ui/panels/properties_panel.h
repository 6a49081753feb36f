#pragma once
// Properties of the selection: for a bone, its name and the pose edit as
// Euler angles in degrees (X, then Y, then Z) with a reset button; for a mesh,
// its vertex and triangle counts and skinning; for a material, its page
// (ui/panels/material_page.h). The character page chooses the
// skinning method. Typed angles and the method become undo commands on the
// document. The character page also counts the skin's crossing triangle pairs
// at the current pose (on a worker thread).

#include <array>

#include <QFutureWatcher>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QStackedWidget;

namespace mq::ui {

class EditorDocument;
class MaterialPage;

class PropertiesPanel : public QWidget {
  Q_OBJECT

 public:
  explicit PropertiesPanel(EditorDocument* document, QWidget* parent = nullptr);

  QDoubleSpinBox* angleBox(int axis) const { return angles_[axis]; }
  QPushButton* resetButton() const { return resetBone_; }
  QComboBox* skinningBox() const { return skinning_; }
  QCheckBox* helperBonesBox() const { return helperBones_; }
  QCheckBox* autoRigBox() const { return autoRig_; }
  QCheckBox* regenerateWeightsBox() const { return regenerateWeights_; }
  QCheckBox* smoothWeightsBox() const { return smoothWeights_; }
  QLabel* weightsLabel() const { return weightsReport_; }
  QPushButton* countCrossingsButton() const { return countCrossings_; }
  MaterialPage* materialPage() const { return materialPage_; }
  QLabel* crossingsLabel() const { return crossings_; }

 private:
  QWidget* makeCharacterPage();
  QWidget* makeBonePage();
  QWidget* makeMeshPage();
  void showSelection();
  void showCharacter();
  void showBoneAngles();
  void applyTypedAngles();
  void resetBone();
  void resetAllBones();
  // Counts the skin's crossing triangle pairs at the current pose on a worker.
  void countCrossings();
  QWidget* makeWeightsRow();
  // Rebuilds the weights as the two boxes say (one undo step).
  void applyWeightBoxes();

  EditorDocument* document_;
  QStackedWidget* pages_;
  QLabel* boneName_ = nullptr;
  QLabel* boneParent_ = nullptr;
  QLabel* boneJoint_ = nullptr;
  QLabel* boneChildren_ = nullptr;
  QLabel* characterName_ = nullptr;
  QLabel* characterSource_ = nullptr;
  QLabel* characterMeshes_ = nullptr;
  QLabel* characterVertices_ = nullptr;
  QLabel* characterTriangles_ = nullptr;
  QLabel* characterBones_ = nullptr;
  QLabel* characterClips_ = nullptr;
  QLabel* characterEdits_ = nullptr;
  QComboBox* skinning_ = nullptr;
  QCheckBox* helperBones_ = nullptr;
  QCheckBox* autoRig_ = nullptr;
  QCheckBox* regenerateWeights_ = nullptr;
  QCheckBox* smoothWeights_ = nullptr;
  QLabel* weightsReport_ = nullptr;
  QLabel* crossings_ = nullptr;
  QPushButton* countCrossings_ = nullptr;
  QFutureWatcher<long> crossingsWatcher_;
  int poseGeneration_ = 0;      // bumped by every pose change
  int countedGeneration_ = -1;  // the pose the running count is for
  std::array<QDoubleSpinBox*, 3> angles_{};
  QPushButton* resetBone_ = nullptr;
  QPushButton* resetAll_ = nullptr;
  QLabel* meshName_ = nullptr;
  QLabel* meshVertices_ = nullptr;
  QLabel* meshTriangles_ = nullptr;
  QLabel* meshSkin_ = nullptr;
  QLabel* meshMorphs_ = nullptr;
  MaterialPage* materialPage_ = nullptr;
  bool syncing_ = false;
};

}  // namespace mq::ui
