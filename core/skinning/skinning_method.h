#pragma once
// The ways a skin follows its skeleton, as a user picks them:
//   Lbs   linear blend skinning (the matrices blended; collapses at bends)
//   Dqs   dual quaternion skinning (Kavan et al. 2008; rigid per vertex)
//   Cones dual quaternions corrected by the section cones of survey 1.2.5
//         (minimum section, bulge limit, contact with the neighbour bone)

#include <optional>
#include <string>

namespace mq {

enum class SkinningMethod { Lbs, Dqs, Cones };

const char* skinningMethodName(SkinningMethod method);
// "lbs", "dqs", "cones"; nullopt for anything else.
std::optional<SkinningMethod> parseSkinningMethod(const std::string& name);
// The accepted names joined for messages: "lbs, dqs or cones".
std::string skinningMethodChoices();

}  // namespace mq
