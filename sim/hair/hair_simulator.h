#pragma once
// Dynamics of guide strands: each strand is a chain of particles whose root
// follows the scalp. One substep, per strand, root to tip:
//   1. predict: v <- v * exp(-airDamping h) + g h,  p = x + v h
//   2. global shape: p_i pulled toward its rest position carried by the root
//      frame, strongly at the root and fading to zero at globalRange
//   3. one pass root to tip: bend each segment toward its rest direction in
//      its parent's frame (angular cantilever), then restore its rest length
//      by moving the child only (follow the leader, Mueller et al. 2012,
//      "Fast Simulation of Inextensible Hair and Fur"), then push the child out
//      of the body proxies; the parent frame is carried down by the minimal
//      rotation from the wanted to the actual segment direction
//   4. velocities: v = (p - x) / h - ftlDamping d_{i+1} / h (FTL damping),
//      friction on particles in contact (no bounce)
// Between 2 and 3, when params.interaction is on, the strands meet each other:
// pressure and friction between all guide particles' predicted positions
// (hair_interaction.h), which steps 3 and 4 then turn into velocities.
// Strands are independent, so the loop splits across ThreadPool::shared() and
// the result does not depend on scheduling.

#include <algorithm>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/hair/strands.h"
#include "sim/hair/adaptive_wisps.h"
#include "sim/hair/hair_colliders.h"
#include "sim/hair/hair_interaction.h"

namespace mq {

struct HairSimParams {
  glm::vec3 gravity{0.0f, -9.81f, 0.0f};
  float airDamping = 1.0f;         // 1/s: free velocity decays as exp(-airDamping t)
  float ftlDamping = 0.9f;         // share of the FTL correction removed from the velocity
  float globalStiffness = 0.3f;    // pull toward the rest shape at the root, per 1/60 s
  float globalRange = 0.5f;        // share of the strand over which that pull fades out
  float bendStiffness = 0.8f;      // pull of a segment toward its rest direction, per 1/60 s
  float friction = 0.4f;           // share of tangential velocity lost per contact step
  float collisionMargin = 0.002f;  // metres kept between hair and body proxies
  float maxSubstep = 1.0f / 60.0f;
  HairInteractionParams interaction;  // hair-hair pressure and friction (off by default)
  bool adaptiveWisps = false;         // simulate merged wisps' guides only (adaptive_wisps.h)
  AdaptiveWispParams wisps;
};

class HairSimulator {
 public:
  HairSimulator() = default;
  explicit HairSimulator(HairSimParams params) : params_(params) {}

  // The guides at rest, in rest space (e.g. the character's bind pose in
  // world space). Resets the state to rest.
  void setRest(const Strands& guides);
  void reset();
  void setParams(const HairSimParams& params);
  const HairSimParams& params() const { return params_; }

  // Advances by dt. The roots move rigidly with the scalp: posedFromRest
  // maps rest space to the current world (for a character: worldFromBone[head]
  // times the head's rest boneFromWorld). `body` holds the posed collision
  // proxies (may be null). Larger dt is split into substeps of at most
  // params.maxSubstep; the root motion is interpolated across them.
  void step(float dt, const glm::mat4& posedFromRest, const PosedHairColliders* body = nullptr);
  // Same with a root position and rotation (posed from rest) per strand, for
  // roots that follow a skinned scalp.
  void step(float dt, const std::vector<glm::vec3>& rootPositions, const std::vector<glm::quat>& rootRotations,
            const PosedHairColliders* body = nullptr);

  size_t strandCount() const { return strandCount_; }
  int pointsPerStrand() const { return pointsPerStrand_; }
  const Strands& rest() const { return rest_; }
  // Current particle positions, laid out like Strands::points.
  const std::vector<float>& positions() const { return positions_; }
  const std::vector<float>& velocities() const { return velocities_; }
  // The hair-hair kernel radius in use (0 while the interaction is off).
  float interactionRadius() const {
    return interactionReady_ && params_.interaction.enabled() ? interaction_.radius() : 0.0f;
  }
  // Per particle: the rotation that carries the strand's rest shape around
  // that particle to its current shape (the root frame times accumulated
  // bending). Children use it to follow their guide.
  const std::vector<glm::quat>& frames() const { return frames_; }
  // The current guides as Strands (rest arrays with current points).
  Strands current() const;

  // Which strands the next steps move (1) and which they leave where they
  // are (0); empty: all. A strand left out is placed by its owner instead
  // (adaptive wisps: it follows its wisp's simulated strand).
  void setActive(std::vector<uint8_t> active) { active_ = std::move(active); }
  bool isActive(size_t s) const { return active_.empty() || active_[s]; }
  // Guides the last step simulated (the rest followed their wisp's).
  size_t simulatedStrands() const {
    return active_.empty() ? strandCount_ : size_t(std::count(active_.begin(), active_.end(), uint8_t(1)));
  }
  // Sets strand s's points, velocities and frames (pointsPerStrand() each).
  void placeStrand(size_t s, const glm::vec3* points, const glm::vec3* velocities, const glm::quat* frames);

 private:
  struct RootTarget {
    glm::vec3 position;
    glm::quat rotation;
  };
  void substep(float h, const std::vector<RootTarget>& roots, const PosedHairColliders* body);
  void stepStrand(size_t s, float h, const RootTarget& root, const PosedHairColliders* body);
  void predictStrand(size_t s, float h, const RootTarget& root, glm::vec3* p) const;
  void solveStrand(size_t s, float h, const RootTarget& root, const PosedHairColliders* body, glm::vec3* p);

  HairSimParams params_;
  HairInteraction interaction_;
  bool interactionReady_ = false;     // interaction_ holds the rest densities
  std::vector<glm::vec3> predicted_;  // all strands' predicted positions, for the interaction
  Strands rest_;
  size_t strandCount_ = 0;
  int pointsPerStrand_ = 0;
  std::vector<float> restLengths_;   // per particle: length of the segment to its parent (0 at roots)
  std::vector<glm::vec3> restDirs_;  // per particle: unit rest direction of the segment to its child
  std::vector<float> positions_, velocities_;
  std::vector<glm::quat> frames_;
  std::vector<RootTarget> previousRoots_;
  std::vector<uint8_t> active_;  // per strand; empty: all
  AdaptiveWisps wisps_;          // while params_.adaptiveWisps
  bool hasPreviousRoots_ = false;
  // Per-substep constants derived from params_.
  float bendPerSubstep_ = 0.0f;
  std::vector<float> globalPerPoint_;
};

}  // namespace mq
