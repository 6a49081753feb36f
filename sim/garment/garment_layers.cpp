#include "sim/garment/garment_layers.h"

#include "sim/cloth/collision/cloth_surface_collider.h"
#include "sim/cloth/parallel.h"

namespace mq::cloth {

int verticesInside(const GarmentSimulation& outer, const std::vector<const GarmentSimulation*>& inner) {
  if (!outer.welded()) return 0;
  const std::vector<glm::vec3>& x = outer.simulator().positions();
  const float radius = innerSurfaceSearchRadius(outer.simulator().settings().collisionThickness);
  int inside = 0;
  for (const GarmentSimulation* g : inner) {
    if (!g || !g->welded()) continue;
    ClothSurfaceCollider surface;
    surface.setMesh(g->simulator().positions(), g->simulator().triangles());
    inside += int(deterministicSum(x.size(), [&](size_t i) {
      SurfaceContact contact;
      return surface.nearestContact(x[i], radius, contact) && contact.signedDistance < 0.0f ? 1.0 : 0.0;
    }));
  }
  return inside;
}

}  // namespace mq::cloth
