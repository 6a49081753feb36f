#pragma once
// Undoable pose edits. Every change of a bone's rotation, typed or dragged,
// is one of these on the document's QUndoStack. Consecutive steps of one
// drag of one bone merge into a single command (same bone, same drag id).

#include <optional>

#include <QUndoCommand>

#include "core/character/character.h"
#include "core/skinning/weight_regeneration.h"

namespace mq::ui {

class EditorDocument;

class SetBoneRotationCommand : public QUndoCommand {
 public:
  // dragId 0: never merges; a gizmo drag passes the same non-zero id for all
  // of its steps.
  SetBoneRotationCommand(EditorDocument* document, int bone, std::optional<glm::quat> after, int dragId = 0);

  void undo() override;
  void redo() override;
  int id() const override { return 0x6d71; }
  bool mergeWith(const QUndoCommand* other) override;

  int bone() const { return bone_; }

  // A fresh id for a new drag.
  static int nextDragId();

 private:
  EditorDocument* document_;
  int bone_;
  std::optional<glm::quat> before_;
  std::optional<glm::quat> after_;
  int dragId_;
};

// Replaces all pose edits at once (reset pose, paste pose).
class SetPoseEditsCommand : public QUndoCommand {
 public:
  SetPoseEditsCommand(EditorDocument* document, PoseEdits after, const QString& text);
  void undo() override;
  void redo() override;

 private:
  EditorDocument* document_;
  PoseEdits before_;
  PoseEdits after_;
};

// Switches the skinning method (LBS, dual quaternions, section cones).
class SetSkinningCommand : public QUndoCommand {
 public:
  SetSkinningCommand(EditorDocument* document, SkinningMethod after);
  void undo() override;
  void redo() override;

 private:
  EditorDocument* document_;
  SkinningMethod before_;
  SkinningMethod after_;
};

// Adds or removes the helper bones at the joints.
class SetHelperBonesCommand : public QUndoCommand {
 public:
  SetHelperBonesCommand(EditorDocument* document, bool on);
  void undo() override;
  void redo() override;

 private:
  EditorDocument* document_;
  bool on_;
};

// Rebuilds the skin weights with other settings (or gives the file's back).
// A panel that rebuilt them already, with progress, passes `before` and
// `applied`: the first redo then has nothing to do.
class SetWeightSettingsCommand : public QUndoCommand {
 public:
  SetWeightSettingsCommand(EditorDocument* document, const WeightSettings& after);
  SetWeightSettingsCommand(EditorDocument* document, const WeightSettings& before, const WeightSettings& after,
                           bool applied);
  void undo() override;
  void redo() override;

 private:
  EditorDocument* document_;
  WeightSettings before_, after_;
  bool skipRedo_ = false;
};

}  // namespace mq::ui
