#pragma once
// How garments get onto a body before the frames, the same in every path
// (the editor's bake, mannequin-cli simulate, render and export): each
// garment sews on the rest body and moves with it to the first pose on its
// own (DrapeSchedule); then all of them, worn in layers, settle together on
// the first pose for kDressingSettleSeconds, stepped inner to outer. So a
// scene gives the same cloth whichever path dresses it.

#include <functional>
#include <vector>

#include "sim/garment/drape_schedule.h"
#include "sim/garment/garment_simulation.h"

namespace mq::cloth {

// Long enough for garments that sewed and draped on their own to resolve
// where they overlap, short enough not to show as a pause.
constexpr float kDressingSettleSeconds = 0.25f;

struct DrapeSteps {
  int sewing = 0;  // steps before the body started moving (sewing on the rest body)
  int total = 0;
};

// One garment through its DrapeSchedule: sewn on `rest`, then carried to
// `first`. Bodies: flat positions; empty: no body (the garment stays put).
DrapeSteps drapeOnto(GarmentSimulation& simulation, const std::vector<float>& rest, const std::vector<float>& first,
                     float dt);

// Every garment in `order` (inner to outer, garment_layers.h) one step of dt
// on `body`, kDressingSettleSeconds long; false when `cancelled` says so.
bool settleTogether(const std::vector<GarmentSimulation*>& simulations, const std::vector<size_t>& order,
                    const std::vector<float>& body, float dt, const std::function<bool()>& cancelled = {});

// The whole dressing: drapeOnto for each garment, then worn in layers
// (inLayers(g): garment g takes part in the layering) and settleTogether.
// Returns each garment's DrapeSteps (by garment index).
std::vector<DrapeSteps> dressGarments(const std::vector<GarmentSimulation*>& simulations,
                                      const std::vector<size_t>& order, const std::vector<float>& rest,
                                      const std::vector<float>& first, float dt,
                                      const std::function<bool(size_t)>& inLayers);

}  // namespace mq::cloth
