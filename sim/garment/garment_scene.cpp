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

GarmentMesh sheetGarmentMesh(const ClothSceneSpec& spec) {
  const Sheet sheet = buildSheet(spec.sheet);
  GarmentMesh mesh;
  mesh.positions = sheet.positions;
  mesh.triangles = sheet.triangles;
  mesh.restUvs.resize(sheet.uvs.size());
  for (size_t i = 0; i + 1 < sheet.uvs.size(); i += 2) {
    mesh.restUvs[i] = sheet.uvs[i] * spec.sheet.width;
    mesh.restUvs[i + 1] = sheet.uvs[i + 1] * spec.sheet.height;
  }
  mesh.panelIds.assign(sheet.vertexCount(), 0);
  mesh.panelFirstVertex = {0};
  return mesh;
}

std::unique_ptr<GarmentSimulation> makeSheetSimulation(const ClothSceneSpec& spec,
                                                       const std::vector<float>& bodyPositions,
                                                       const std::vector<uint32_t>& bodyTriangles) {
  GarmentSimulationSettings settings;
  settings.cloth = spec.settings;
  settings.fabric = spec.fabric;
  if (spec.massPerVertex > 0.0f)  // the same total mass, spread by area
    settings.fabric.massPerArea =
        spec.massPerVertex * float(spec.sheet.columns * spec.sheet.rows) / (spec.sheet.width * spec.sheet.height);
  auto sim = std::make_unique<GarmentSimulation>(sheetGarmentMesh(spec), settings, bodyPositions, bodyTriangles);
  for (const PrimitiveCollider& c : spec.colliders) sim->addCollider(c);
  std::vector<uint32_t> pinned;
  buildClothMesh(spec, pinned);
  for (uint32_t v : pinned) sim->pin(v);
  return sim;
}

}  // namespace mq::cloth
