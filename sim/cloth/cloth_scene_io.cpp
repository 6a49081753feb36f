#include "sim/cloth/cloth_scene_io.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/garment/fabric_json.h"
#include "core/util/error.h"

namespace mq::cloth {

namespace {

using nlohmann::json;

// Reads typed values from one section, naming "<section>.<key>" in errors.
class SectionReader {
 public:
  SectionReader(const json& j, std::string section, std::string path)
      : j_(j), section_(std::move(section)), path_(std::move(path)) {
    if (!j_.is_object()) fail("", "must be an object");
  }

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw FileError(path_, section_ + (key.empty() ? "" : "." + key) + ": " + problem);
  }

  bool has(const std::string& key) const { return j_.contains(key) && !j_[key].is_null(); }

  float number(const std::string& key, float fallback) const {
    if (!has(key)) return fallback;
    const json& v = j_[key];
    if (!v.is_number()) fail(key, "must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d) || std::abs(d) > 3.0e38) fail(key, "must be a finite number");
    return float(d);
  }

  float positive(const std::string& key, float fallback) const {
    const float f = number(key, fallback);
    if (!(f > 0.0f)) fail(key, "must be positive");
    return f;
  }

  float nonNegative(const std::string& key, float fallback) const {
    const float f = number(key, fallback);
    if (f < 0.0f) fail(key, "must not be negative");
    return f;
  }

  int integer(const std::string& key, int fallback, int minimum) const {
    if (!has(key)) return fallback;
    const json& v = j_[key];
    if (!v.is_number_integer()) fail(key, "must be an integer");
    const long long i = v.get<long long>();
    if (i < minimum || i > 1000000000) fail(key, "must be an integer >= " + std::to_string(minimum));
    return int(i);
  }

  bool boolean(const std::string& key, bool fallback) const {
    if (!has(key)) return fallback;
    if (!j_[key].is_boolean()) fail(key, "must be true or false");
    return j_[key].get<bool>();
  }

  std::string string(const std::string& key, const std::string& fallback) const {
    if (!has(key)) return fallback;
    if (!j_[key].is_string()) fail(key, "must be a string");
    return j_[key].get<std::string>();
  }

  glm::vec3 vec3(const std::string& key, glm::vec3 fallback) const {
    if (!has(key)) return fallback;
    const json& v = j_[key];
    if (!v.is_array() || v.size() != 3) fail(key, "must be an array of 3 numbers");
    glm::vec3 out;
    for (int c = 0; c < 3; ++c) {
      if (!v[c].is_number() || !std::isfinite(v[c].get<double>()) || std::abs(v[c].get<double>()) > 3.0e38)
        fail(key, "must be an array of 3 finite numbers");
      out[c] = v[c].get<float>();
    }
    return out;
  }

  const json& raw(const std::string& key) const { return j_[key]; }
  const std::string& section() const { return section_; }
  const std::string& path() const { return path_; }

 private:
  const json& j_;
  std::string section_, path_;
};

std::string knownNames(std::initializer_list<const char*> names) {
  std::string s;
  for (const char* n : names) s += (s.empty() ? "" : ", ") + std::string(n);
  return "(known: " + s + ")";
}

SheetGarmentSpec parseGarment(const SectionReader& r) {
  SheetGarmentSpec g;
  if (!r.has("garment")) return g;
  const SectionReader s(r.raw("garment"), r.section() + ".garment", r.path());
  const std::string type = s.string("type", "sheet");
  if (type != "sheet") s.fail("type", "unknown garment type '" + type + "' " + knownNames({"sheet"}));
  g.columns = s.integer("columns", g.columns, 2);
  g.rows = s.integer("rows", g.rows, 2);
  g.width = s.positive("width", g.width);
  g.height = s.positive("height", g.height);
  g.center = s.vec3("center", g.center);
  const std::string orientation = s.string("orientation", "horizontal");
  if (orientation != "horizontal" && orientation != "vertical")
    s.fail("orientation", "must be \"horizontal\" or \"vertical\"");
  g.vertical = orientation == "vertical";
  g.tiltDegrees = s.number("tilt_degrees", 0.0f);
  return g;
}

void parseFabric(const SectionReader& r, ClothSceneSpec& spec) {
  spec.fabric = fabricPreset("cotton");
  if (!r.has("fabric")) return;
  try {
    spec.fabric = fabricFromJson(r.raw("fabric"), r.section() + ".fabric", spec.fabricPreset);
  } catch (const Error& e) {
    throw FileError(r.path(), e.what());
  }
}

void parseSettings(const SectionReader& r, ClothSettings& st) {
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
  st.substeps = r.integer("substeps", st.substeps, 0);
  st.gravity = r.vec3("gravity", st.gravity);
  st.wind = r.vec3("wind", st.wind);
  st.airDamping = r.nonNegative("air_damping", st.airDamping);
  st.maxStretch = r.number("max_stretch", st.maxStretch);
  if (st.maxStretch < 1.0f) r.fail("max_stretch", "must be at least 1");
  st.stretchIterations = r.integer("stretch_iterations", st.stretchIterations, 1);
  st.maxRefinement = r.integer("max_refinement", st.maxRefinement, 1);
  st.selfCollisions = r.boolean("self_collisions", st.selfCollisions);
  st.collisionThickness = r.nonNegative("thickness", st.collisionThickness);
  st.selfThickness = r.nonNegative("self_thickness", st.selfThickness);
  st.friction = r.has("friction") ? r.nonNegative("friction", 0.0f) : st.friction;
  st.cgMaxIterations = r.integer("cg_max_iterations", st.cgMaxIterations, 1);
  st.cgTolerance = r.positive("cg_tolerance", st.cgTolerance);
  const std::string preconditioner = r.string("cg_preconditioner", cgPreconditionerName(st.cgPreconditioner));
  if (!parseCgPreconditioner(preconditioner, st.cgPreconditioner))
    r.fail("cg_preconditioner", "unknown preconditioner '" + preconditioner + "' " +
                                    knownNames({"block_jacobi", "two_level"}));
}

void parsePins(const SectionReader& r, ClothSceneSpec& spec) {
  if (!r.has("pins")) return;
  const SectionReader p(r.raw("pins"), r.section() + ".pins", r.path());
  auto indices = [&](const char* key, auto& out) {
    if (!p.has(key)) return;
    const json& a = p.raw(key);
    if (!a.is_array()) p.fail(key, "must be an array of indices");
    for (const json& v : a) {
      if (!v.is_number_integer() || v.get<long long>() < 0) p.fail(key, "must be an array of non-negative integers");
      out.push_back(v.get<long long>());
    }
  };
  indices("rows", spec.pinnedRows);
  indices("vertices", spec.pinnedVertices);
}

PrimitiveCollider parseCollider(const json& j, size_t index, const std::string& path) {
  const SectionReader c(j, "colliders[" + std::to_string(index) + "]", path);
  const std::string type = c.string("type", "");
  PrimitiveCollider out;
  if (type == "sphere") {
    out = PrimitiveCollider::sphere(c.vec3("center", glm::vec3(0.0f)), c.positive("radius", 0.0f));
  } else if (type == "capsule") {
    out = PrimitiveCollider::capsule(c.vec3("a", glm::vec3(0.0f)), c.vec3("b", glm::vec3(0.0f)), c.positive("radius", 0.0f));
  } else if (type == "plane") {
    const glm::vec3 n = c.vec3("normal", {0.0f, 1.0f, 0.0f});
    if (!(glm::length(n) > 0.0f)) c.fail("normal", "must not be zero");
    out = PrimitiveCollider::plane(c.vec3("point", glm::vec3(0.0f)), n);
  } else {
    c.fail("type", "unknown collider type '" + type + "' " + knownNames({"sphere", "capsule", "plane"}));
  }
  out.friction = c.has("friction") ? c.nonNegative("friction", 0.0f) : -1.0f;
  return out;
}

json vec3Json(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

}  // namespace

ClothSceneSpec parseClothScene(const json& cloth, const json& colliders, const std::string& path, bool hasGarments) {
  ClothSceneSpec spec;
  if (!colliders.is_null()) {
    if (!colliders.is_array()) throw FileError(path, "colliders: must be an array");
    for (size_t i = 0; i < colliders.size(); ++i) spec.colliders.push_back(parseCollider(colliders[i], i, path));
  }
  if (cloth.is_null() && hasGarments) {
    spec.hasSheet = false;
    spec.fabric = fabricPreset("cotton");
    return spec;
  }
  if (cloth.is_null()) throw FileError(path, "the scene has no cloth section (and no garments)");
  const SectionReader r(cloth, "cloth", path);
  spec.hasSheet = !hasGarments || r.has("garment");
  spec.sheet = parseGarment(r);
  parseFabric(r, spec);
  try {
    spec.fabric.validate();
  } catch (const Error& e) {
    throw FileError(path, std::string("cloth.fabric: ") + e.what());
  }
  spec.massPerVertex = r.has("mass_per_vertex") ? r.positive("mass_per_vertex", 0.0f) : 0.0f;
  parseSettings(r, spec.settings);
  parsePins(r, spec);
  if (!spec.hasSheet && (!spec.pinnedRows.empty() || !spec.pinnedVertices.empty()))
    r.fail("pins", "pins the sheet, but there is no \"garment\" sheet (garments have their own \"pins\")");
  for (int row : spec.pinnedRows)
    if (row >= spec.sheet.rows) r.fail("pins.rows", "row " + std::to_string(row) + " is beyond the sheet's rows");
  for (uint32_t v : spec.pinnedVertices)
    if (v >= uint32_t(spec.sheet.rows * spec.sheet.columns))
      r.fail("pins.vertices", "vertex " + std::to_string(v) + " is beyond the sheet's vertices");
  spec.fps = r.positive("fps", spec.fps);
  spec.animateBody = r.boolean("animate_body", spec.animateBody);
  spec.bakeFrames = r.integer("bake_frames", spec.bakeFrames, 1);
  return spec;
}

void writeClothScene(const ClothSceneSpec& spec, json& cloth, json& colliders) {
  const SheetGarmentSpec& g = spec.sheet;
  const Fabric& f = spec.fabric;
  const ClothSettings& s = spec.settings;
  cloth = json::object();
  if (spec.hasSheet)
    cloth["garment"] = {{"type", "sheet"}, {"columns", g.columns}, {"rows", g.rows}, {"width", g.width},
                      {"height", g.height}, {"center", vec3Json(g.center)},
                      {"orientation", g.vertical ? "vertical" : "horizontal"}, {"tilt_degrees", g.tiltDegrees}};
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
      case PrimitiveCollider::Shape::Sphere: j["center"] = vec3Json(c.a); j["radius"] = c.radius; break;
      case PrimitiveCollider::Shape::Capsule:
        j["a"] = vec3Json(c.a); j["b"] = vec3Json(c.b); j["radius"] = c.radius; break;
      case PrimitiveCollider::Shape::Plane: j["point"] = vec3Json(c.a); j["normal"] = vec3Json(c.b); break;
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
