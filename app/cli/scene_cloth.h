#pragma once
// What `simulate` and `export --with` share of a scene's cloth: the posed
// body the cloth collides with, and the sheet of the document's "cloth"
// section.

#include <memory>
#include <vector>

#include "core/character/posed_character.h"
#include "core/scene/open_scene.h"
#include "sim/cloth/cloth_scene_io.h"
#include "sim/cloth/cloth_simulator.h"

namespace mq::cli {

// The body the cloth collides with: all of the character's meshes, posed.
class PosedBody {
 public:
  explicit PosedBody(const LoadedScene& scene) : scene_(scene) {}
  bool empty() const { return scene_.character.meshes.empty(); }
  // The scene's clip at `time` with its pose edits; rest: the rest pose
  // without edits (where garment patterns are placed).
  void pose(float time, std::vector<float>& positions, std::vector<uint32_t>* triangles, bool rest = false);

 private:
  const LoadedScene& scene_;
  PosedCharacter posed_;
};

// The sheet of the document's "cloth" section (null when it has none), with
// its colliders, pins and the body.
std::unique_ptr<cloth::ClothSimulator> makeSheet(const cloth::ClothSceneSpec& spec, const std::vector<float>& body,
                                                 const std::vector<uint32_t>& bodyTriangles);

}  // namespace mq::cli
