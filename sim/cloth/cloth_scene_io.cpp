#include "sim/cloth/cloth_scene_io.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/garment/fabric_json.h"
#include "core/io/json_fields.h"
#include "core/util/error.h"

namespace mq::cloth {

namespace {

using nlohmann::json;

// Bounds on what a scene may ask for: memory grows with sheet vertices and
// with frames x vertices of a bake.
constexpr long long kMaxSheetSide = 4096;
constexpr long long kMaxSheetVertices = 1000000;
constexpr long long kMaxFrames = 100000;
constexpr float kMaxDistance = 1000.0f;  // metres

std::string knownNames(std::initializer_list<const char*> names) {
  std::string s;
  for (const char* n : names) s += (s.empty() ? "" : ", ") + std::string(n);
  return "(known: " + s + ")";
}

SheetGarmentSpec parseGarment(const JsonFields& r) {
  SheetGarmentSpec g;
  if (!r.has("garment")) return g;
  const JsonFields s = r.object("garment");
  const std::string type = s.string("type", "sheet");
  if (type != "sheet") s.fail("type", "unknown garment type '" + type + "' " + knownNames({"sheet"}));
  g.columns = int(s.integer("columns", g.columns, 2, kMaxSheetSide));
  g.rows = int(s.integer("rows", g.rows, 2, kMaxSheetSide));
  if (static_cast<long long>(g.columns) * g.rows > kMaxSheetVertices)
    s.fail("rows", "columns x rows must be at most " + std::to_string(kMaxSheetVertices) + " vertices");
  g.width = s.positive("width", g.width, kMaxDistance);
  g.height = s.positive("height", g.height, kMaxDistance);
  g.center = s.vec3("center", g.center, kMaxDistance);
  const std::string orientation = s.string("orientation", "horizontal");
  if (orientation != "horizontal" && orientation != "vertical")
    s.fail("orientation", "must be \"horizontal\" or \"vertical\"");
  g.vertical = orientation == "vertical";
  g.tiltDegrees = s.number("tilt_degrees", 0.0f, -360.0, 360.0);
  return g;
}

void parseFabric(const JsonFields& r, ClothSceneSpec& spec) {
  spec.fabric = fabricPreset("cotton");
  if (!r.has("fabric")) return;
  spec.fabric = fabricFromJson(r.raw("fabric"), r.pathOf("fabric"), spec.fabricPreset);
}

void parseSettings(const JsonFields& r, ClothSettings& st) {
  const std::string integrator = r.string("integrator", integratorName(st.integrator));
  if (!parseIntegrator(integrator, st.integrator))
    r.fail("integrator", "unknown integrator '" + integrator + "' " +
                             knownNames({"symplectic_euler", "verlet", "rk4", "implicit_euler"}));
  const std::string bending = r.string("bending", bendingModelName(st.bending));
  if (!parseBendingModel(bending, st.bending))
    r.fail("bending", "unknown bending model '" + bending + "' " + knownNames({"springs", "cantilever"}));
  const std::string limit = r.string("stretch_limit", stretchLimitName(st.stretchLimit));
  if (!parseStretchLimit(limit, st.stretchLimit))
    r.fail("stretch_limit", "unknown stretch limit '" + limit + "' " + knownNames({"position", "velocity", "off"}));
  st.substeps = int(r.integer("substeps", st.substeps, 0, 1000));
  st.gravity = r.vec3("gravity", st.gravity, 1000.0f);
  st.wind = r.vec3("wind", st.wind, 1000.0f);
  st.airDamping = r.nonNegative("air_damping", st.airDamping, 1000.0);
  st.maxStretch = r.number("max_stretch", st.maxStretch, 1.0, 10.0);
  st.stretchIterations = int(r.integer("stretch_iterations", st.stretchIterations, 1, 1000));
  st.maxRefinement = int(r.integer("max_refinement", st.maxRefinement, 1, 1000));
  st.selfCollisions = r.boolean("self_collisions", st.selfCollisions);
  st.collisionThickness = r.nonNegative("thickness", st.collisionThickness, 1.0);
  st.selfThickness = r.nonNegative("self_thickness", st.selfThickness, 1.0);
  st.friction = r.has("friction") ? r.nonNegative("friction", 0.0f, 10.0) : st.friction;
  st.cgMaxIterations = int(r.integer("cg_max_iterations", st.cgMaxIterations, 1, 100000));
  st.cgTolerance = r.positive("cg_tolerance", st.cgTolerance, 1.0);
  const std::string preconditioner = r.string("cg_preconditioner", cgPreconditionerName(st.cgPreconditioner));
  if (!parseCgPreconditioner(preconditioner, st.cgPreconditioner))
    r.fail("cg_preconditioner",
           "unknown preconditioner '" + preconditioner + "' " + knownNames({"block_jacobi", "two_level"}));
}

void parsePins(const JsonFields& r, ClothSceneSpec& spec) {
  if (!r.has("pins")) return;
  const JsonFields p = r.object("pins");
  auto indices = [&](const char* key, auto& out) {
    if (!p.has(key)) return;
    const json& a = p.raw(key);
    if (!a.is_array()) p.fail(key, "must be an array of indices");
    for (const json& v : a) {
      if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() >= kMaxSheetVertices)
        p.fail(key, "must be an array of indices from 0 to " + std::to_string(kMaxSheetVertices - 1));
      out.push_back(v.get<long long>());
    }
  };
  indices("rows", spec.pinnedRows);
  indices("vertices", spec.pinnedVertices);
}

PrimitiveCollider parseCollider(const json& j, size_t index) {
  const JsonFields c(j, "colliders[" + std::to_string(index) + "]");
  const std::string type = c.string("type", "");
  PrimitiveCollider out;
  if (type == "sphere") {
    out = PrimitiveCollider::sphere(c.vec3("center", glm::vec3(0.0f), kMaxDistance),
                                    c.positive("radius", 0.0f, kMaxDistance));
  } else if (type == "capsule") {
    out = PrimitiveCollider::capsule(c.vec3("a", glm::vec3(0.0f), kMaxDistance),
                                     c.vec3("b", glm::vec3(0.0f), kMaxDistance),
                                     c.positive("radius", 0.0f, kMaxDistance));
  } else if (type == "plane") {
    const glm::vec3 n = c.vec3("normal", {0.0f, 1.0f, 0.0f}, 1000.0f);
    if (!(glm::length(n) > 0.0f)) c.fail("normal", "must not be zero");
    out = PrimitiveCollider::plane(c.vec3("point", glm::vec3(0.0f), kMaxDistance), n);
  } else {
    c.fail("type", "unknown collider type '" + type + "' " + knownNames({"sphere", "capsule", "plane"}));
  }
  out.friction = c.has("friction") ? c.nonNegative("friction", 0.0f, 10.0) : -1.0f;
  return out;
}

json vec3Json(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

}  // namespace

namespace {

ClothSceneSpec readClothScene(const json& cloth, const json& colliders, bool hasGarments) {
  ClothSceneSpec spec;
  if (!colliders.is_null()) {
    if (!colliders.is_array()) throw Error("colliders: must be an array");
    for (size_t i = 0; i < colliders.size(); ++i) spec.colliders.push_back(parseCollider(colliders[i], i));
  }
  if (cloth.is_null() && hasGarments) {
    spec.hasSheet = false;
    spec.fabric = fabricPreset("cotton");
    return spec;
  }
  if (cloth.is_null()) throw Error("the scene has no cloth section (and no garments)");
  const JsonFields r(cloth, "cloth");
  spec.hasSheet = !hasGarments || r.has("garment");
  spec.sheet = parseGarment(r);
  parseFabric(r, spec);
  try {
    spec.fabric.validate();
  } catch (const Error& e) {
    throw Error(std::string("cloth.fabric: ") + e.what());
  }
  spec.massPerVertex = r.has("mass_per_vertex") ? r.positive("mass_per_vertex", 0.0f, 1000.0) : 0.0f;
  parseSettings(r, spec.settings);
  parsePins(r, spec);
  if (!spec.hasSheet && (!spec.pinnedRows.empty() || !spec.pinnedVertices.empty()))
    r.fail("pins", "pins the sheet, but there is no \"garment\" sheet (garments have their own \"pins\")");
  for (int row : spec.pinnedRows)
    if (row >= spec.sheet.rows) r.fail("pins.rows", "row " + std::to_string(row) + " is beyond the sheet's rows");
  for (uint32_t v : spec.pinnedVertices)
    if (v >= uint32_t(spec.sheet.rows * spec.sheet.columns))
      r.fail("pins.vertices", "vertex " + std::to_string(v) + " is beyond the sheet's vertices");
  spec.fps = r.positive("fps", spec.fps, 1000.0);
  spec.animateBody = r.boolean("animate_body", spec.animateBody);
  spec.bakeFrames = int(r.integer("bake_frames", spec.bakeFrames, 1, kMaxFrames));
  return spec;
}

}  // namespace

ClothSceneSpec parseClothScene(const json& cloth, const json& colliders, const std::string& path, bool hasGarments) {
  try {
    return readClothScene(cloth, colliders, hasGarments);
  } catch (const FileError&) {
    throw;
  } catch (const Error& e) {
    throw FileError(path, e.what());
  }
}

void writeClothScene(const ClothSceneSpec& spec, json& cloth, json& colliders) {
  const SheetGarmentSpec& g = spec.sheet;
  const Fabric& f = spec.fabric;
  const ClothSettings& s = spec.settings;
  cloth = json::object();
  if (spec.hasSheet)
    cloth["garment"] = {{"type", "sheet"},
                        {"columns", g.columns},
                        {"rows", g.rows},
                        {"width", g.width},
                        {"height", g.height},
                        {"center", vec3Json(g.center)},
                        {"orientation", g.vertical ? "vertical" : "horizontal"},
                        {"tilt_degrees", g.tiltDegrees}};
  cloth["fabric"] = fabricToJson(f, spec.fabricPreset);
  if (spec.massPerVertex > 0.0f) cloth["mass_per_vertex"] = spec.massPerVertex;
  cloth["integrator"] = integratorName(s.integrator);
  cloth["substeps"] = s.substeps;
  cloth["bending"] = bendingModelName(s.bending);
  cloth["gravity"] = vec3Json(s.gravity);
  cloth["wind"] = vec3Json(s.wind);
  cloth["air_damping"] = s.airDamping;
  cloth["stretch_limit"] = stretchLimitName(s.stretchLimit);
  cloth["max_stretch"] = s.maxStretch;
  cloth["stretch_iterations"] = s.stretchIterations;
  cloth["max_refinement"] = s.maxRefinement;
  cloth["self_collisions"] = s.selfCollisions;
  cloth["thickness"] = s.collisionThickness;
  cloth["self_thickness"] = s.selfThickness;
  if (s.friction >= 0.0f) cloth["friction"] = s.friction;
  cloth["cg_max_iterations"] = s.cgMaxIterations;
  cloth["cg_tolerance"] = s.cgTolerance;
  cloth["cg_preconditioner"] = cgPreconditionerName(s.cgPreconditioner);
  cloth["pins"] = {{"rows", spec.pinnedRows}, {"vertices", spec.pinnedVertices}};
  cloth["fps"] = spec.fps;
  cloth["animate_body"] = spec.animateBody;
  cloth["bake_frames"] = spec.bakeFrames;
  colliders = json::array();
  for (const PrimitiveCollider& c : spec.colliders) {
    json j = {{"type", shapeName(c.shape)}};
    switch (c.shape) {
      case PrimitiveCollider::Shape::Sphere:
        j["center"] = vec3Json(c.a);
        j["radius"] = c.radius;
        break;
      case PrimitiveCollider::Shape::Capsule:
        j["a"] = vec3Json(c.a);
        j["b"] = vec3Json(c.b);
        j["radius"] = c.radius;
        break;
      case PrimitiveCollider::Shape::Plane:
        j["point"] = vec3Json(c.a);
        j["normal"] = vec3Json(c.b);
        break;
    }
    if (c.friction >= 0.0f) j["friction"] = c.friction;
    colliders.push_back(j);
  }
}

Sheet buildSheet(const SheetGarmentSpec& g) {
  SheetSpec s;
  s.columns = g.columns;
  s.rows = g.rows;
  s.width = g.width;
  s.height = g.height;
  if (!g.vertical) {
    s = horizontalSheet(g.columns, g.width, g.center);
    s.rows = g.rows;
    s.height = g.height;
    s.origin = g.center - glm::vec3(0.5f * g.width, 0.0f, 0.5f * g.height);
    return makeSheet(s);
  }
  // Row 0 is the top edge; rows go down, tilted toward -Z about the top edge.
  const float tilt = g.tiltDegrees * 3.14159265f / 180.0f;
  s.origin = g.center + glm::vec3(-0.5f * g.width, 0.5f * g.height, 0.0f);
  s.widthAxis = {1.0f, 0.0f, 0.0f};
  s.heightAxis = {0.0f, -std::cos(tilt), -std::sin(tilt)};
  return makeSheet(s);
}

ClothMesh buildClothMesh(const ClothSceneSpec& spec, std::vector<uint32_t>& pinned) {
  const Sheet sheet = buildSheet(spec.sheet);
  ClothMesh mesh;
  mesh.positions = sheet.positions;
  mesh.triangles = sheet.triangles;
  if (spec.massPerVertex > 0.0f) mesh.masses.assign(sheet.vertexCount(), spec.massPerVertex);
  pinned = spec.pinnedVertices;
  for (int row : spec.pinnedRows)
    for (int c = 0; c < sheet.columns; ++c) pinned.push_back(sheet.index(row, c));
  return mesh;
}

}  // namespace mq::cloth
