#pragma once
// The built-in character: a procedural art-mannequin humanoid, 1.75 m tall,
// Y up, metres, standing on y = 0 and facing +Z, arms in an A-pose (45 deg).
// Its skin is an implicit surface (primitives on the bones, see
// implicit_body.h) polygonised into one closed 2-manifold mesh, skinned with
// weights from the primitives' potentials. Clips: "walk" (1 s loop) and
// "arm_raise" (2 s). The same call always returns the same character.
//
// Bones: pelvis (root), spine, chest, neck, head, clavicle_l, upperarm_l,
// forearm_l, hand_l, thigh_l, shin_l, foot_l, toes_l and the _r mirrors; _l is
// the character's own left (+X). Each bone's local +Y points from its joint to
// its child joint and local +X = Y x (world +Z), so a positive rotation about
// local X swings a limb forward, bends the elbow or the spine forward and a
// negative one bends the knee. Foot and toes point forward: their +X is
// Y x (world +Y) and a positive rotation lifts the toes.
//
// Mesh: one closed 2-manifold of about 30k vertices with field-gradient
// normals, 4 weights per vertex, TagScalp on the hair region.

#include "core/character/character.h"

namespace mq {

Character makeDefaultMannequin();

}  // namespace mq
