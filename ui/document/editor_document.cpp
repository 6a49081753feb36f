#include "ui/document/editor_document.h"

#include <algorithm>

#include <QLocale>
#include <QUndoStack>

#include "core/character/auto_rig.h"
#include "core/character/posed_character.h"
#include "core/skinning/section_cones.h"
#include "core/util/error.h"
#include "core/util/thread_pool.h"

namespace mq::ui {

EditorDocument::EditorDocument(QObject* parent) : QObject(parent), undoStack_(new QUndoStack(this)) {
  connect(undoStack_, &QUndoStack::cleanChanged, this, [this] { emit modifiedChanged(isModified()); });
}

EditorDocument::~EditorDocument() = default;

void EditorDocument::replace(LoadedDocument loaded) {
  undoStack_->clear();
  character_ = std::move(loaded.character);
  scene_ = std::move(loaded.scene);
  documentPath_ = loaded.documentPath;
  displayName_ = loaded.displayName;
  edits_ = std::move(loaded.edits);
  clipIndex_ = loaded.clipIndex < static_cast<int>(character_.clips.size()) ? loaded.clipIndex : -1;
  noClipDuration_ = 0.0f;
  time_ = clipIndex_ >= 0 ? std::clamp(scene_.time, clipStart(), clipEnd()) : 0.0f;
  selectedBone_ = -1;
  selectedMesh_ = -1;
  selectedMaterial_ = -1;
  fileMaterials_ = std::move(loaded.fileMaterials);
  if (fileMaterials_.size() != character_.materials.size()) fileMaterials_ = character_.materials;
  fileSkins_ = std::move(loaded.fileSkins);
  weightReport_ = {};
  if (fileSkins_.size() != character_.meshes.size()) {  // the skins before any helper bones
    fileSkins_.clear();
    const bool helpers = character_.skinsBeforeHelpers.size() == character_.meshes.size();
    for (size_t m = 0; m < character_.meshes.size(); ++m)
      fileSkins_.push_back(helpers ? character_.skinsBeforeHelpers[m] : character_.meshes[m].skin);
  }
  unsavedSectionChanges_ = false;
  evaluatePose();
  emit characterReplaced();
  emit clipsChanged();
  emit clipChanged(clipIndex_);
  emit timeChanged(time_);
  emit selectionChanged();
  emit viewSettingsChanged();
  emit poseChanged();
  emit documentChanged();
  emit modifiedChanged(false);
}

void EditorDocument::setDocumentPath(const QString& path) {
  documentPath_ = path;
  displayName_ = path.section('/', -1);
}

bool EditorDocument::isModified() const { return !undoStack_->isClean() || unsavedSectionChanges_; }

void EditorDocument::markSaved() {
  unsavedSectionChanges_ = false;
  undoStack_->setClean();
  emit modifiedChanged(false);
}

void EditorDocument::notifyChanged() {
  unsavedSectionChanges_ = true;
  emit documentChanged();
  emit modifiedChanged(true);
}

QString EditorDocument::summary() const {
  const QLocale locale;
  return tr("%1 vertices, %2 triangles, %3 bones, %4 clips")
      .arg(locale.toString(qulonglong(character_.vertexCount())))
      .arg(locale.toString(qulonglong(character_.triangleCount())))
      .arg(character_.skeleton.boneCount())
      .arg(character_.clips.size());
}

// --- pose ---------------------------------------------------------------------

std::optional<glm::quat> EditorDocument::boneRotation(int bone) const {
  const auto it = edits_.rotations.find(bone);
  if (it == edits_.rotations.end()) return std::nullopt;
  return it->second;
}

void EditorDocument::setBoneRotation(int bone, std::optional<glm::quat> rotation) {
  if (bone < 0 || bone >= character_.skeleton.boneCount()) return;
  if (rotation)
    edits_.rotations[bone] = glm::normalize(*rotation);
  else
    edits_.rotations.erase(bone);
  evaluatePose();
  emit poseChanged();
  emit documentChanged();
}

void EditorDocument::setPoseEdits(const PoseEdits& edits) {
  edits_ = edits;
  evaluatePose();
  emit poseChanged();
  emit documentChanged();
}

void EditorDocument::setSkinning(SkinningMethod method) {
  if (method == character_.skinning) return;
  character_.skinning = method;
  scene_.skinning = method;
  prepareSkinning(character_);
  evaluatePose();
  emit poseChanged();
  emit documentChanged();
}

std::string EditorDocument::setHelperBones(bool on) {
  if (on == helperBones()) return {};
  if (on) {
    std::string why;
    if (addHelperBones(character_, &why) == 0) return why;
  } else {
    removeHelperBones(character_);
    const int bones = character_.skeleton.boneCount();
    for (auto it = edits_.rotations.begin(); it != edits_.rotations.end();)
      it = it->first >= bones ? edits_.rotations.erase(it) : std::next(it);
    if (selectedBone_ >= bones) selectedBone_ = -1;
  }
  scene_.helperBones = on;
  skeletonEdited();
  return {};
}

// After bones came or went: the skin is bound again and everyone told.
void EditorDocument::skeletonEdited() {
  prepareSkinning(character_);
  evaluatePose();
  emit skeletonChanged();
  emit selectionChanged();
  emit poseChanged();
  emit documentChanged();
}

std::string EditorDocument::setAutoRig(bool on) {
  if (on == scene_.autoRig) return {};
  if (on) {
    if (character_.skeleton.boneCount() > 0) return "the character has its own skeleton";
    Character rigged = character_;
    try {
      autoRigHumanoid(rigged, true, &ThreadPool::shared());
    } catch (const Error& e) {
      return e.what();
    }
    unrigged_ = std::move(character_);
    character_ = std::move(rigged);
  } else {
    if (unrigged_) {
      character_ = std::move(*unrigged_);
      unrigged_.reset();
    } else {  // rigged when the document opened: the mesh keeps its place, the bones go
      character_.skeleton = Skeleton();
      character_.helperBones.clear();
      character_.skinsBeforeHelpers.clear();
      for (Mesh& mesh : character_.meshes) mesh.skin = SkinBinding(), mesh.dropSkinningBindings();
    }
    character_.clips.clear();  // their channels drive bones that are gone
    clipIndex_ = -1;
    emit clipChanged(clipIndex_);
  }
  scene_.autoRig = on;
  scene_.helperBones = false;
  scene_.weights = WeightSettings();
  edits_ = PoseEdits();
  fileSkins_.clear();
  for (const Mesh& mesh : character_.meshes) fileSkins_.push_back(mesh.skin);
  selectedBone_ = -1;
  skeletonEdited();
  return {};
}

bool EditorDocument::setWeightSettings(const WeightSettings& settings, const WeightCallbacks* callbacks) {
  if (settings == scene_.weights) return true;
  const SkinningSnapshot before(character_);
  const bool helpers = helperBones();
  if (helpers) removeHelperBones(character_);
  for (size_t m = 0; m < character_.meshes.size(); ++m) {
    character_.meshes[m].skin = fileSkins_[m];
    character_.meshes[m].dropSkinningBindings();
  }
  WeightReport report = regenerateWeights(character_, settings, &ThreadPool::shared(), callbacks);
  if (report.cancelled) {
    before.restore(character_);
    prepareSkinning(character_);
    return false;
  }
  weightReport_ = report;
  if (helpers) addHelperBones(character_);
  scene_.weights = settings;
  prepareSkinning(character_);
  evaluatePose();
  emit weightsChanged();
  emit poseChanged();
  emit documentChanged();
  return true;
}

void EditorDocument::evaluatePose() { posed_.evaluate(character_, clipIndex_, time_, &edits_, &ThreadPool::shared()); }

// --- animation ------------------------------------------------------------------

float EditorDocument::clipStart() const { return clipIndex_ >= 0 ? character_.clips[clipIndex_].startTime() : 0.0f; }

float EditorDocument::clipEnd() const {
  return clipIndex_ >= 0 ? character_.clips[clipIndex_].endTime() : noClipDuration_;
}

void EditorDocument::setNoClipDuration(float seconds) {
  seconds = std::max(0.0f, seconds);
  if (seconds == noClipDuration_) return;
  noClipDuration_ = seconds;
  emit timeAxisChanged();
  if (clipIndex_ < 0 && time_ > seconds) setTime(seconds);
}

void EditorDocument::setClip(int clipIndex) {
  if (clipIndex < -1 || clipIndex >= static_cast<int>(character_.clips.size()) || clipIndex == clipIndex_) return;
  clipIndex_ = clipIndex;
  time_ = clipStart();
  evaluatePose();
  emit clipChanged(clipIndex_);
  emit timeChanged(time_);
  emit poseChanged();
  emit documentChanged();
}

void EditorDocument::setTime(float seconds) {
  seconds = std::clamp(seconds, clipStart(), clipEnd());
  if (seconds == time_) return;
  time_ = seconds;
  evaluatePose();
  emit timeChanged(time_);
  emit poseChanged();
  emit documentChanged();
}

void EditorDocument::addClip(Clip clip) {
  character_.clips.push_back(std::move(clip));
  emit clipsChanged();
  clipIndex_ = -2;  // force setClip to apply and signal
  setClip(static_cast<int>(character_.clips.size()) - 1);
}

void EditorDocument::removeLastClip(int clipIndex, float seconds) {
  if (character_.clips.empty()) return;
  clipIndex_ = -1;  // the panels must not read the clip going away
  character_.clips.pop_back();
  emit clipsChanged();
  clipIndex_ = -2;  // force setClip to apply and signal
  setClip(std::min(clipIndex, static_cast<int>(character_.clips.size()) - 1));
  setTime(seconds);
}

// --- selection and view -------------------------------------------------------------

void EditorDocument::selectBone(int bone) { setSelection(bone < character_.skeleton.boneCount() ? bone : -1, -1, -1); }

void EditorDocument::selectMesh(int mesh) {
  setSelection(-1, mesh < static_cast<int>(character_.meshes.size()) ? mesh : -1, -1);
}

void EditorDocument::selectMaterial(int material) {
  setSelection(-1, -1, material < static_cast<int>(character_.materials.size()) ? material : -1);
}

// At most one of the three is selected (the others -1).
void EditorDocument::setSelection(int bone, int mesh, int material) {
  if (bone == selectedBone_ && mesh == selectedMesh_ && material == selectedMaterial_) return;
  selectedBone_ = bone;
  selectedMesh_ = mesh;
  selectedMaterial_ = material;
  emit selectionChanged();
}

bool EditorDocument::selectByName(const std::string& name) {
  if (const int bone = character_.skeleton.findBone(name); bone >= 0) {
    selectBone(bone);
    return true;
  }
  for (size_t i = 0; i < character_.materials.size(); ++i)
    if (character_.materials[i].name == name) {
      selectMaterial(static_cast<int>(i));
      return true;
    }
  for (size_t i = 0; i < character_.meshes.size(); ++i)
    if (character_.meshes[i].name == name) {
      selectMesh(static_cast<int>(i));
      return true;
    }
  return false;
}

void EditorDocument::setMaterial(int index, const Material& material) {
  if (index < 0 || index >= static_cast<int>(character_.materials.size())) return;
  character_.materials[index] = material;
  const MaterialOverride changes = MaterialOverride::between(fileMaterials_[index], material);
  if (changes.empty())
    scene_.materials.erase(material.name);
  else
    scene_.materials[material.name] = changes;
  emit materialChanged(index);
  emit documentChanged();
}

const Material* EditorDocument::fileMaterial(int index) const {
  return index >= 0 && index < static_cast<int>(fileMaterials_.size()) ? &fileMaterials_[index] : nullptr;
}

void EditorDocument::setLook(const std::string& look) {
  if (scene_.view.look == look) return;
  scene_.view.look = look;
  notifyChanged();
  emit viewSettingsChanged();
}

void EditorDocument::setWeightsVisible(bool visible) {
  if (scene_.view.showWeights == visible) return;
  scene_.view.showWeights = visible;
  emit viewSettingsChanged();
}

void EditorDocument::setConesVisible(bool visible) {
  if (scene_.view.showCones == visible) return;
  scene_.view.showCones = visible;
  emit viewSettingsChanged();
}

void EditorDocument::setSkeletonVisible(bool visible) {
  if (scene_.view.showSkeleton == visible) return;
  scene_.view.showSkeleton = visible;
  emit viewSettingsChanged();
}

SceneDocument EditorDocument::sceneDocument() const {
  SceneDocument out = scene_;
  out.poseRotations.clear();
  for (const auto& [bone, rotation] : edits_.rotations)
    out.poseRotations[character_.skeleton.bone(bone).name] = rotation;
  out.clip = clipIndex_ >= 0 ? character_.clips[clipIndex_].name : std::string();
  out.time = time_;
  return out;
}

}  // namespace mq::ui
