// Layering: this cloth against the surface of the cloth it is worn over
// (a T-shirt over trousers), in its own file to keep the solver's step short.
//
// One-way, as production cloth tools do it (outer on inner): the inner
// garment is simulated first and never feels the outer one. Two-way contact
// would need both garments in one solve (or iterating the pair every
// substep), doubling the cost for little visible gain: the outer layer is
// the lighter, looser one lying over the inner, whose motion the body
// drives. The inner surface moves linearly over the step, and a contact
// responds relative to its velocity there (with the cloth's friction), so
// the shirt's hem rides along with the trousers' waistband.

#include <algorithm>

#include "sim/cloth/cloth_simulator.h"
#include "sim/cloth/collision/cloth_surface_collider.h"
#include "sim/cloth/collision/contact_response.h"
#include "sim/cloth/parallel.h"

namespace mq::cloth {

void ClothSimulator::collideWithInnerSurface(float fraction) {
  if (innerSurface_->empty()) return;
  innerSurface_->moveTo(fraction);
  const float thickness = settings_.collisionThickness;
  const float radius = innerSurfaceSearchRadius(thickness);
  forRange(state_.size(), [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      if (state_.invMass[i] == 0.0f) continue;
      SurfaceContact contact;
      if (!innerSurface_->nearestContact(state_.x[i], radius, contact) || !(contact.signedDistance < thickness))
        continue;
      touched_[i] = std::max(touched_[i], kContact);
      respondToContact(state_.x[i], state_.v[i], contact.normal, thickness - contact.signedDistance, contact.velocity,
                       settings_.friction);
    }
  });
}

}  // namespace mq::cloth
