#pragma once
// Built-in garments sized from a character: a T-shirt, a skirt and trousers.
// Each has a few measurements (metres) as named parameters; the panels are
// drawn from them and from body measurements (joint positions from the
// skeleton's rest world transforms, girths from the rest skin), then placed
// on cylinders around the bones, clear of the body's bounding capsules.

#include <map>
#include <string>
#include <vector>

#include "core/garment/garment.h"

namespace mq {

struct Character;

// A measurement a garment type declares, so editors can build their panels.
struct GarmentParameter {
  std::string name;
  float value;  // the default
  float min, max;
  std::string help;
};

// "tshirt", "skirt", "trousers".
std::vector<std::string> parametricGarmentTypes();
// Throws mq::Error for an unknown type.
std::vector<GarmentParameter> garmentParameters(const std::string& type);

// Builds a garment of `type` for `body`. Parameters not given take their
// defaults, lengths scaled by the body's size relative to the default
// mannequin's (its neck joint's height over the ankles; unscaled within 3%,
// so the default mannequin's garments are the declared ones); unknown names
// or values out of range throw mq::Error. The result remembers type and
// parameters in Garment::recipe.
Garment makeParametricGarment(const std::string& type, const Character& body,
                              const std::map<std::string, float>& parameters = {});

// Rebuilds a garment from its recipe for `body`, keeping its name, fabric and
// target edge length (not its pins: they index the old mesh's vertices).
// Throws mq::Error when the garment has no recipe.
Garment rebuildParametricGarment(const Garment& garment, const Character& body);

}  // namespace mq
