#pragma once
// The elongation limit after contacts moved vertices: limit again without
// pulling the cloth back into what it touches.
//
// The vertices in contact weigh less in the limit (their inverse mass
// scaled down: they move little, far less than the thickness they keep from
// the surface). Vertices a moving body part swept along in this substep are
// first held where it put them (pulled back, they would cross the part and
// come out of its far side); when the limit cannot hold that way (cloth
// pinched between two body parts), it is redone with them merely heavy.
//
// Heavy is not held: over a convex body part the limit pulls contact
// vertices partly into it (a leg swinging in a trouser leg; trousers
// stretched over a bent knee showing the skin through). So with a body the
// limit runs in rounds; between two, a touched vertex that went in deeper
// than half the thickness is put back along its contact normal (it still
// slides along the surface) and the body-vertex contacts are pushed out
// again, so the next round pulls the cloth around them. The last round gets
// the rest of the pass budget; a round that held with nothing left to put
// back or push out ends it early (the rounds after would change nothing).

#include <cstdint>
#include <functional>
#include <vector>

#include "sim/cloth/cloth_state.h"
#include "sim/cloth/collision/body_collider.h"
#include "sim/cloth/constraints/stretch_limit.h"

namespace mq::cloth {

struct ContactAwareLimitSettings {
  float maxStretch = 1.1f;
  int passBudget = 100;      // passes in all
  int heldPassBudget = 100;  // passes of the try with swept vertices held
  float h = 0.0f;            // substep, s (velocities take the corrections / h)
  float contactInvMassScale = 0.05f;
  int bodyRounds = 8;      // rounds with a body
  float thickness = 0.0f;  // the collision thickness, m
};

// What the substep's contacts did to each vertex, and the body they touch.
struct ContactSet {
  std::vector<uint8_t>& touched;  // per vertex: 0, `contact` or `swept`
  uint8_t contact = 1, swept = 2;
  // Vertex i's nearest body contact within a radius (false: none); null
  // without a body (then one round).
  std::function<bool(size_t vertex, float radius, BodyContact& contact)> nearestBody;
  // Pushes body vertices out of cloth triangles again; returns the pushes.
  std::function<int()> pushBodyVerticesOut;
};

struct ContactAwareLimitResult {
  bool held = true;
  int passes = 0;
};

ContactAwareLimitResult limitStretchAroundContacts(ClothState& state, const ContactSet& contacts,
                                                   StretchLimiter& limiter, const ContactAwareLimitSettings& settings);

}  // namespace mq::cloth
