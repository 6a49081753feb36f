#pragma once
// The hair of a scene document for the headless commands (simulate, render):
// the "hair" section groomed on the scene's character in its rest pose, then
// driven by the character's pose. Each guide root is anchored to the nearest
// triangle of the skinned mesh (barycentric point plus an offset in the
// triangle's frame), so the roots follow the skinned scalp; the guides'
// dynamics (sim/hair) collide with the body proxies posed on the skeleton,
// and the children follow their guides. Dynamics: characterHairParams().

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/character/posed_character.h"
#include "core/hair/hair_groom.h"
#include "core/hair/hairstyle_json.h"
#include "core/scene/open_scene.h"
#include "sim/hair/hair_bake.h"
#include "sim/hair/hair_simulator.h"

namespace mq::cli {

bool sceneHasHair(const LoadedScene& scene);

// The document's hair section; FileError naming the document when invalid.
HairSection sceneHairSection(const LoadedScene& scene);

class SceneHair {
 public:
  // Grooms `section` on the scene's character (throws FileError naming the
  // document when the groom is impossible, e.g. no scalp).
  SceneHair(const LoadedScene& scene, const HairSection& section);
  // The clip the character plays (default: the scene's current clip, -1 none).
  void setClip(int clipIndex) { clip_ = clipIndex; }

  const HairGroom& groom() const { return *groom_; }
  const HairStyle& style() const { return section_.style; }
  double groomSeconds() const { return groomSeconds_; }
  const HairSimulator& simulator() const { return simulator_; }

  // Poses the character at clip time `time` (with the document's pose edits)
  // and steps the guides by dt toward that pose.
  void step(float time, float dt);
  // Steps at the pose of `time` for `seconds` (the hair settles under gravity).
  void settle(float time, float seconds, float fps);
  // Every strand's current points (guides as simulated, children following,
  // pushed out of the body), laid out like groom().strands().points.
  const std::vector<float>& updateAllStrands();
  // The groom's strands carried rigidly by the head bone to the pose of `time`.
  const std::vector<float>& rigidStrands(float time);
  const std::vector<float>& allStrands() const { return all_; }

  // Points of allStrands() inside the posed body proxies (no margin). The
  // roots are counted apart: they ride on the skinned scalp, which the rigid
  // proxies only approximate (a root can dip into the neck's capsule when
  // the head bends); every other point is pushed out of the proxies.
  struct InsideCount {
    size_t points = 0;  // roots excluded
    size_t roots = 0;
  };
  InsideCount pointsInsideBody() const;
  // Largest relative change of a guide segment's length from its rest length.
  float maxGuideLengthError() const;

 private:
  struct RootAnchor {
    int mesh = -1;
    uint32_t corner[3] = {0, 0, 0};
    glm::vec3 barycentric{0.0f};
    glm::vec3 localOffset{0.0f};  // root minus the surface point, in the rest triangle frame
    glm::mat3 restFrame{1.0f};
  };
  void anchorRoots();
  void poseAt(float time);
  void updateRootTargets();

  const LoadedScene& scene_;
  int clip_ = -1;
  HairSection section_;
  std::unique_ptr<HairGroom> groom_;
  double groomSeconds_ = 0.0;
  HairRig rig_;
  HairSimulator simulator_;
  PosedCharacter posed_;
  PosedHairColliders body_;
  std::vector<RootAnchor> anchors_;
  std::vector<glm::vec3> rootPositions_;
  std::vector<glm::quat> rootRotations_;
  std::vector<float> all_;
};

}  // namespace mq::cli
