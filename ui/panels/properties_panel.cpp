#include "ui/panels/properties_panel.h"

#include <cmath>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QStackedWidget>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "core/math/transform.h"
#include "core/skinning/helper_bones.h"
#include "core/skinning/skin_metrics.h"
#include "ui/document/editor_document.h"
#include "ui/document/pose_commands.h"
#include "ui/document/snapshot_command.h"
#include "ui/jobs/step_progress.h"
#include "ui/panels/material_page.h"

namespace mq::ui {
namespace {

enum Page { CharacterPage = 0, BonePage, MeshPage, MaterialPageIndex };

QString count(size_t n) { return QLocale().toString(static_cast<qulonglong>(n)); }

}  // namespace

PropertiesPanel::PropertiesPanel(EditorDocument* document, QWidget* parent)
    : QWidget(parent), document_(document), pages_(new QStackedWidget(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(6, 6, 6, 6);
  layout->addWidget(pages_);
  layout->addStretch(1);
  pages_->addWidget(makeCharacterPage());
  pages_->addWidget(makeBonePage());
  pages_->addWidget(makeMeshPage());
  materialPage_ = new MaterialPage(document_);
  pages_->addWidget(materialPage_);

  connect(document_, &EditorDocument::selectionChanged, this, &PropertiesPanel::showSelection);
  connect(document_, &EditorDocument::characterReplaced, this, &PropertiesPanel::showSelection);
  connect(document_, &EditorDocument::skeletonChanged, this, &PropertiesPanel::showSelection);
  connect(document_, &EditorDocument::poseChanged, this, [this] {
    ++poseGeneration_;
    crossings_->setText(tr("-"));
    if (pages_->currentIndex() == BonePage)
      showBoneAngles();
    else if (pages_->currentIndex() == CharacterPage)
      showCharacter();
  });
  connect(document_, &EditorDocument::clipsChanged, this, [this] {
    if (pages_->currentIndex() == CharacterPage) showCharacter();
  });
  showSelection();
}

QWidget* PropertiesPanel::makeCharacterPage() {
  auto* page = new QWidget;
  auto* layout = new QVBoxLayout(page);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* box = new QGroupBox(tr("Character"));
  auto* form = new QFormLayout(box);
  characterName_ = new QLabel;
  characterSource_ = new QLabel;
  characterMeshes_ = new QLabel;
  characterVertices_ = new QLabel;
  characterTriangles_ = new QLabel;
  characterBones_ = new QLabel;
  characterClips_ = new QLabel;
  characterEdits_ = new QLabel;
  form->addRow(tr("Name"), characterName_);
  form->addRow(tr("Source"), characterSource_);
  form->addRow(tr("Meshes"), characterMeshes_);
  form->addRow(tr("Vertices"), characterVertices_);
  form->addRow(tr("Triangles"), characterTriangles_);
  form->addRow(tr("Bones"), characterBones_);
  form->addRow(tr("Clips"), characterClips_);
  form->addRow(tr("Posed bones"), characterEdits_);
  skinning_ = new QComboBox;
  skinning_->addItem(tr("Linear blend (LBS)"), int(SkinningMethod::Lbs));
  skinning_->addItem(tr("Dual quaternion (DQS)"), int(SkinningMethod::Dqs));
  skinning_->addItem(tr("Section cones"), int(SkinningMethod::Cones));
  skinning_->setToolTip(
      tr("How the skin follows the bones. Linear blend thins bent joints and collapses twists; "
         "dual quaternions keep the joint's section; section cones also keep the bend's volume "
         "and push folds out of the neighbouring limb."));
  connect(skinning_, &QComboBox::activated, this, [this](int index) {
    const auto method = SkinningMethod(skinning_->itemData(index).toInt());
    if (method != document_->skinning()) document_->undoStack()->push(new SetSkinningCommand(document_, method));
  });
  form->addRow(tr("Skinning"), skinning_);
  helperBones_ = new QCheckBox(tr("Helper bones"));
  helperBones_->setToolTip(
      tr("Small bones at the shoulders, elbows, hips and knees that turn half as far as the "
         "limb, and two twist bones in each forearm: linear blend skinning then keeps bent "
         "joints round and twisted forearms thick. A humanoid's only."));
  connect(helperBones_, &QCheckBox::clicked, this, [this](bool on) {
    const std::string refusal = on ? helperBonesRefusal(document_->character()) : std::string();
    if (!refusal.empty()) {
      helperBones_->setChecked(false);
      helperBones_->setToolTip(QString::fromStdString(refusal));
      return;
    }
    if (on != document_->helperBones()) document_->undoStack()->push(new SetHelperBonesCommand(document_, on));
  });
  form->addRow(QString(), helperBones_);
  autoRig_ = new QCheckBox(tr("Auto-rig"));
  autoRig_->setToolTip(
      tr("Give a mesh without bones (an OBJ, PLY or STL body) a humanoid skeleton placed from its "
         "shape, to pose it and play motions on it. It must stand upright, face +Z and hold its "
         "arms away from the body."));
  connect(autoRig_, &QCheckBox::clicked, this, [this](bool on) {
    const std::string refusal = document_->setAutoRig(on);
    if (!refusal.empty()) {
      autoRig_->setChecked(!on);
      autoRig_->setToolTip(QString::fromStdString(refusal));
      return;
    }
    EditorDocument* document = document_;
    document_->undoStack()->push(new SnapshotCommand<bool>([document](const bool& rig) { document->setAutoRig(rig); },
                                                           !on, on, on ? tr("Auto-rig") : tr("Remove the auto-rig")));
  });
  form->addRow(QString(), autoRig_);
  form->addRow(tr("Weights"), makeWeightsRow());
  crossings_ = new QLabel(tr("-"));
  crossings_->setToolTip(
      tr("Triangle pairs of the skin that cross each other at this pose (exact predicates): "
         "what a fold or a limb pressed into the body does to the mesh."));
  countCrossings_ = new QPushButton(tr("Count"));
  connect(countCrossings_, &QPushButton::clicked, this, &PropertiesPanel::countCrossings);
  connect(&crossingsWatcher_, &QFutureWatcher<long>::finished, this, [this] {
    countCrossings_->setEnabled(true);
    if (countedGeneration_ != poseGeneration_) return;  // the pose changed meanwhile
    const long pairs = crossingsWatcher_.result();
    crossings_->setText(pairs < 0 ? tr("the skin is not a closed surface")
                                  : tr("%n crossing triangle pair(s)", "", int(pairs)));
  });
  auto* crossingsRow = new QHBoxLayout;
  crossingsRow->addWidget(crossings_, 1);
  crossingsRow->addWidget(countCrossings_);
  form->addRow(tr("Skin crossings"), crossingsRow);
  layout->addWidget(box);
  auto* hint =
      new QLabel(tr("Click a bone in the viewport or the scene tree to pose it; "
                    "drag a ring of the gizmo or type angles."));
  hint->setWordWrap(true);
  hint->setEnabled(false);
  layout->addWidget(hint);
  return page;
}

void PropertiesPanel::countCrossings() {
  if (crossingsWatcher_.isRunning()) return;
  countedGeneration_ = poseGeneration_;
  countCrossings_->setEnabled(false);
  crossings_->setText(tr("counting..."));
  crossingsWatcher_.setFuture(
      QtConcurrent::run([character = document_->character(), posed = document_->posed().meshes()]() -> long {
        try {
          const MetricBody body(character);
          return long(intersectingPairs(body.weld(posed), body.triangles()));
        } catch (const std::exception&) {
          return -1;  // not a 2-manifold: the pairs are not defined
        }
      }));
}

void PropertiesPanel::showCharacter() {
  const Character& c = document_->character();
  characterName_->setText(QString::fromStdString(c.name.empty() ? "(unnamed)" : c.name));
  const QString source = QString::fromStdString(c.sourcePath);
  characterSource_->setText(source.section('/', -1));
  characterSource_->setToolTip(source);
  characterMeshes_->setText(QString::number(c.meshes.size()));
  characterVertices_->setText(count(c.vertexCount()));
  characterTriangles_->setText(count(c.triangleCount()));
  characterBones_->setText(QString::number(c.skeleton.boneCount()));
  QStringList clips;
  for (const Clip& clip : c.clips)
    clips << QString("%1 (%2 s)").arg(QString::fromStdString(clip.name)).arg(clip.duration(), 0, 'f', 2);
  // One line: a label whose height changes later is not re-laid out inside
  // the stacked pages; the timeline's clip box lists the clips anyway.
  characterClips_->setText(QString::number(clips.size()));
  characterClips_->setToolTip(clips.join("\n"));
  characterEdits_->setText(QString::number(document_->poseEdits().rotations.size()));
  skinning_->setCurrentIndex(skinning_->findData(int(document_->skinning())));
  helperBones_->setChecked(document_->helperBones());
  autoRig_->setChecked(document_->autoRigged());
  autoRig_->setVisible(document_->autoRigged() || c.skeleton.boneCount() == 0);
  regenerateWeights_->setChecked(document_->weightSettings().regenerate);
  smoothWeights_->setChecked(document_->weightSettings().smooth);
  const WeightReport& report = document_->weightReport();
  weightsReport_->setText(!document_->weightSettings().active() ? tr("the file's")
                          : report.vertices > 0                 ? QString::fromStdString(report.summary())
                                                                : tr("rebuilt when the scene opened"));
}

QWidget* PropertiesPanel::makeWeightsRow() {
  auto* row = new QWidget;
  auto* layout = new QVBoxLayout(row);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* boxes = new QHBoxLayout;
  regenerateWeights_ = new QCheckBox(tr("Regenerate"));
  regenerateWeights_->setToolTip(
      tr("Rebuild the skin weights (survey 1.2.5): each vertex goes to the bone whose "
         "cylinder is nearest and which it sees from inside the skin, then the bones "
         "blend over two section radii at each joint. Undo gives the file's weights "
         "back; the setting is saved with the scene."));
  smoothWeights_ = new QCheckBox(tr("Smooth"));
  smoothWeights_->setToolTip(
      tr("Bound how fast a weight may change along the skin, by the section of the bone's "
         "cone: fingers switch over a finger's width, the pelvis over the pelvis's."));
  connect(regenerateWeights_, &QCheckBox::clicked, this, &PropertiesPanel::applyWeightBoxes);
  connect(smoothWeights_, &QCheckBox::clicked, this, &PropertiesPanel::applyWeightBoxes);
  boxes->addWidget(regenerateWeights_);
  boxes->addWidget(smoothWeights_);
  boxes->addStretch();
  layout->addLayout(boxes);
  weightsReport_ = new QLabel(tr("the file's"));
  weightsReport_->setWordWrap(true);
  layout->addWidget(weightsReport_);
  return row;
}

void PropertiesPanel::applyWeightBoxes() {
  WeightSettings settings = document_->weightSettings();
  settings.regenerate = regenerateWeights_->isChecked();
  settings.smooth = smoothWeights_->isChecked();
  const WeightSettings before = document_->weightSettings();
  if (settings == before) return;
  // About a second on the mannequin, longer on a big skin: the dialog shows
  // after a moment, with a Cancel that leaves the weights as they were.
  StepProgress progress(this, tr("Rebuilding the skin weights..."), 300);
  progress.dialog().setObjectName("weightsProgress");
  WeightCallbacks callbacks;
  callbacks.progress = [&](int done, int total) { progress.step(done, total); };
  callbacks.cancelled = [&] { return progress.cancelled(); };
  if (!document_->setWeightSettings(settings, &callbacks)) {
    regenerateWeights_->setChecked(before.regenerate);
    smoothWeights_->setChecked(before.smooth);
    return;
  }
  document_->undoStack()->push(new SetWeightSettingsCommand(document_, before, settings, true));
}

QWidget* PropertiesPanel::makeBonePage() {
  auto* page = new QWidget;
  auto* layout = new QVBoxLayout(page);
  layout->setContentsMargins(0, 0, 0, 0);

  auto* info = new QGroupBox(tr("Bone"));
  auto* form = new QFormLayout(info);
  boneName_ = new QLabel;
  boneName_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  boneParent_ = new QLabel;
  boneJoint_ = new QLabel;
  boneChildren_ = new QLabel;
  form->addRow(tr("Name"), boneName_);
  form->addRow(tr("Parent"), boneParent_);
  form->addRow(tr("Children"), boneChildren_);
  form->addRow(tr("Joint (m)"), boneJoint_);
  layout->addWidget(info);

  auto* rotation = new QGroupBox(tr("Pose rotation (degrees, XYZ)"));
  auto* rotationForm = new QFormLayout(rotation);
  const char* axisNames[3] = {"X", "Y", "Z"};
  for (int axis = 0; axis < 3; ++axis) {
    auto* box = new QDoubleSpinBox;
    box->setObjectName(QString("angle%1").arg(axisNames[axis]));
    box->setRange(-180.0, 180.0);
    box->setDecimals(1);
    box->setSingleStep(5.0);
    box->setSuffix(QString::fromUtf8("°"));
    box->setWrapping(true);
    box->setKeyboardTracking(false);  // one edit per Enter, not per keystroke
    box->setAccelerated(true);
    connect(box, &QDoubleSpinBox::valueChanged, this, [this] { applyTypedAngles(); });
    angles_[axis] = box;
    rotationForm->addRow(axisNames[axis], box);
  }
  auto* buttons = new QHBoxLayout;
  resetBone_ = new QPushButton(tr("Reset bone"));
  resetAll_ = new QPushButton(tr("Reset pose"));
  resetBone_->setToolTip(tr("Remove this bone's pose edit"));
  resetAll_->setToolTip(tr("Remove the pose edits of every bone"));
  connect(resetBone_, &QPushButton::clicked, this, &PropertiesPanel::resetBone);
  connect(resetAll_, &QPushButton::clicked, this, &PropertiesPanel::resetAllBones);
  buttons->addWidget(resetBone_);
  buttons->addWidget(resetAll_);
  rotationForm->addRow(buttons);
  layout->addWidget(rotation);
  return page;
}

QWidget* PropertiesPanel::makeMeshPage() {
  auto* box = new QGroupBox(tr("Mesh"));
  auto* form = new QFormLayout(box);
  meshName_ = new QLabel;
  meshVertices_ = new QLabel;
  meshTriangles_ = new QLabel;
  meshSkin_ = new QLabel;
  meshMorphs_ = new QLabel;
  form->addRow(tr("Name"), meshName_);
  form->addRow(tr("Vertices"), meshVertices_);
  form->addRow(tr("Triangles"), meshTriangles_);
  form->addRow(tr("Skinning"), meshSkin_);
  form->addRow(tr("Morph targets"), meshMorphs_);
  return box;
}

void PropertiesPanel::showSelection() {
  const Character& character = document_->character();
  const int bone = document_->selectedBone();
  const int mesh = document_->selectedMesh();
  if (bone >= 0) {
    const Bone& b = character.skeleton.bone(bone);
    boneName_->setText(QString::fromStdString(b.name));
    boneParent_->setText(b.parent >= 0 ? QString::fromStdString(character.skeleton.bone(b.parent).name) : tr("(root)"));
    QStringList children;
    for (int child : character.skeleton.children(bone))
      children << QString::fromStdString(character.skeleton.bone(child).name);
    boneChildren_->setText(children.isEmpty() ? tr("none") : children.join(", "));
    showBoneAngles();
    pages_->setCurrentIndex(BonePage);
  } else if (mesh >= 0) {
    const Mesh& m = character.meshes[mesh];
    meshName_->setText(QString::fromStdString(m.name));
    meshVertices_->setText(count(m.vertexCount()));
    meshTriangles_->setText(count(m.triangleCount()));
    meshSkin_->setText(
        m.skin.empty()
            ? tr("rigid")
            : tr("%1 joints, up to %2 per vertex").arg(m.skin.jointBones.size()).arg(m.skin.maxInfluences()));
    meshMorphs_->setText(QString::number(m.morphTargets.size()));
    pages_->setCurrentIndex(MeshPage);
  } else if (document_->selectedMaterial() >= 0) {
    materialPage_->showMaterial(document_->selectedMaterial());
    pages_->setCurrentIndex(MaterialPageIndex);
  } else {
    showCharacter();
    pages_->setCurrentIndex(CharacterPage);
  }
}

void PropertiesPanel::showBoneAngles() {
  const int bone = document_->selectedBone();
  if (bone < 0) return;
  const glm::vec3 degrees = eulerDegreesFromQuat(document_->boneRotation(bone).value_or(glm::quat(1, 0, 0, 0)));
  syncing_ = true;
  for (int axis = 0; axis < 3; ++axis)
    if (std::abs(angles_[axis]->value() - degrees[axis]) > 0.05) angles_[axis]->setValue(degrees[axis]);
  const auto& world = document_->posed().worldFromBone();
  if (bone < static_cast<int>(world.size())) {
    const glm::vec3 joint(world[bone][3]);
    boneJoint_->setText(QString("%1, %2, %3").arg(joint.x, 0, 'f', 3).arg(joint.y, 0, 'f', 3).arg(joint.z, 0, 'f', 3));
  }
  resetBone_->setEnabled(document_->boneRotation(bone).has_value());
  resetAll_->setEnabled(!document_->poseEdits().empty());
  syncing_ = false;
}

void PropertiesPanel::applyTypedAngles() {
  const int bone = document_->selectedBone();
  if (syncing_ || bone < 0) return;
  const glm::vec3 degrees(angles_[0]->value(), angles_[1]->value(), angles_[2]->value());
  document_->undoStack()->push(new SetBoneRotationCommand(document_, bone, quatFromEulerDegrees(degrees)));
}

void PropertiesPanel::resetBone() {
  const int bone = document_->selectedBone();
  if (bone < 0 || !document_->boneRotation(bone)) return;
  document_->undoStack()->push(new SetBoneRotationCommand(document_, bone, std::nullopt));
}

void PropertiesPanel::resetAllBones() {
  if (document_->poseEdits().empty()) return;
  document_->undoStack()->push(new SetPoseEditsCommand(document_, PoseEdits{}, tr("Reset pose")));
}

}  // namespace mq::ui
