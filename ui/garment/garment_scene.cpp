#include "ui/garment/garment_scene.h"

#include <nlohmann/json.hpp>

#include "core/garment/fabric_json.h"
#include "core/garment/garment_json.h"

namespace mq::ui {

using nlohmann::json;

bool fabricIsPreset(const Garment& garment) {
  return !garment.customFabric ||
         (hasFabricPreset(garment.fabric) && sameFabricValues(*garment.customFabric, fabricPreset(garment.fabric)));
}

void setFabricValues(Garment& garment, const Fabric& fabric) {
  if (hasFabricPreset(garment.fabric) && sameFabricValues(fabric, fabricPreset(garment.fabric)))
    garment.customFabric.reset();
  else
    garment.customFabric = fabric;
}

GarmentScene garmentSceneFromSections(const json& garments, const json& cloth, const json& colliders,
                                      const std::string& pathForErrors) {
  GarmentScene scene;
  scene.garments = garmentsFromJson(garments);
  scene.writeCloth = !cloth.is_null();
  if (cloth.is_null() && scene.garments.empty()) {
    scene.cloth = cloth::parseClothScene(json(), colliders, pathForErrors, true);  // defaults, no sheet
  } else {
    scene.cloth = cloth::parseClothScene(cloth, colliders, pathForErrors, !scene.garments.empty());
  }
  return scene;
}

void garmentSceneToSections(const GarmentScene& scene, json& garments, json& cloth, json& colliders) {
  garments = scene.garments.empty() ? json() : garmentsToJson(scene.garments);
  json written, writtenColliders;
  cloth::writeClothScene(scene.cloth, written, writtenColliders);
  // The colliders stand on their own: a scene may have colliders and a
  // sheet, garments, or (for the body's sake) neither.
  colliders = scene.cloth.colliders.empty() ? json() : writtenColliders;
  // Without garments and without a sheet the cloth section would describe a
  // default sheet: leave it out.
  if (!scene.writeCloth || (scene.garments.empty() && !scene.cloth.hasSheet)) {
    cloth = json();
    return;
  }
  cloth = written;
}

bool GarmentScene::operator==(const GarmentScene& other) const {
  json ga, ca, la, gb, cb, lb;
  garmentSceneToSections(*this, ga, ca, la);
  garmentSceneToSections(other, gb, cb, lb);
  return ga == gb && ca == cb && la == lb;
}

std::string bakeInvalidatedBy(const GarmentScene& before, const GarmentScene& after) {
  if (before.garments.size() != after.garments.size()) return "garments added or removed";
  for (size_t i = 0; i < before.garments.size(); ++i) {
    json a = garmentToJson(before.garments[i]), b = garmentToJson(after.garments[i]);
    for (const auto& [part, change] :
         {std::pair{"fabric", "fabric changed"}, {"pins", "pins changed"}, {"layer", "layers changed"}}) {
      if (a.value(part, json()) != b.value(part, json())) return change;
      a.erase(part), b.erase(part);
    }
    a.erase("name"), b.erase("name");
    if (a != b) return "pattern changed";
  }
  json clothBefore, collidersBefore, clothAfter, collidersAfter;
  cloth::writeClothScene(before.cloth, clothBefore, collidersBefore);
  cloth::writeClothScene(after.cloth, clothAfter, collidersAfter);
  if (collidersBefore != collidersAfter) return "colliders changed";
  if (clothBefore != clothAfter) return "cloth settings changed";
  return {};
}

}  // namespace mq::ui
