#pragma once
// What the garment tool edits, as one value: the document's garments (each
// with its fabric and pins, core/garment/garment.h) and the cloth solver
// settings they share (the "cloth" section, sim/cloth/cloth_scene_io.h).
// Every edit replaces the whole value through an undo command
// (GarmentEditCommand), so undo and redo are exact.

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/garment/garment.h"
#include "sim/cloth/cloth_scene_io.h"

namespace mq::ui {

struct GarmentScene {
  std::vector<Garment> garments;
  cloth::ClothSceneSpec cloth;  // solver settings and fps (a sheet too, if the document has one)
  bool writeCloth = false;      // the document has a cloth section, or the settings were edited

  bool operator==(const GarmentScene& other) const;
};

// The scene of a document's sections. Throws mq::Error / FileError naming
// the JSON path of a bad value.
GarmentScene garmentSceneFromSections(const nlohmann::json& garments, const nlohmann::json& cloth,
                                      const nlohmann::json& colliders, const std::string& pathForErrors);
void garmentSceneToSections(const GarmentScene& scene, nlohmann::json& garments, nlohmann::json& cloth,
                            nlohmann::json& colliders);

// What an edit from `before` to `after` changed that a bake of `before`
// depends on ("fabric changed", "pins changed", ...), for the dock; empty
// when the bake still holds (a garment renamed).
std::string bakeInvalidatedBy(const GarmentScene& before, const GarmentScene& after);

// True when the garment uses its preset's values (no values of its own).
bool fabricIsPreset(const Garment& garment);
// Sets the garment's fabric values (none of its own when they are the preset's).
void setFabricValues(Garment& garment, const Fabric& fabric);

}  // namespace mq::ui
