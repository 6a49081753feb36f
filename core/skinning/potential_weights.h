#pragma once
// Smooth skinning weights from an implicit body's primitives (the survey's
// weights from field potentials): each vertex takes, for each bone, the sum of
// exp(-d / falloff) over the bone's primitives at distance d, limited to the
// bone of its nearest primitive and that bone's neighbours in the hierarchy
// (a thigh never pulls the other thigh's skin), averaged with its mesh
// neighbours' (12 Laplacian passes remove the seams where the nearest
// primitive changes), traces under 1% dropped, normalised, at most 4 a
// vertex. A bone named "pelvis" reaches twice as far, so the crotch blends
// between the hip and both legs.

#include "core/character/implicit_body.h"
#include "core/mesh/mesh.h"
#include "core/skeleton/skeleton.h"

namespace mq {

// Binds `mesh` (its positions on `body`'s surface) to `skeleton`: writes mesh.skin.
void bindPotentialWeights(Mesh& mesh, const ImplicitBody& body, const Skeleton& skeleton);

}  // namespace mq
