#include "core/scene/open_scene.h"

#include "core/character/auto_rig.h"
#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/io/bvh_import.h"
#include "core/io/character_import.h"
#include "core/skinning/section_cones.h"
#include "core/skinning/weight_regeneration.h"
#include "core/util/error.h"
#include "core/util/thread_pool.h"

namespace mq {

int addMotion(Character& character, const std::string& bvhPath, const MotionOptions& options, BoneMatchReport* match) {
  RetargetedMotion motion = retargetBvhMotion(bvhPath, character, options);
  character.clips.push_back(std::move(motion.clip));
  if (match) *match = std::move(motion.match);
  return static_cast<int>(character.clips.size()) - 1;
}

PoseEdits poseEditsFromNames(const std::map<std::string, glm::quat>& rotations, const Skeleton& skeleton) {
  PoseEdits edits;
  for (const auto& [name, rotation] : rotations) {
    const int bone = skeleton.findBone(name);
    if (bone < 0) throw Error("pose edit for bone '" + name + "', which the character does not have");
    edits.rotations[bone] = rotation;
  }
  return edits;
}

LoadedScene resolveSceneDocument(const SceneDocument& document, const std::string& documentPath) {
  LoadedScene scene;
  scene.document = document;
  scene.documentPath = documentPath;
  if (!document.hasCharacter()) return scene;
  if (document.character == "default") {
    scene.character = makeDefaultMannequin();
  } else {
    scene.character = importCharacter(resolveDocumentPath(documentPath, document.character));
  }
  if (document.scale != 1.0f) scene.character.scaleUniformly(document.scale);
  if (document.autoRig) {
    try {
      autoRigHumanoid(scene.character, true, &ThreadPool::shared());
    } catch (const Error& e) {
      throw Error(std::string("auto_rig: ") + e.what());
    }
  }
  if (!document.motionFile.empty()) {
    MotionOptions options;
    if (!document.motionMapFile.empty())
      options.nameMapPath = resolveDocumentPath(documentPath, document.motionMapFile);
    options.inPlace = document.motionInPlace;
    scene.motionMatch.emplace();
    scene.clipIndex = addMotion(scene.character, resolveDocumentPath(documentPath, document.motionFile), options,
                                &*scene.motionMatch);
  }
  if (!document.clip.empty()) {
    scene.clipIndex = scene.character.findClip(document.clip);
    if (scene.clipIndex < 0) throw Error("the character has no clip '" + document.clip + "'");
  } else if (scene.clipIndex < 0 && document.firstClipWhenNone && !scene.character.clips.empty()) {
    scene.clipIndex = 0;
  }
  scene.edits = poseEditsFromNames(document.poseRotations, scene.character.skeleton);
  for (const Mesh& mesh : scene.character.meshes) scene.fileSkins.push_back(mesh.skin);
  if (document.weights.active()) regenerateWeights(scene.character, document.weights, &ThreadPool::shared());
  if (document.helperBones) {
    std::string why;
    if (addHelperBones(scene.character, &why) == 0)
      scene.character.loadWarnings.push_back("skinning.helper_bones: " + why);
  }
  scene.character.skinning = document.skinning;
  prepareSkinning(scene.character);
  scene.fileMaterials = scene.character.materials;
  applyMaterialOverrides(document.materials, scene.character);
  return scene;
}

std::vector<std::string> loadNotices(const LoadedScene& scene) {
  std::vector<std::string> notices = scene.character.loadWarnings;
  if (!scene.character.unitNotice.empty() && scene.document.scale == 1.0f)
    notices.push_back(scene.character.unitNotice);
  return notices;
}

void applyMaterialOverrides(const std::map<std::string, MaterialOverride>& overrides, Character& character) {
  for (const auto& [name, changes] : overrides) {
    bool found = false;
    for (Material& material : character.materials)
      if (material.name == name) {
        changes.applyTo(material);
        found = true;
      }
    if (!found)
      character.loadWarnings.push_back("the scene changes material '" + name + "', which " +
                                       (character.name.empty() ? std::string("the character") : character.name) +
                                       " does not have; the change is kept but unused");
  }
}

LoadedScene openScene(const std::string& fileOrDefault) {
  SceneDocument bare;  // a character without a document: it plays its first clip
  bare.firstClipWhenNone = true;
  if (fileOrDefault == "default") return resolveSceneDocument(bare, "");
  if (isSceneDocumentPath(fileOrDefault)) {
    const SceneDocument document = loadSceneDocument(fileOrDefault);
    try {
      return resolveSceneDocument(document, fileOrDefault);
    } catch (const FileError&) {
      throw;  // already names the file that failed (the character or motion)
    } catch (const Error& e) {
      throw FileError(fileOrDefault, e.what());
    }
  }
  bare.character = fileOrDefault;
  return resolveSceneDocument(bare, "");
}

}  // namespace mq
