#pragma once
// The document open in the editor: the loaded character, the scene document
// it belongs to (pose edits, clip, time, view settings, the hair and garment
// sections), the posed meshes at the current time, the selection and the undo
// stack. Widgets observe its signals; every pose change goes through an undo
// command (ui/document/pose_commands.h) which calls setBoneRotation.

#include <optional>

#include <QObject>
#include <QString>

#include "core/character/character.h"
#include "core/character/posed_character.h"
#include "core/scene/scene_document.h"

class QUndoStack;

namespace mq::ui {

// What a file open produces, before it replaces the current document.
struct LoadedDocument {
  Character character;
  SceneDocument scene;
  PoseEdits edits;                      // scene.poseRotations by bone index
  int clipIndex = -1;                   // current clip, -1 for the rest pose
  std::vector<Material> fileMaterials;  // the file's materials before the scene's changes
  std::vector<SkinBinding> fileSkins;   // the file's weights before the scene rebuilt them
  QString documentPath;                 // the scene file, empty for a character file or "default"
  QString displayName;                  // for the title bar
};

class EditorDocument : public QObject {
  Q_OBJECT

 public:
  explicit EditorDocument(QObject* parent = nullptr);
  ~EditorDocument() override;

  // Replaces everything (character, edits, clip, time, selection); clears undo.
  void replace(LoadedDocument loaded);

  const Character& character() const { return character_; }
  // "30,362 vertices, 60,720 triangles, 21 bones, 2 clips"
  QString summary() const;
  const PosedCharacter& posed() const { return posed_; }
  const PoseEdits& poseEdits() const { return edits_; }
  QUndoStack* undoStack() const { return undoStack_; }

  // File identity
  const QString& documentPath() const { return documentPath_; }
  const QString& displayName() const { return displayName_; }
  void setDocumentPath(const QString& path);
  bool isModified() const;
  void markSaved();

  // Pose edits (local rotation after the clip's): nullopt removes the edit.
  std::optional<glm::quat> boneRotation(int bone) const;
  void setBoneRotation(int bone, std::optional<glm::quat> rotation);
  void setPoseEdits(const PoseEdits& edits);

  // Animation
  int clipIndex() const { return clipIndex_; }  // -1: rest pose
  float time() const { return time_; }
  void setClip(int clipIndex);
  void setTime(float seconds);
  // Start and end of the current clip's time axis (0, 0 for the rest pose,
  // 0 and the no-clip duration when one is set).
  float clipStart() const;
  float clipEnd() const;
  // A time axis from 0 to `seconds` while no clip plays (0: none): a scene of
  // cloth and colliders without a character scrubs its bake on it (the
  // garment tool sets it from the bake's length). The pose stays the rest pose.
  void setNoClipDuration(float seconds);
  // Adds a clip (e.g. an imported BVH motion) and makes it current. Callers
  // outside the undo stack mark the change with notifyChanged().
  void addClip(Clip clip);
  // Removes the last clip (undoing addClip) and returns to `clipIndex` at
  // `seconds`.
  void removeLastClip(int clipIndex, float seconds);

  // How the skin follows the bones (saved in the document's "skinning").
  SkinningMethod skinning() const { return character_.skinning; }
  // Binds the section cones on first use of that method.
  void setSkinning(SkinningMethod method);
  // Helper bones at the joints (saved in the document's skinning section).
  // Adding them to a character that cannot have them changes nothing and
  // returns why; removing gives the weights back.
  bool helperBones() const { return !character_.helperBones.empty(); }
  std::string setHelperBones(bool on);
  // A mesh without bones given a humanoid skeleton (core/character/auto_rig.h;
  // saved as "auto_rig"); off, the mesh goes back to no bones, and the clips
  // and pose edits made on the rig go with it. Returns why it cannot (the
  // mesh has bones of its own, or is not a standing person).
  bool autoRigged() const { return scene_.autoRig; }
  std::string setAutoRig(bool on);
  // Rebuilt skin weights (weight_regeneration.h), saved in the document;
  // inactive settings give the file's weights back. `callbacks` report the
  // rebuild's progress and may cancel it: false then, and nothing changed.
  const WeightSettings& weightSettings() const { return scene_.weights; }
  bool setWeightSettings(const WeightSettings& settings, const WeightCallbacks* callbacks = nullptr);
  // What the last rebuild did (empty for the file's weights).
  const WeightReport& weightReport() const { return weightReport_; }

  // Materials: the user's changes are saved in the scene document as
  // overrides of the file's material (the file is never modified).
  void setMaterial(int index, const Material& material);
  // The material as the file has it, without the user's changes.
  const Material* fileMaterial(int index) const;
  // The surface look (auto, skin, mannequin, plain), saved in the view settings.
  void setLook(const std::string& look);

  // Selection
  int selectedBone() const { return selectedBone_; }
  int selectedMesh() const { return selectedMesh_; }
  int selectedMaterial() const { return selectedMaterial_; }
  void selectBone(int bone);  // -1 clears
  void selectMesh(int mesh);
  void selectMaterial(int material);
  // Selects the bone, else the material, else the mesh of that name; false if none.
  bool selectByName(const std::string& name);

  // View settings stored in the document
  const ViewSettings& viewSettings() const { return scene_.view; }
  void setSkeletonVisible(bool visible);
  // The selected bone's skin weights drawn as a heat map (saved in the view).
  void setWeightsVisible(bool visible);
  // The section cones drawn around the limbs (saved in the view).
  void setConesVisible(bool visible);

  // The scene document as it should be saved now (pose edits by bone name,
  // clip, time and the sections other modules own).
  SceneDocument sceneDocument() const;
  // Sections owned by other modules (hair, garments, ...): read and replace.
  SceneDocument& sceneSections() { return scene_; }
  // Tools that change a section call this so the title shows the change.
  void notifyChanged();

 signals:
  void characterReplaced();
  void skeletonChanged();  // bones added or removed on the same character (helper bones)
  void poseChanged();      // the posed meshes changed (edit, clip or time)
  void weightsChanged();   // the skin weights were rebuilt or given back
  void timeChanged(float seconds);
  void clipChanged(int clipIndex);
  void clipsChanged();     // the list of clips changed
  void timeAxisChanged();  // clipStart() or clipEnd() changed without a clip change
  void selectionChanged();
  void viewSettingsChanged();
  void materialChanged(int index);
  // Any change at all (for tools that keep derived data, e.g. hair, cloth).
  void documentChanged();
  void modifiedChanged(bool modified);

 private:
  void evaluatePose();
  void skeletonEdited();
  void setSelection(int bone, int mesh, int material);

  Character character_;
  SceneDocument scene_;
  PoseEdits edits_;
  PosedCharacter posed_;
  QString documentPath_;
  QString displayName_;
  int clipIndex_ = -1;
  float time_ = 0.0f;
  float noClipDuration_ = 0.0f;
  int selectedBone_ = -1;
  int selectedMesh_ = -1;
  int selectedMaterial_ = -1;
  std::vector<Material> fileMaterials_;
  std::vector<SkinBinding> fileSkins_;
  std::optional<Character> unrigged_;  // the mesh before the auto-rig, when the editor rigged it
  WeightReport weightReport_;
  bool unsavedSectionChanges_ = false;  // changes outside the undo stack
  QUndoStack* undoStack_ = nullptr;
};

}  // namespace mq::ui
