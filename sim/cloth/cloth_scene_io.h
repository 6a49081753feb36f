#pragma once
// The cloth part of a scene document: the `cloth` section (sheet garment,
// fabric, solver settings, pins) and the primitive `colliders` section. The
// solver settings also apply to the document's "garments" (core/garment/
// garment_json.h), which carry their own fabric and pins; the fabric's JSON
// is core/garment/fabric_json.h.
//
//   "cloth": {
//     "garment": {"type": "sheet", "columns": 64, "rows": 64, "width": 1, "height": 1,
//                 "center": [0, 0.8, 0], "orientation": "horizontal" | "vertical",
//                 "tilt_degrees": 0},
//     "fabric": "cotton" | {"preset": "cotton", "mass_per_area": 0.12, "stretch": 1e4,
//                           "shear": 50, "bend": 1e-5, "damping": 0.02, "friction": 0.3,
//                           "thickness": 5e-4},
//     "mass_per_vertex": 0.3,                  optional, overrides the fabric's mass per area
//     "integrator": "implicit_euler" | "symplectic_euler" | "verlet" | "rk4",
//     "substeps": 0, "bending": "springs" | "cantilever",
//     "gravity": [0, -9.81, 0], "wind": [0, 0, 0], "air_damping": 0.5,
//     "stretch_limit": "position" | "velocity" | "off", "max_stretch": 1.1,
//     "stretch_iterations": 100, "max_refinement": 8, "self_collisions": false, "thickness": 0.005,
//     "self_thickness": 0.004, "friction": 0.3, "cg_max_iterations": 100, "cg_tolerance": 0.001,
//     "cg_preconditioner": "block_jacobi" | "two_level",
//     "pins": {"rows": [0], "vertices": [12, 13]},   sheet rows (0 = first row) and/or vertex indices
//     "fps": 24, "animate_body": true,
//     "bake_frames": 120 },                    frames the editor bakes when there is no clip to follow
//                                              (no character); optional, added after version 1 shipped
//   "colliders": [ {"type": "sphere", "center": [0, 0, 0], "radius": 0.3},
//                  {"type": "capsule", "a": [..], "b": [..], "radius": 0.1},
//                  {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "friction": 0.5} ]
//
// A vertical sheet hangs in the XY plane from its top edge at center.y +
// height/2, rows going down, tilted by tilt_degrees about the top edge toward -Z.

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/garment/fabric.h"
#include "core/garment/sheet.h"
#include "sim/cloth/cloth_settings.h"
#include "sim/cloth/cloth_state.h"
#include "sim/cloth/collision/primitive_collider.h"

namespace mq::cloth {

struct SheetGarmentSpec {
  int columns = 32, rows = 32;
  float width = 1.0f, height = 1.0f;
  glm::vec3 center{0.0f, 1.0f, 0.0f};
  bool vertical = false;
  float tiltDegrees = 0.0f;
};

struct ClothSceneSpec {
  bool hasSheet = true;  // false: only the document's garments (no "garment" key)
  SheetGarmentSpec sheet;
  std::string fabricPreset = "cotton";  // the preset the fabric started from ("" = custom)
  Fabric fabric;
  float massPerVertex = 0.0f;  // > 0 overrides the fabric's mass per area
  ClothSettings settings;
  std::vector<int> pinnedRows;
  std::vector<uint32_t> pinnedVertices;
  std::vector<PrimitiveCollider> colliders;
  float fps = 24.0f;
  bool animateBody = true;  // the character (if any) plays its clip while the cloth runs
  int bakeFrames = 120;     // the editor's bake length at fps when there is no clip (no character)
};

// Throws FileError(pathForErrors, "cloth.<key>: <problem>") for bad sections.
// With hasGarments (the document has a "garments" section) the section may be
// null and its "garment" sheet is optional: the solver settings, fps and
// animate_body then apply to the garments.
ClothSceneSpec parseClothScene(const nlohmann::json& cloth, const nlohmann::json& colliders,
                               const std::string& pathForErrors, bool hasGarments = false);
void writeClothScene(const ClothSceneSpec& spec, nlohmann::json& cloth, nlohmann::json& colliders);

// The sheet's mesh (with masses when massPerVertex > 0) and the vertices to pin.
Sheet buildSheet(const SheetGarmentSpec& spec);
ClothMesh buildClothMesh(const ClothSceneSpec& spec, std::vector<uint32_t>& pinned);

}  // namespace mq::cloth
