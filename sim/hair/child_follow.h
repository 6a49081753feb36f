#pragma once
// Children (interpolated strands) follow their simulated guides: each child
// point keeps its rest offset from the guide point at the same place along
// the strand, turned by the guide's frame there:
//   child_i = guide_i + F_i (childRest_i - guideRest_i)
// so children translate and rotate with their guide's bending.

#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/hair/strands.h"

namespace mq {

class HairSimulator;
class PosedHairColliders;

// restChildren.guideOf[c] is the index of child c's guide in restGuides
// (entries < 0 keep the child at rest). guidePositions and guideFrames are
// the guides' current state, laid out like restGuides. Children may have a
// different point count than guides. When body is given, child points are
// pushed out of it. childPositions is resized to restChildren.points.
void followGuides(const Strands& restChildren, const Strands& restGuides, const std::vector<float>& guidePositions,
                  const std::vector<glm::quat>& guideFrames, std::vector<float>& childPositions,
                  const PosedHairColliders* body = nullptr);

// Same with the simulator's current guides.
void followGuides(const Strands& restChildren, const HairSimulator& guides, std::vector<float>& childPositions,
                  const PosedHairColliders* body = nullptr);

}  // namespace mq
