#pragma once
// Layers of garments (a T-shirt over trousers): each garment is worn over
// the garments of lower layers and over those earlier in the scene's list on
// its own layer, and collides with their surfaces one-way (outer on inner,
// see sim/cloth/cloth_simulator_layers.cpp). Callers step the garments in
// layerOrder() every frame, inner first, so an outer garment meets the inner
// ones where they are at the end of the frame:
//
//   const std::vector<size_t> order = layerOrder(garments);
//   wearInLayers(simulations, order);         // once, or when the order changes
//   for each frame: for (size_t g : order) simulations[g]->step(dt, &body);

#include <algorithm>
#include <memory>
#include <numeric>
#include <vector>

#include "core/garment/garment.h"
#include "sim/garment/garment_simulation.h"

namespace mq::cloth {

// Indices of `layers` (one per garment) from the innermost garment to the
// outermost: by layer, then by index.
inline std::vector<size_t> layerOrder(const std::vector<int>& layers) {
  std::vector<size_t> order(layers.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return layers[a] < layers[b]; });
  return order;
}

inline std::vector<size_t> layerOrder(const std::vector<Garment>& garments) {
  std::vector<int> layers;
  for (const Garment& g : garments) layers.push_back(g.layer);
  return layerOrder(layers);
}

// Each simulation g in `order` for which inLayers(g) is worn over the ones
// before it that are in layers too; the others over none (null entries are
// skipped, e.g. garments not simulated).
template <class Pointer, class InLayers>
void wearInLayers(const std::vector<Pointer>& simulations, const std::vector<size_t>& order, InLayers&& inLayers) {
  std::vector<const GarmentSimulation*> inner;
  for (size_t g : order) {
    if (!simulations[g]) continue;
    GarmentSimulation* sim = &*simulations[g];
    const bool layered = inLayers(g);
    sim->setInnerGarments(layered ? inner : std::vector<const GarmentSimulation*>{});
    if (layered) inner.push_back(sim);
  }
}

// Each simulation in `order` worn over the ones before it; layered = false: none over any.
template <class Pointer>
void wearInLayers(const std::vector<Pointer>& simulations, const std::vector<size_t>& order, bool layered = true) {
  wearInLayers(simulations, order, [layered](size_t) { return layered; });
}

// The vertices of `outer` now behind the surface of one of `inner` (on its
// body side, within the layer contact's search; not those beyond its hems),
// whether or not `outer` is worn over them: 0 before the welds.
int verticesInside(const GarmentSimulation& outer, const std::vector<const GarmentSimulation*>& inner);

}  // namespace mq::cloth
