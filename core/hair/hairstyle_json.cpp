#include "core/hair/hairstyle_json.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>

#include "core/util/error.h"

namespace mq {

using nlohmann::json;

namespace {

// Floats written with 6 significant digits, so files read 0.05, not 0.0500000007.
double tidy(float f) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", double(f));
  return std::strtod(text, nullptr);
}

json vec(const glm::vec3& v) { return json::array({tidy(v.x), tidy(v.y), tidy(v.z)}); }

glm::vec3 readVec(const json& j, const char* field) {
  if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
    throw Error(std::string("hair: '") + field + "' must be an array of 3 numbers");
  return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
}

// Reads an optional field into `out` (kept when absent).
template <class T>
void read(const json& j, const char* field, T& out) {
  auto it = j.find(field);
  if (it == j.end()) return;
  try {
    if constexpr (std::is_same_v<T, glm::vec3>) out = readVec(*it, field);
    else out = it->get<T>();
  } catch (const json::exception&) {
    throw Error(std::string("hair: field '") + field + "' has the wrong type");
  }
}

const json& arrayField(const json& j, const char* field) {
  static const json empty = json::array();
  auto it = j.find(field);
  if (it == j.end()) return empty;
  if (!it->is_array()) throw Error(std::string("hair: '") + field + "' must be an array");
  return *it;
}

void readPrimitives(const json& j, FlowPrimitives& p) {
  if (j.contains("streams")) {
    p.streams.clear();
    for (const json& e : arrayField(j, "streams")) {
      UniformStream s;
      read(e, "direction", s.direction);
      read(e, "strength", s.strength);
      p.streams.push_back(s);
    }
  }
  if (j.contains("sources")) {
    p.sources.clear();
    for (const json& e : arrayField(j, "sources")) {
      PointSource s;
      read(e, "position", s.position);
      read(e, "strength", s.strength);
      read(e, "radius", s.radius);
      p.sources.push_back(s);
    }
  }
  if (j.contains("vortices")) {
    p.vortices.clear();
    for (const json& e : arrayField(j, "vortices")) {
      Vortex v;
      read(e, "position", v.position);
      read(e, "axis", v.axis);
      read(e, "strength", v.strength);
      read(e, "radius", v.radius);
      if (glm::length(v.axis) <= 0.0f) throw Error("hair: a vortex axis must not be zero");
      p.vortices.push_back(v);
    }
  }
}

}  // namespace

std::string hairShadingModelName(HairShadingModel model) {
  return model == HairShadingModel::Physical ? "physical" : "kajiya-kay";
}

HairShadingModel hairShadingModelFromName(const std::string& name) {
  if (name == "kajiya-kay") return HairShadingModel::KajiyaKay;
  if (name == "physical") return HairShadingModel::Physical;
  throw Error("hair: unknown shading model '" + name + "' (kajiya-kay or physical)");
}

HairShadingParams hairShadingFromJson(const json& j, const HairShadingParams& base) {
  if (!j.is_object()) throw Error("hair: 'shading' must be an object");
  HairShadingParams s = base;
  std::string model = hairShadingModelName(s.model);
  read(j, "model", model);
  s.model = hairShadingModelFromName(model);
  read(j, "melanin", s.melanin);
  read(j, "pheomelanin", s.pheomelanin);
  read(j, "roughness", s.roughness);
  if (!(s.melanin >= 0.0f) || !(s.pheomelanin >= 0.0f)) throw Error("hair: melanin concentrations must be >= 0");
  if (!(s.roughness >= 0.05f && s.roughness <= 1.0f)) throw Error("hair: shading 'roughness' must be in 0.05..1");
  return s;
}

json toJson(const HairShadingParams& s) {
  return {{"model", hairShadingModelName(s.model)},
          {"melanin", tidy(s.melanin)},
          {"pheomelanin", tidy(s.pheomelanin)},
          {"roughness", tidy(s.roughness)}};
}

HairStyle hairStyleFromJson(const json& j) {
  if (j.is_string()) return builtinHairStyle(j.get<std::string>());
  if (!j.is_object()) throw Error("hair: 'style' must be a built-in style name or an object");
  HairStyle s = j.contains("preset") ? hairStyleFromJson(j.at("preset")) : HairStyle{};
  read(j, "name", s.name);
  readPrimitives(j, s.primitives);
  read(j, "scalp_outflow", s.scalpOutflow);
  read(j, "noise_amplitude", s.noiseAmplitude);
  read(j, "noise_scale", s.noiseScale);
  read(j, "density", s.density);
  read(j, "max_strands", s.maxStrands);
  read(j, "guides", s.guideCount);
  read(j, "length", s.length);
  read(j, "length_variation", s.lengthVariation);
  if (j.contains("length_map")) {
    s.lengthMap.clear();
    for (const json& e : arrayField(j, "length_map")) {
      LengthPoint p;
      read(e, "position", p.position);
      read(e, "scale", p.scale);
      read(e, "radius", p.radius);
      s.lengthMap.push_back(p);
    }
  }
  read(j, "points_per_strand", s.pointsPerStrand);
  read(j, "strand_noise", s.strandNoise);
  read(j, "wave_amplitude", s.waveAmplitude);
  read(j, "wave_length", s.waveLength);
  read(j, "curl_radius", s.curlRadius);
  read(j, "curl_length", s.curlLength);
  read(j, "clumping", s.clumping);
  read(j, "clump_shape", s.clumpShape);
  read(j, "frizz", s.frizz);
  read(j, "frizz_frequency", s.frizzFrequency);
  read(j, "root_color", s.rootColor);
  read(j, "tip_color", s.tipColor);
  read(j, "seed", s.seed);
  if (j.contains("shading")) s.shading = hairShadingFromJson(j.at("shading"), s.shading);
  if (s.pointsPerStrand < 2 || s.pointsPerStrand > 1024) throw Error("hair: 'points_per_strand' must be in 2..1024");
  if (!(s.length > 0.0f)) throw Error("hair: 'length' must be positive");
  if (s.density < 0.0f || s.maxStrands < 0 || s.guideCount < 1) throw Error("hair: density and counts must be positive");
  return s;
}

ScalpRegion scalpRegionFromJson(const json& j) {
  ScalpRegion r;
  if (j.is_null()) return r;
  if (!j.is_object()) throw Error("hair: 'scalp' must be an object");
  std::string kind = "tagged";
  read(j, "kind", kind);
  if (kind == "tagged") {
    r.kind = ScalpRegion::Kind::Tagged;
  } else if (kind == "bone_cone") {
    r.kind = ScalpRegion::Kind::BoneCone;
    read(j, "bone", r.bone);
    read(j, "axis", r.axis);
    read(j, "angle", r.angleDegrees);
    if (glm::length(r.axis) <= 0.0f) throw Error("hair: the scalp axis must not be zero");
  } else if (kind == "faces") {
    r.kind = ScalpRegion::Kind::Faces;
    read(j, "mesh", r.mesh);
    read(j, "faces", r.faces);
  } else {
    throw Error("hair: unknown scalp kind '" + kind + "' (tagged, bone_cone or faces)");
  }
  return r;
}

HairSection hairSectionFromJson(const json& j) {
  HairSection section;
  if (j.is_null()) return section;
  if (!j.is_object()) throw Error("hair: the section must be an object");
  if (j.contains("style")) {
    const json& style = j.at("style");
    section.style = hairStyleFromJson(style);
    section.fitToHead = style.is_string() || style.contains("preset");
  }
  if (j.contains("scalp")) {
    section.scalp = scalpRegionFromJson(j.at("scalp"));
    section.scalpGiven = true;
  }
  read(j, "strands", section.strands);
  if (j.contains("shading")) section.style.shading = hairShadingFromJson(j.at("shading"), section.style.shading);
  return section;
}

json toJson(const HairStyle& s) {
  json streams = json::array(), sources = json::array(), vortices = json::array(), lengthMap = json::array();
  for (const UniformStream& e : s.primitives.streams) streams.push_back({{"direction", vec(e.direction)}, {"strength", tidy(e.strength)}});
  for (const PointSource& e : s.primitives.sources)
    sources.push_back({{"position", vec(e.position)}, {"strength", tidy(e.strength)}, {"radius", tidy(e.radius)}});
  for (const Vortex& e : s.primitives.vortices)
    vortices.push_back({{"position", vec(e.position)}, {"axis", vec(e.axis)}, {"strength", tidy(e.strength)}, {"radius", tidy(e.radius)}});
  for (const LengthPoint& e : s.lengthMap)
    lengthMap.push_back({{"position", vec(e.position)}, {"scale", tidy(e.scale)}, {"radius", tidy(e.radius)}});
  json out{{"name", s.name},
              {"streams", streams},
              {"sources", sources},
              {"vortices", vortices},
              {"scalp_outflow", tidy(s.scalpOutflow)},
              {"noise_amplitude", tidy(s.noiseAmplitude)},
              {"noise_scale", tidy(s.noiseScale)},
              {"density", tidy(s.density)},
              {"max_strands", s.maxStrands},
              {"guides", s.guideCount},
              {"length", tidy(s.length)},
              {"length_variation", tidy(s.lengthVariation)},
              {"length_map", lengthMap},
              {"points_per_strand", s.pointsPerStrand},
              {"strand_noise", tidy(s.strandNoise)},
              {"wave_amplitude", tidy(s.waveAmplitude)},
              {"wave_length", tidy(s.waveLength)},
              {"curl_radius", tidy(s.curlRadius)},
              {"curl_length", tidy(s.curlLength)},
              {"clumping", tidy(s.clumping)},
              {"clump_shape", tidy(s.clumpShape)},
              {"frizz", tidy(s.frizz)},
              {"frizz_frequency", tidy(s.frizzFrequency)},
              {"root_color", vec(s.rootColor)},
              {"tip_color", vec(s.tipColor)},
              {"seed", s.seed}};
  if (s.shading != HairShadingParams{}) out["shading"] = toJson(s.shading);
  return out;
}

json toJson(const ScalpRegion& r) {
  switch (r.kind) {
    case ScalpRegion::Kind::BoneCone:
      return {{"kind", "bone_cone"}, {"bone", r.bone}, {"axis", vec(r.axis)}, {"angle", tidy(r.angleDegrees)}};
    case ScalpRegion::Kind::Faces:
      return {{"kind", "faces"}, {"mesh", r.mesh}, {"faces", r.faces}};
    case ScalpRegion::Kind::Tagged:
    default:
      return {{"kind", "tagged"}};
  }
}

json toJson(const HairSection& section) {
  return {{"style", toJson(section.style)}, {"scalp", toJson(section.scalp)}, {"strands", section.strands}};
}

}  // namespace mq
