#pragma once
// A humanoid skeleton for a mesh without one (a body scan, a statue, a body
// from another program), placed from the mesh's shape: a person standing
// upright, facing +Z, arms held away from the body (A or T pose). Heights
// come from the mesh (its feet, its top) and standard anthropometry
// (Drillis and Contini: hips at 0.53 of the stature, knees 0.285, shoulders
// 0.82); every joint is then centred in the limb's cross-section there, and
// the arm follows the arm's own vertices to its farthest point. The bones
// have the built-in mannequin's names, so everything that finds a humanoid
// by its bones (garments, helper bones, skin-report, motions) works on it.
// Each vertex goes to the bone of the region it lies in (head, neck, an
// arm beyond its shoulder and near its axis, a leg below the hips, the torso
// by height); `blend` then smooths the weights across the joints (weight
// smoothing, weight_regeneration.h), for a skin to pose.

#include "core/character/character.h"

namespace mq {

class ThreadPool;

// Rigs `character` in place: its meshes (all unskinned) become skinned in
// world space. Throws mq::Error saying what is not there (already rigged, too
// short for a person, arms along the body).
void autoRigHumanoid(Character& character, bool blend = true, ThreadPool* pool = nullptr);

}  // namespace mq
