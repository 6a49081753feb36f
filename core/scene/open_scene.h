#pragma once
// Opening whatever a user names: the word "default" (the built-in mannequin),
// a character file (glTF, GLB, FBX, DAE, BVH) or a scene document. The CLI
// and the editor both go through here, so they agree on what a FILE means.

#include <optional>
#include <string>

#include "core/character/character.h"
#include "core/io/bvh_import.h"
#include "core/scene/scene_document.h"

namespace mq {

struct LoadedScene {
  SceneDocument document;
  std::string documentPath;  // empty unless opened from a scene document
  Character character;       // empty skeleton and meshes when the scene has none
  int clipIndex = -1;        // current clip, -1 for none
  PoseEdits edits;           // document pose rotations mapped to bone indices
  // The character file's materials before the document's changes (the
  // editor diffs against them when it saves).
  std::vector<Material> fileMaterials;
  // The file's skin weights per mesh, before the document rebuilt them
  // (weight_regeneration.h) or added helper bones.
  std::vector<SkinBinding> fileSkins;
  // How the document's motion was paired with the character (when it has one).
  std::optional<BoneMatchReport> motionMatch;
};

// Applies a document's material changes to `character` by material name; a
// name the character lacks becomes a load warning.
void applyMaterialOverrides(const std::map<std::string, MaterialOverride>& overrides, Character& character);

// Throws FileError naming the file and the problem.
LoadedScene openScene(const std::string& fileOrDefault);

// What a user should read after loading: the load warnings, and the unit
// notice unless the scene scales the character.
std::vector<std::string> loadNotices(const LoadedScene& scene);

// Loads the character a document refers to and applies its motion, clip and
// pose. `documentPath` resolves relative paths ("" = relative to the cwd).
LoadedScene resolveSceneDocument(const SceneDocument& document, const std::string& documentPath);

// Adds a BVH motion to `character` as a new clip and returns its index;
// `match` (optional) receives how its joints were paired with the bones.
int addMotion(Character& character, const std::string& bvhPath, const MotionOptions& options = {},
              BoneMatchReport* match = nullptr);

// Pose rotations keyed by bone name -> bone index (unknown names throw Error).
PoseEdits poseEditsFromNames(const std::map<std::string, glm::quat>& rotations, const Skeleton& skeleton);

}  // namespace mq
