#include "core/garment/garment_json.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/garment/fabric_json.h"
#include "core/util/error.h"

namespace mq {
namespace {

using nlohmann::json;

json vec(glm::vec2 v) { return json::array({v.x, v.y}); }
json vec(glm::vec3 v) { return json::array({v.x, v.y, v.z}); }

const char* shapeName(EdgeShape shape) {
  switch (shape) {
    case EdgeShape::Line:
      return "line";
    case EdgeShape::Quadratic:
      return "quadratic";
    case EdgeShape::Cubic:
      return "cubic";
  }
  return "line";
}

json placementToJson(const PanelPlacement& p) {
  return {{"shape", p.shape == PanelPlacement::Shape::Cylinder ? "cylinder" : "plane"},
          {"bone", p.bone},
          {"center", vec(p.center)},
          {"axis", vec(p.axis)},
          {"facing", vec(p.facing)},
          {"radius", p.radius},
          {"anchor", vec(p.anchor)}};
}

json panelToJson(const Panel& panel) {
  json corners = json::array(), edges = json::array();
  for (glm::vec2 c : panel.corners) corners.push_back(vec(c));
  for (const PanelEdge& e : panel.edges) {
    json edge = {{"name", e.name}, {"shape", shapeName(e.shape)}};
    if (e.shape == EdgeShape::Quadratic) edge["controls"] = json::array({vec(e.control[0])});
    if (e.shape == EdgeShape::Cubic) edge["controls"] = json::array({vec(e.control[0]), vec(e.control[1])});
    edges.push_back(edge);
  }
  return {
      {"name", panel.name}, {"corners", corners}, {"edges", edges}, {"placement", placementToJson(panel.placement)}};
}

// ---- Reading, with the JSON path in every error ------------------------------

[[noreturn]] void fail(const std::string& path, const std::string& problem) { throw Error(path + ": " + problem); }

const json& member(const json& object, const std::string& path, const char* key) {
  if (!object.is_object()) fail(path, "expected an object");
  auto it = object.find(key);
  if (it == object.end()) fail(path, std::string("missing \"") + key + "\"");
  return *it;
}

const json* optionalMember(const json& object, const char* key) {
  auto it = object.find(key);
  return it == object.end() || it->is_null() ? nullptr : &*it;
}

// Garments are metres across: nothing in a pattern or a placement lies
// farther than this from its origin.
constexpr double kMaxCoordinate = 100.0;

float number(const json& value, const std::string& path) {
  if (!value.is_number()) fail(path, "expected a number");
  const double d = value.get<double>();
  if (!std::isfinite(d) || std::abs(d) > 3.0e38) fail(path, "must be a finite number");
  return float(d);
}

std::string text(const json& value, const std::string& path) {
  if (!value.is_string()) fail(path, "expected a string");
  return value.get<std::string>();
}

const json& array(const json& value, const std::string& path) {
  if (!value.is_array()) fail(path, "expected an array");
  return value;
}

template <int N>
glm::vec<N, float> vector(const json& value, const std::string& path) {
  static const char* expected = N == 2 ? "expected [u, v] (two numbers)" : "expected [x, y, z] (three numbers)";
  if (!value.is_array() || value.size() != N) fail(path, expected);
  glm::vec<N, float> v;
  for (int i = 0; i < N; ++i) {
    if (!value[i].is_number()) fail(path, expected);
    const double d = value[i].get<double>();
    if (!(std::abs(d) <= kMaxCoordinate)) fail(path, "must hold numbers between -100 and 100 (metres)");
    v[i] = float(d);
  }
  return v;
}

std::string at(const std::string& path, const char* key) { return path + "." + key; }
std::string at(const std::string& path, size_t index) { return path + "[" + std::to_string(index) + "]"; }

EdgeShape edgeShape(const std::string& name, const std::string& path) {
  if (name == "line") return EdgeShape::Line;
  if (name == "quadratic") return EdgeShape::Quadratic;
  if (name == "cubic") return EdgeShape::Cubic;
  fail(path, "unknown edge shape '" + name + "' (line, quadratic or cubic)");
}

PanelEdge edgeFromJson(const json& j, const std::string& path) {
  PanelEdge edge;
  if (!j.is_object()) fail(path, "expected an object");
  if (const json* name = optionalMember(j, "name")) edge.name = text(*name, at(path, "name"));
  const json* shape = optionalMember(j, "shape");
  edge.shape = shape ? edgeShape(text(*shape, at(path, "shape")), at(path, "shape")) : EdgeShape::Line;
  size_t needed = edge.shape == EdgeShape::Quadratic ? 1 : edge.shape == EdgeShape::Cubic ? 2 : 0;
  if (needed == 0) return edge;
  std::string controlsPath = at(path, "controls");
  const json& controls = array(member(j, path, "controls"), controlsPath);
  if (controls.size() != needed)
    fail(controlsPath, "a " + std::string(shapeName(edge.shape)) + " edge needs " + std::to_string(needed) +
                           " control point(s), got " + std::to_string(controls.size()));
  for (size_t i = 0; i < needed; ++i) edge.control[i] = vector<2>(controls[i], at(controlsPath, i));
  if (needed == 1) edge.control[1] = edge.control[0];
  return edge;
}

PanelPlacement placementFromJson(const json& j, const std::string& path) {
  PanelPlacement p;
  std::string shape = text(member(j, path, "shape"), at(path, "shape"));
  if (shape == "cylinder")
    p.shape = PanelPlacement::Shape::Cylinder;
  else if (shape != "plane")
    fail(at(path, "shape"), "unknown placement '" + shape + "' (plane or cylinder)");
  if (const json* bone = optionalMember(j, "bone")) p.bone = text(*bone, at(path, "bone"));
  p.center = vector<3>(member(j, path, "center"), at(path, "center"));
  p.axis = vector<3>(member(j, path, "axis"), at(path, "axis"));
  p.facing = vector<3>(member(j, path, "facing"), at(path, "facing"));
  if (const json* anchor = optionalMember(j, "anchor")) p.anchor = vector<2>(*anchor, at(path, "anchor"));
  if (p.shape == PanelPlacement::Shape::Cylinder) {
    p.radius = number(member(j, path, "radius"), at(path, "radius"));
    if (!(p.radius > 0.0f && p.radius <= kMaxCoordinate))
      fail(at(path, "radius"), "must be between 0 and 100 (metres)");
  }
  if (glm::length(p.axis) < 1e-6f || glm::length(p.facing) < 1e-6f) fail(path, "axis and facing must be non-zero");
  p.axis = glm::normalize(p.axis);
  p.facing = p.facing - glm::dot(p.facing, p.axis) * p.axis;
  if (glm::length(p.facing) < 1e-6f) fail(at(path, "facing"), "must not be parallel to the axis");
  p.facing = glm::normalize(p.facing);
  return p;
}

Panel panelFromJson(const json& j, const std::string& path) {
  Panel panel;
  panel.name = text(member(j, path, "name"), at(path, "name"));
  const json& corners = array(member(j, path, "corners"), at(path, "corners"));
  for (size_t i = 0; i < corners.size(); ++i)
    panel.corners.push_back(vector<2>(corners[i], at(at(path, "corners"), i)));
  const json& edges = array(member(j, path, "edges"), at(path, "edges"));
  if (edges.size() != corners.size())
    fail(at(path, "edges"), "has " + std::to_string(edges.size()) + " edges for " + std::to_string(corners.size()) +
                                " corners (one edge leaves each corner)");
  for (size_t i = 0; i < edges.size(); ++i) panel.edges.push_back(edgeFromJson(edges[i], at(at(path, "edges"), i)));
  if (const json* placement = optionalMember(j, "placement"))
    panel.placement = placementFromJson(*placement, at(path, "placement"));
  return panel;
}

std::pair<std::string, std::string> seamSide(const json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_string() || !j[1].is_string())
    fail(path, "expected [\"panel\", \"edge\"]");
  return {j[0].get<std::string>(), j[1].get<std::string>()};
}

// "pins": {"vertices": [garment-mesh vertex indices], "attach": "body" | "space"}.
// (Indices are checked against the mesh where it is built: the simulation.)
GarmentPins pinsFromJson(const json& j, const std::string& path) {
  GarmentPins pins;
  if (!j.is_object()) fail(path, "expected {\"vertices\": [...], \"attach\": \"body\" | \"space\"}");
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it.key() != "vertices" && it.key() != "attach") fail(at(path, it.key().c_str()), "unknown pins key");
  if (const json* vertices = optionalMember(j, "vertices")) {
    const std::string verticesPath = at(path, "vertices");
    array(*vertices, verticesPath);
    for (size_t i = 0; i < vertices->size(); ++i) {
      const json& v = (*vertices)[i];
      if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > 0xffffffffLL)
        fail(at(verticesPath, i), "expected a garment vertex index (an integer >= 0)");
      pins.vertices.push_back(uint32_t(v.get<long long>()));
    }
  }
  if (const json* attach = optionalMember(j, "attach")) {
    const std::string name = text(*attach, at(path, "attach"));
    if (name == "body")
      pins.attach = GarmentPins::Attach::Body;
    else if (name == "space")
      pins.attach = GarmentPins::Attach::Space;
    else
      fail(at(path, "attach"), "unknown attach '" + name + "' (body or space)");
  }
  return pins;
}

}  // namespace

json garmentToJson(const Garment& garment) {
  json panels = json::array(), seams = json::array();
  for (const Panel& panel : garment.panels) panels.push_back(panelToJson(panel));
  for (const Seam& s : garment.seams)
    seams.push_back({{"a", {s.panelA, s.edgeA}}, {"b", {s.panelB, s.edgeB}}, {"reversed", s.reversed}});
  json out = {
      {"name", garment.name},
      {"fabric", garment.customFabric ? fabricToJson(*garment.customFabric, garment.fabric) : json(garment.fabric)},
      {"targetEdgeLength", garment.targetEdgeLength},
      {"panels", panels},
      {"seams", seams}};
  if (!garment.pins.vertices.empty())
    out["pins"] = {{"vertices", garment.pins.vertices},
                   {"attach", garment.pins.attach == GarmentPins::Attach::Body ? "body" : "space"}};
  if (garment.layer != 0) out["layer"] = garment.layer;
  if (!garment.recipe.type.empty())
    out["recipe"] = {{"type", garment.recipe.type}, {"parameters", garment.recipe.parameters}};
  return out;
}

json garmentsToJson(const std::vector<Garment>& garments) {
  json out = json::array();
  for (const Garment& g : garments) out.push_back(garmentToJson(g));
  return out;
}

Garment garmentFromJson(const json& j, const std::string& path) {
  Garment g;
  if (!j.is_object()) fail(path, "expected a garment object");
  if (const json* name = optionalMember(j, "name")) g.name = text(*name, at(path, "name"));
  if (const json* fabric = optionalMember(j, "fabric")) {
    Fabric values = fabricFromJson(*fabric, at(path, "fabric"), g.fabric);
    if (!fabric->is_string()) g.customFabric = values;
  }
  if (const json* pins = optionalMember(j, "pins")) g.pins = pinsFromJson(*pins, at(path, "pins"));
  if (const json* layer = optionalMember(j, "layer")) {
    if (!layer->is_number_integer() || layer->get<long long>() < 0 || layer->get<long long>() > Garment::kMaxLayer)
      fail(at(path, "layer"), "expected a layer number, an integer from 0 to " + std::to_string(Garment::kMaxLayer));
    g.layer = int(layer->get<long long>());
  }
  if (const json* target = optionalMember(j, "targetEdgeLength")) {
    g.targetEdgeLength = number(*target, at(path, "targetEdgeLength"));
    if (!(g.targetEdgeLength >= 0.002f && g.targetEdgeLength <= 1.0f))
      fail(at(path, "targetEdgeLength"), "must be between 0.002 and 1 metre");
  }
  const json& panels = array(member(j, path, "panels"), at(path, "panels"));
  for (size_t i = 0; i < panels.size(); ++i) g.panels.push_back(panelFromJson(panels[i], at(at(path, "panels"), i)));
  if (const json* seams = optionalMember(j, "seams")) {
    array(*seams, at(path, "seams"));
    for (size_t i = 0; i < seams->size(); ++i) {
      std::string seamPath = at(at(path, "seams"), i);
      const json& s = (*seams)[i];
      auto [panelA, edgeA] = seamSide(member(s, seamPath, "a"), at(seamPath, "a"));
      auto [panelB, edgeB] = seamSide(member(s, seamPath, "b"), at(seamPath, "b"));
      bool reversed = true;
      if (const json* r = optionalMember(s, "reversed")) {
        if (!r->is_boolean()) fail(at(seamPath, "reversed"), "expected true or false");
        reversed = r->get<bool>();
      }
      g.seams.push_back({panelA, edgeA, panelB, edgeB, reversed});
    }
  }
  if (const json* recipe = optionalMember(j, "recipe")) {
    std::string recipePath = at(path, "recipe");
    g.recipe.type = text(member(*recipe, recipePath, "type"), at(recipePath, "type"));
    if (const json* parameters = optionalMember(*recipe, "parameters")) {
      if (!parameters->is_object()) fail(at(recipePath, "parameters"), "expected an object of numbers");
      for (auto it = parameters->begin(); it != parameters->end(); ++it)
        g.recipe.parameters[it.key()] = number(it.value(), at(at(recipePath, "parameters"), it.key().c_str()));
    }
  }
  try {
    g.validate();
  } catch (const Error& e) {
    fail(path, e.what());
  }
  return g;
}

std::vector<Garment> garmentsFromJson(const json& j, const std::string& path) {
  std::vector<Garment> garments;
  if (j.is_null()) return garments;
  array(j, path);
  for (size_t i = 0; i < j.size(); ++i) garments.push_back(garmentFromJson(j[i], at(path, i)));
  return garments;
}

}  // namespace mq
