#pragma once
// Adaptive wisps (Bertails et al. 2003, "Adaptive Wisp Tree"; the survey's
// section 2.4): the guides grouped into a binary tree of wisps by root
// position, down to one guide a wisp. The wisps in play form a cut of the
// tree: each simulates one of its guides and the others follow it as
// children follow guides (their rest offset turned by its frames, kept out
// of the body). After each step:
//   - a wisp splits in two when its guide swings relative to its root frame
//     faster than splitSpeed, or when one of its followers had to be pushed
//     out of the body by more than splitContact: the halves would move apart;
//   - two halves merge back when the second's guide lies within
//     mergeDistance of where following the first's would put it, at every
//     point, their tips move alike (within mergeSpeed), both swing slower
//     than half of splitSpeed, none of their followers was pushed deeper
//     than half of splitContact, and the parent did not split during the
//     last cooldown.
// A merged wisp goes on simulating its larger half's guide, and a half that
// splits off simulates the guide rooted nearest its centre, starting from
// where it followed with its leader's velocity: no simulated guide jumps.
// Hair at rest or carried by the head is simulated by few guides; hair that
// swings or meets the body by all of them.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace mq {

class HairSimulator;
class PosedHairColliders;

struct AdaptiveWispParams {
  float splitSpeed = 0.2f;       // m/s: a guide tip's speed relative to its root frame
  float splitContact = 0.004f;   // m: the deepest push out of the body a follower may need
  float mergeDistance = 0.006f;  // m
  float mergeSpeed = 0.05f;      // m/s
  float cooldown = 0.5f;         // s: a wisp that split stays split at least this long
};

class AdaptiveWisps {
 public:
  // The tree over the simulator's rest guides, every guide simulated.
  void build(const HairSimulator& sim, const AdaptiveWispParams& params = {});
  bool built() const { return !nodes_.empty(); }
  // After the simulator stepped by dt: places every follower, then splits
  // and merges wisps and tells the simulator which guides the next step
  // moves.
  void update(HairSimulator& sim, float dt, const PosedHairColliders* body);

 private:
  struct Node {
    int first = -1, second = -1;  // halves; -1 for a single guide
    int begin = 0, end = 0;       // its guides: order_[begin, end)
    int nominal = -1;             // its guide rooted nearest its root centre
    int guide = -1;               // the guide it simulates while in play
    float splitAt = -1e30f;       // time of its last split
  };
  int buildNode(int begin, int end, const std::vector<glm::vec3>& roots);
  void follow(HairSimulator& sim, const PosedHairColliders* body);
  void measureSwing(const HairSimulator& sim, float dt);
  void splitWisps(float time);
  void mergeWisps(const HairSimulator& sim, float time);
  bool holds(const Node& node, int guide) const;
  bool followsWithin(const HairSimulator& sim, int leader, int guide, float distance) const;
  void applyCut(HairSimulator& sim);

  AdaptiveWispParams params_;
  std::vector<Node> nodes_;           // a node's halves come after it
  std::vector<int> order_;            // guides, each node's contiguous
  std::vector<int> leafOf_;           // per guide: its single-guide node
  std::vector<int> positionInOrder_;  // per guide: its index in order_
  std::vector<uint8_t> inCut_;
  std::vector<int> cut_;             // the wisps in play
  std::vector<float> pushed_;        // per node: deepest follower push, last step in the cut
  std::vector<glm::vec3> rigidTip_;  // per guide: its rest tip carried by its root frame
  bool measured_ = false;            // rigidTip_ holds the last step's
  std::vector<float> swing_;         // per guide: speed of that offset (m/s)
  float time_ = 0.0f;
};

}  // namespace mq
