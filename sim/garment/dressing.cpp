#include "sim/garment/dressing.h"

#include <cmath>

#include "sim/garment/garment_layers.h"

namespace mq::cloth {
namespace {

const std::vector<float>* bodyOrNull(const std::vector<float>& body) { return body.empty() ? nullptr : &body; }

}  // namespace

DrapeSteps drapeOnto(GarmentSimulation& simulation, const std::vector<float>& rest, const std::vector<float>& first,
                     float dt) {
  DrapeSchedule drape;
  DrapeSteps steps;
  std::vector<float> body;
  for (; steps.total < drape.maxSteps(dt) && !drape.draped(); ++steps.total) {
    if (!drape.sewingDone(simulation)) steps.sewing = steps.total + 1;
    blendBody(rest, first, drape.advance(simulation, dt), body);
    simulation.step(dt, bodyOrNull(body));
  }
  return steps;
}

bool settleTogether(const std::vector<GarmentSimulation*>& simulations, const std::vector<size_t>& order,
                    const std::vector<float>& body, float dt, const std::function<bool()>& cancelled) {
  const int steps = int(std::ceil(kDressingSettleSeconds / dt));
  for (int s = 0; s < steps; ++s) {
    if (cancelled && cancelled()) return false;
    for (size_t g : order) simulations[g]->step(dt, bodyOrNull(body));
  }
  return true;
}

std::vector<DrapeSteps> dressGarments(const std::vector<GarmentSimulation*>& simulations,
                                      const std::vector<size_t>& order, const std::vector<float>& rest,
                                      const std::vector<float>& first, float dt,
                                      const std::function<bool(size_t)>& inLayers) {
  std::vector<DrapeSteps> steps(simulations.size());
  wearInLayers(simulations, order, false);  // each drapes on its own
  for (size_t g = 0; g < simulations.size(); ++g) steps[g] = drapeOnto(*simulations[g], rest, first, dt);
  wearInLayers(simulations, order, inLayers);
  settleTogether(simulations, order, first, dt);
  return steps;
}

}  // namespace mq::cloth
