#pragma once
// The scene document's "hair" section:
//   "hair": {
//     "style": "wavy"                         a built-in style, or an object:
//            | {"preset": "wavy", "length": 0.4, ...,   fields override the preset
//               "streams":  [{"direction": [x,y,z], "strength": s}],
//               "sources":  [{"position": [x,y,z], "strength": s, "radius": r}],
//               "vortices": [{"position": [..], "axis": [..], "strength": s, "radius": r}],
//               "length_map": [{"position": [..], "scale": k, "radius": r}],
//               "strokes": [{"brush": "comb", "radius": r, "strength": s,   brush strokes in
//                            "mirror": false, "value": v,               order (groom_stroke.h;
//                                                                        value: paint brushes);
//                            "dabs": [[x, y, z, mx, my, mz], ..]}],     head space, metres
//               "dynamics": {"volume": 0.5, "friction": 0.3}},  hair against hair, 0 .. 1 (default 0: off)
//     "scalp": {"kind": "tagged"}                          default: TagScalp vertices
//            | {"kind": "bone_cone", "bone": "head", "axis": [0,1,0], "angle": 70}
//            | {"kind": "faces", "bone": "head", "mesh": 0, "faces": [..]},   bone: the head
//     "strands": 0,                            total count, 0 = from the density
//     "shading": {"model": "kajiya-kay" | "physical",   default kajiya-kay
//                 "melanin": 1.3, "pheomelanin": 0.1,   pigments (physical)
//                 "roughness": 0.3}                      fibre roughness beta (physical)
//   }
// "shading" may also sit in a style object (the editor saves it there); the
// section's one wins. A style whose shading or dynamics is the default writes
// none, so files saved before they existed read and write unchanged.
// Primitive positions are in head space (see hairstyle.h).

#include <nlohmann/json_fwd.hpp>

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
HairStyle hairStyleFromJson(const nlohmann::json& j, const std::string& path = "hair.style");
// Errors name the field by its JSON path under `path`.
HairSection hairSectionFromJson(const nlohmann::json& j, const std::string& path = "hair");
ScalpRegion scalpRegionFromJson(const nlohmann::json& j, const std::string& path = "hair.scalp");
// Fields absent keep `base`'s values.
HairShadingParams hairShadingFromJson(const nlohmann::json& j, const HairShadingParams& base = {},
                                      const std::string& path = "hair.shading");
nlohmann::json toJson(const HairShadingParams& shading);
HairDynamicsParams hairDynamicsFromJson(const nlohmann::json& j, const HairDynamicsParams& base = {},
                                        const std::string& path = "hair.style.dynamics");
nlohmann::json toJson(const HairDynamicsParams& dynamics);
// "kajiya-kay", "physical"; the parser throws mq::Error naming them.
std::string hairShadingModelName(HairShadingModel model);
HairShadingModel hairShadingModelFromName(const std::string& name);

nlohmann::json toJson(const HairStyle& style);
nlohmann::json toJson(const ScalpRegion& region);
nlohmann::json toJson(const HairSection& section);

}  // namespace mq
