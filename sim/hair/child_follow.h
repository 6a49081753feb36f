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

// A groom's strands in one array, guides first (HairGroom::strands(): the
// children's guideOf index the guides), with the simulator holding those
// guides: writes every strand's current points into `positions` (resized
// like all.points): the guides as simulated, the children following them.
// The frames followGuides needs, rebuilt from guide positions alone (e.g. a
// baked frame): the root rotation carried down each strand by the minimal
// rotation from each rest segment direction to the current one, as the
// simulator does. rootRotation maps rest space to the posed world.
std::vector<glm::quat> guideFrames(const Strands& restGuides, const std::vector<float>& positions,
                                   const glm::quat& rootRotation);

// The first guideCount strands of `all` (the guides of a groom).
Strands leadingStrands(const Strands& all, size_t guideCount);

void poseGroomedStrands(const Strands& all, const HairSimulator& guides, std::vector<float>& positions,
                        const PosedHairColliders* body = nullptr);

}  // namespace mq
