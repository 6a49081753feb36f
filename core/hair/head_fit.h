#pragma once
// Fitting hair to a character's head. The built-in hairstyles are made for
// the default mannequin's head; on another head they are scaled about the
// head centre (head space, see hairstyle.h) by the ratio of head sizes, so a
// bob stays a bob on a child's or a giant's head. Also: the head bone and
// the scalp of characters that carry no scalp tags (imported ones).

#include <string>

#include "core/character/character.h"
#include "core/hair/body_proxy.h"
#include "core/hair/hairstyle.h"
#include "core/hair/scalp.h"

namespace mq {

// Size of a head proxy: the geometric mean of its head ellipsoid's radii
// (metres); 0 when the proxy has no head.
float headSize(const BodyProxy& proxy);
// headSize() of the default mannequin's groom, the head the built-in styles
// are made for.
constexpr float kReferenceHeadSize = 0.08866552f;

// `style` for a head `scale` times the reference: positions, radii, lengths,
// wavelengths and offsets scale; source strengths scale too, so the flow's
// streamlines keep their shape; densities scale by 1/scale^2, so the strand
// count stays the same. Counts, colours, angles and shares are unchanged.
HairStyle scaledHairStyle(const HairStyle& style, float scale);
// scaledHairStyle for the head of `proxy` (unchanged within 0.1% of the
// reference, e.g. on the default mannequin).
HairStyle fitHairStyleToHead(const HairStyle& style, const BodyProxy& proxy);

// The character's head bone: one named "head" (any case), else one whose name
// contains "head" (not "end" or "top"), else the bone whose driven vertices
// are highest on average (an upright rest pose). -1 when nothing qualifies.
int findHeadBone(const Character& character);

// Where hair grows when the document does not say: the faces tagged TagScalp
// when the character has some; else the faces of the mesh the head bone
// drives most, on the top and back of the head: their centres within 75
// degrees of an axis tilted 25 degrees back from up, seen from the centre of
// the head's vertices. A character without bones (a static mesh) has its
// head found from the mesh's top (static_head.h), and a region without a
// bone. Throws mq::Error when the character has no head.
ScalpRegion automaticScalpRegion(const Character& character);

}  // namespace mq
