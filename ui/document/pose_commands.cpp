#include "ui/document/pose_commands.h"

#include <QCoreApplication>

#include "ui/document/editor_document.h"

namespace mq::ui {

SetBoneRotationCommand::SetBoneRotationCommand(EditorDocument* document, int bone, std::optional<glm::quat> after,
                                               int dragId)
    : document_(document), bone_(bone), before_(document->boneRotation(bone)), after_(after), dragId_(dragId) {
  const QString name = QString::fromStdString(document->character().skeleton.bone(bone).name);
  setText(after ? QCoreApplication::translate("mq", "Rotate %1").arg(name)
                : QCoreApplication::translate("mq", "Reset %1").arg(name));
}

void SetBoneRotationCommand::undo() { document_->setBoneRotation(bone_, before_); }
void SetBoneRotationCommand::redo() { document_->setBoneRotation(bone_, after_); }

bool SetBoneRotationCommand::mergeWith(const QUndoCommand* other) {
  const auto* next = static_cast<const SetBoneRotationCommand*>(other);
  if (dragId_ == 0 || next->dragId_ != dragId_ || next->bone_ != bone_) return false;
  after_ = next->after_;
  return true;
}

int SetBoneRotationCommand::nextDragId() {
  static int counter = 0;
  return ++counter;
}

SetPoseEditsCommand::SetPoseEditsCommand(EditorDocument* document, PoseEdits after, const QString& text)
    : document_(document), before_(document->poseEdits()), after_(std::move(after)) {
  setText(text);
}

void SetPoseEditsCommand::undo() { document_->setPoseEdits(before_); }
void SetPoseEditsCommand::redo() { document_->setPoseEdits(after_); }

SetSkinningCommand::SetSkinningCommand(EditorDocument* document, SkinningMethod after)
    : document_(document), before_(document->skinning()), after_(after) {
  setText(QObject::tr("Skinning: %1").arg(skinningMethodName(after)));
}

void SetSkinningCommand::undo() { document_->setSkinning(before_); }
void SetSkinningCommand::redo() { document_->setSkinning(after_); }

SetHelperBonesCommand::SetHelperBonesCommand(EditorDocument* document, bool on) : document_(document), on_(on) {
  setText(on ? QObject::tr("Add helper bones") : QObject::tr("Remove helper bones"));
}

void SetHelperBonesCommand::undo() { document_->setHelperBones(!on_); }
void SetHelperBonesCommand::redo() { document_->setHelperBones(on_); }

SetWeightSettingsCommand::SetWeightSettingsCommand(EditorDocument* document, const WeightSettings& after)
    : SetWeightSettingsCommand(document, document->weightSettings(), after, false) {}

SetWeightSettingsCommand::SetWeightSettingsCommand(EditorDocument* document, const WeightSettings& before,
                                                   const WeightSettings& after, bool applied)
    : document_(document), before_(before), after_(after), skipRedo_(applied) {
  setText(after.active() ? QObject::tr("Rebuild weights") : QObject::tr("File weights"));
}

void SetWeightSettingsCommand::undo() { document_->setWeightSettings(before_); }

void SetWeightSettingsCommand::redo() {
  if (skipRedo_) {
    skipRedo_ = false;
    return;
  }
  document_->setWeightSettings(after_);
}

}  // namespace mq::ui
