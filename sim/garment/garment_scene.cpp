#include "sim/garment/garment_scene.h"

#include "core/util/error.h"

namespace mq::cloth {

GarmentSimulationSettings garmentSimulationSettings(const Garment& garment, const ClothSceneSpec& spec) {
  GarmentSimulationSettings settings;
  settings.cloth = spec.settings;
  settings.fabric = garment.solverFabric();
  return settings;
}

std::unique_ptr<GarmentSimulation> makeGarmentSimulation(const Garment& garment, const ClothSceneSpec& spec,
                                                         const std::vector<float>& bodyPositions,
                                                         const std::vector<uint32_t>& bodyTriangles,
                                                         const std::string& jsonPath) {
  const GarmentSimulationSettings settings = [&] {
    try {
      return garmentSimulationSettings(garment, spec);
    } catch (const Error& e) {
      throw Error(jsonPath + ".fabric: " + e.what());
    }
  }();
  const GarmentMesh mesh = buildGarmentMesh(garment);
  const GarmentPins& pins = garment.pins;
  for (size_t i = 0; i < pins.vertices.size(); ++i)
    if (pins.vertices[i] >= mesh.vertexCount())
      throw Error(jsonPath + ".pins.vertices[" + std::to_string(i) + "]: vertex " + std::to_string(pins.vertices[i]) +
                  " is beyond the garment's " + std::to_string(mesh.vertexCount()) + " vertices");
  const bool toBody = pins.attach == GarmentPins::Attach::Body;
  if (toBody && !pins.vertices.empty() && bodyTriangles.empty())
    throw Error(jsonPath + ".pins.attach: \"body\" needs a character to pin to (use \"space\")");
  auto sim = std::make_unique<GarmentSimulation>(mesh, settings, bodyPositions, bodyTriangles);
  for (const PrimitiveCollider& c : spec.colliders) sim->addCollider(c);
  for (uint32_t v : pins.vertices) toBody ? sim->pinToBody(v) : sim->pin(v);
  return sim;
}

}  // namespace mq::cloth
