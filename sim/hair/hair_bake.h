#pragma once
// Hair on a character: the rig that drives the simulator from a skeleton pose
// (scalp motion from the head bone, posed body proxies), and baking the
// guides' motion over a clip.

#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "core/hair/hairstyle.h"
#include "core/hair/strands.h"
#include "sim/hair/hair_colliders.h"
#include "sim/hair/hair_simulator.h"

namespace mq {

struct Character;

// What moves hair on a character: the bone the scalp rides on (its rest
// world transform maps rest-space strands to bone space) and the colliders.
struct HairRig {
  int headBone = -1;  // -1: the scalp does not move
  glm::mat4 restWorldFromHead{1.0f};
  HairColliders body;

  // Head bone found by name ("head", case-insensitive); colliders from the
  // hair module's body proxy fitted to the character (with its tagged scalp
  // when it has one); no colliders when the character has no head.
  static HairRig fromCharacter(const Character& character);
  // The same with a body proxy already fitted (e.g. the groom's).
  static HairRig fromProxy(const Character& character, const BodyProxy& restProxy);
  // Maps rest space to the posed world: worldFromHead * restHeadFromWorld.
  glm::mat4 posedFromRest(const std::vector<glm::mat4>& worldFromBone) const;
};

// The dynamics for a groom on a character (the editor, mannequin-cli): the
// HairSimParams defaults with the style memory reaching down the whole
// strand (globalRange 1) instead of its root half, so the groom keeps its
// shape where it rests on the shoulders instead of the ends sliding off and
// the children, which follow their guide's bending, fanning out there.
// The style's dynamics turn on hair-hair interaction.
HairSimParams characterHairParams(const HairDynamicsParams& dynamics = {});

struct HairBakeCallbacks {
  std::function<void(int done, int total)> progress;  // after each frame
  std::function<bool()> cancelled;                    // polled before each frame
};

// Guide positions at each frame of a clip, from its start to its end.
struct HairBake {
  float fps = 60.0f;
  float startTime = 0.0f;
  int pointsPerStrand = 0;
  std::vector<std::vector<float>> frames;  // each laid out like Strands::points
  bool cancelled = false;

  int frameCount() const { return int(frames.size()); }
  // The frame nearest to clip time t (clamped); null when empty.
  const std::vector<float>* frameAt(float t) const;
};

struct HairBakeSettings {
  float fps = 60.0f;
  float settleSeconds = 0.5f;  // steps at the first frame's pose before recording
};

// Simulates restGuides (in the character's bind pose, world space) through
// clip clipIndex (-1: the rest pose for one second). Deterministic. Stops
// early, with cancelled set and the frames done so far, when asked to.
// rig: null fits one with HairRig::fromCharacter.
HairBake bakeHair(const Character& character, int clipIndex, const Strands& restGuides, const HairSimParams& params,
                  const HairBakeSettings& settings = {}, const HairBakeCallbacks& callbacks = {},
                  const HairRig* rig = nullptr);

}  // namespace mq
