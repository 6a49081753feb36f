#pragma once
// Writes a character as a rigged glTF 2.0 / GLB: its skeleton as nodes, each
// skinned mesh in bind space with JOINTS_0 / WEIGHTS_0 and a skin, meshes
// that follow one bone as that bone's children, morph targets with their
// names, the materials with their textures embedded, and every clip as an
// animation sampled at `fps` on the clip's own time axis (linear
// translation, rotation, scale and morph weights). Procedural bones (helper
// bones) are baked into the samples, so any engine plays them with plain
// linear blend skinning.
//
// A take (a simulation's frames) writes one animation instead: the clip the
// frames were simulated on, sampled at each frame, and the baked surfaces
// (garments, hair) as meshes whose frames are morph targets, one per frame
// after the first, played by a weights animation in the same take. Written
// atomically; failures throw FileError naming the file.

#include <optional>
#include <string>
#include <vector>

#include "core/character/character.h"
#include "core/io/baked_surface.h"

namespace mq {

struct ExportTake {
  std::string name;    // the animation's name
  int clip = -1;       // -1: the rest pose
  float start = 0.0f;  // clip time of frame 0
  float fps = 30.0f;
  int frames = 1;
  const PoseEdits* edits = nullptr;  // the scene's pose edits, or null
};

struct RiggedExportOptions {
  float fps = 30.0f;                // the clips' sampling rate (no take)
  std::optional<ExportTake> take;   // one animation of these frames instead of every clip
  std::vector<BakedSurface> baked;  // needs a take with as many frames
};

// Returns warnings (an image that could not be embedded); the file is written anyway.
std::vector<std::string> exportRiggedCharacter(const Character& character, const std::string& path,
                                               const RiggedExportOptions& options);
inline std::vector<std::string> exportRiggedCharacter(const Character& character, const std::string& path, float fps) {
  RiggedExportOptions options;
  options.fps = fps;
  return exportRiggedCharacter(character, path, options);
}

// True when `path` ends in .gltf or .glb.
bool isRiggedExportPath(const std::string& path);

}  // namespace mq
