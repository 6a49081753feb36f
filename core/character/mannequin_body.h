#pragma once
// The built-in mannequin's skeleton (joints from anthropometry for a 1.75 m
// adult, A-pose) and its implicit body (primitives on the bones:
// implicit_body.h). default_mannequin.h assembles the character from them.

#include "core/character/implicit_body.h"
#include "core/skeleton/skeleton.h"

namespace mq {

Skeleton makeMannequinSkeleton();
// The body's primitives for that skeleton (its bones found by name).
ImplicitBody makeMannequinBody(const Skeleton& skeleton);

}  // namespace mq
