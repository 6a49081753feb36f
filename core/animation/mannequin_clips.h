#pragma once
// The built-in mannequin's procedural clips (default_mannequin.h names its
// bones): "walk", a walk in place, one stride of each leg per second (a 1 s
// loop); "arm_raise", both arms raised over the head and lowered (2 s);
// "head_turn", the head turned over one shoulder, across and back (2 s).
// Keyframed rotations sampled from closed-form motions of the phase.

#include "core/animation/clip.h"
#include "core/skeleton/skeleton.h"

namespace mq {

Clip makeMannequinWalk(const Skeleton& skeleton);
Clip makeMannequinArmRaise(const Skeleton& skeleton);
Clip makeMannequinHeadTurn(const Skeleton& skeleton);

}  // namespace mq
