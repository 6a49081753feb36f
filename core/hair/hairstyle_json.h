#pragma once
// The scene document's "hair" section:
//   "hair": {
//     "style": "wavy"                         a built-in style, or an object:
//            | {"preset": "wavy", "length": 0.4, ...,   fields override the preset
//               "streams":  [{"direction": [x,y,z], "strength": s}],
//               "sources":  [{"position": [x,y,z], "strength": s, "radius": r}],
//               "vortices": [{"position": [..], "axis": [..], "strength": s, "radius": r}],
//               "length_map": [{"position": [..], "scale": k, "radius": r}]},
//     "scalp": {"kind": "tagged"}                          default: TagScalp vertices
//            | {"kind": "bone_cone", "bone": "head", "axis": [0,1,0], "angle": 70}
//            | {"kind": "faces", "mesh": 0, "faces": [..]},
//     "strands": 0                             total count, 0 = from the density
//   }
// Primitive positions are in head space (see hairstyle.h).

#include <nlohmann/json.hpp>

#include "core/hair/hairstyle.h"
#include "core/hair/scalp.h"

namespace mq {

struct HairSection {
  HairStyle style;
  ScalpRegion scalp;
  size_t strands = 0;
  // The style is a built-in's numbers (a name, a "preset" with overrides, or
  // no style at all), made for the default mannequin's head: fitted to the
  // character's head when groomed (see head_fit.h). A full style object, as
  // the editor saves it, is already in the character's metres.
  bool fitToHead = true;
  // The document names the scalp; else automaticScalpRegion() chooses it.
  bool scalpGiven = false;
};

// Throw mq::Error saying which field is wrong.
HairStyle hairStyleFromJson(const nlohmann::json& j);
HairSection hairSectionFromJson(const nlohmann::json& j);
ScalpRegion scalpRegionFromJson(const nlohmann::json& j);

nlohmann::json toJson(const HairStyle& style);
nlohmann::json toJson(const ScalpRegion& region);
nlohmann::json toJson(const HairSection& section);

}  // namespace mq
