#pragma once
// The scene document: a versioned JSON file (extension .mqscene; .json is
// accepted too) that records what a user made: the character (the built-in
// mannequin, a file, or none), a motion, pose edits, the current clip and
// time, view settings, and the hair, garment, cloth and collider sections
// that their own modules parse.
//
//   { "format": "mannequin-scene", "version": 1,
//     "character": "default" | "relative/or/absolute/path.glb" | null,
//     "motion": {"file": "walk.bvh", "map": "names.txt", "inPlace": false},   (optional)
//     "animation": {"clip": "walk", "time": 0.5},
//     "pose": {"upperarm_l": [x, y, z, w], ...},   local rotation edits
//     "view": {"skeleton": false, "weights": false, "cones": false, "look": "auto", "camera": {"position": [..],
//     "focus": [..]}}, "skinning": {"method": "lbs" | "dqs" | "cones",    (absent: lbs)
//                  "helper_bones": bool,                (absent: false)
//                  "weights": {"regenerate": bool, "smooth": bool, ...}},
//                                      (weight_regeneration.h; absent: the file's)
//     "scale": 0.01,   the character file's units to metres (absent: 1)
//     "auto_rig": true,   give a mesh without bones a humanoid skeleton (auto_rig.h; absent: false)
//     "materials": {"<name>": {...}},   user changes to the file's materials
//                                       (core/material/material_override.h)
//     "hair": {...}, "garments": [...], "cloth": {...}, "colliders": [...] }

#include <map>
#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "core/character/character.h"
#include "core/material/material_override.h"
#include "core/skinning/weight_regeneration.h"

namespace mq {

struct ViewSettings {
  bool showSkeleton = false;
  bool showWeights = false;   // the selected bone's skin weights as a heat map
  bool showCones = false;     // the section cones around the limbs
  std::string look = "auto";  // surface look: auto, skin, mannequin or plain
  bool hasCamera = false;
  glm::vec3 cameraPosition{0.0f};
  glm::vec3 cameraFocus{0.0f};
};

struct SceneDocument {
  static constexpr int kFormatVersion = 1;

  std::string character = "default";  // "default", a file path, or "" for none
  std::string motionFile;             // BVH applied to the character, optional
  std::string motionMapFile;          // bone-name map for the BVH, optional
  bool motionInPlace = false;         // the root's horizontal travel dropped
  std::string clip;                   // clip name or index; "" = none, the rest pose with the pose edits
  // Not saved: a document made for a bare character file (or "default")
  // plays the file's first clip when `clip` is "".
  bool firstClipWhenNone = false;
  float time = 0.0f;
  std::map<std::string, glm::quat> poseRotations;  // bone name -> local rotation edit
  ViewSettings view;
  SkinningMethod skinning = SkinningMethod::Lbs;
  bool helperBones = false;                           // add helper bones at the joints (helper_bones.h) on open
  WeightSettings weights;                             // regenerate or smooth the file's weights on open
  float scale = 1.0f;                                 // applied to the character at load (its file's units to metres)
  bool autoRig = false;                               // a mesh without bones gets a humanoid skeleton on open
  std::map<std::string, MaterialOverride> materials;  // by material name
  // Sections owned by other modules (null when absent).
  nlohmann::json hair;
  nlohmann::json garments;
  nlohmann::json cloth;
  nlohmann::json colliders;

  bool hasCharacter() const { return !character.empty(); }
};

// True when `path` names a scene document (by extension).
bool isSceneDocumentPath(const std::string& path);

// Parses a document; throws FileError naming the file and the problem
// (not JSON, not a scene document, written by a newer version, bad values).
SceneDocument loadSceneDocument(const std::string& path);
SceneDocument parseSceneDocument(const std::string& text, const std::string& pathForErrors);
nlohmann::json toJson(const SceneDocument& document);
// Writes atomically (temporary file, then rename).
void saveSceneDocument(const SceneDocument& document, const std::string& path);

// Resolves a path stored in a document relative to the document's folder.
std::string resolveDocumentPath(const std::string& documentPath, const std::string& stored);
// Rewrites the document's file paths (character, motion, name map), stored
// relative to `fromPath` (a document, or "" for the working folder), to be
// relative to `toPath`, where the document is about to be saved.
void rebaseDocumentPaths(SceneDocument& document, const std::string& fromPath, const std::string& toPath);

}  // namespace mq
