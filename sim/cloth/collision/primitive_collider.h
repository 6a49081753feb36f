#pragma once
// The cloth's analytic colliders are the plain solids of core (sphere,
// capsule, plane); the cloth code keeps its own name for them.

#include "core/geometry/solid_primitive.h"

namespace mq::cloth {

using PrimitiveCollider = SolidPrimitive;
using mq::shapeName;

}  // namespace mq::cloth
