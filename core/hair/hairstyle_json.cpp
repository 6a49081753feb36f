#include "core/hair/hairstyle_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/io/json_fields.h"
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

// Metres: nothing on a head lies farther than this from the origin.
constexpr float kMaxDistance = 100.0f;
// The groom refuses more strands than this (memory: strands x points).
constexpr long long kMaxStrands = 150000;

void readPrimitives(const JsonFields& f, FlowPrimitives& p) {
  if (f.has("streams")) {
    p.streams.clear();
    for (size_t i = 0; i < f.array("streams").size(); ++i) {
      const JsonFields e = f.element("streams", i);
      UniformStream s;
      s.direction = e.vec3("direction", s.direction, 1.0e3f);
      s.strength = e.number("strength", s.strength, -1.0e3, 1.0e3);
      p.streams.push_back(s);
    }
  }
  if (f.has("sources")) {
    p.sources.clear();
    for (size_t i = 0; i < f.array("sources").size(); ++i) {
      const JsonFields e = f.element("sources", i);
      PointSource s;
      s.position = e.vec3("position", s.position, kMaxDistance);
      s.strength = e.number("strength", s.strength, -1.0e3, 1.0e3);
      s.radius = e.positive("radius", s.radius, kMaxDistance);
      p.sources.push_back(s);
    }
  }
  if (f.has("vortices")) {
    p.vortices.clear();
    for (size_t i = 0; i < f.array("vortices").size(); ++i) {
      const JsonFields e = f.element("vortices", i);
      Vortex v;
      v.position = e.vec3("position", v.position, kMaxDistance);
      v.axis = e.vec3("axis", v.axis, 1.0e3f);
      v.strength = e.number("strength", v.strength, -1.0e3, 1.0e3);
      v.radius = e.positive("radius", v.radius, kMaxDistance);
      if (glm::length(v.axis) <= 0.0f) e.fail("axis", "must not be zero");
      p.vortices.push_back(v);
    }
  }
}

// "strokes": [{"brush", "radius", "strength", "mirror", "dabs": [[x, y, z, mx, my, mz], ...]}]
std::vector<GroomStroke> readStrokes(const JsonFields& f) {
  const json& list = f.array("strokes");
  if (list.size() > kMaxGroomStrokes)
    f.fail("strokes",
           "holds " + std::to_string(list.size()) + " strokes, more than " + std::to_string(kMaxGroomStrokes));
  std::vector<GroomStroke> strokes;
  size_t dabCount = 0;
  for (size_t i = 0; i < list.size(); ++i) {
    const JsonFields e = f.element("strokes", i);
    e.allowOnly({"brush", "radius", "strength", "mirror", "value", "dabs"});
    GroomStroke stroke;
    try {
      stroke.brush = groomBrushFromName(e.string("brush", groomBrushName(stroke.brush)));
    } catch (const Error& error) {
      e.fail("brush", error.what());
    }
    stroke.radius = e.positive("radius", stroke.radius, 1.0);
    stroke.strength = e.number("strength", stroke.strength, stroke.brush == GroomBrush::Length ? -1.0 : 0.0, 1.0);
    stroke.mirror = e.boolean("mirror", stroke.mirror);
    if (isPaintBrush(stroke.brush)) {
      const PaintRange range = paintRange(stroke.brush);
      stroke.value = e.number("value", std::clamp(stroke.value, range.min, range.max), range.min, range.max);
    }
    const json& dabs = e.array("dabs");
    dabCount += dabs.size();
    if (dabCount > kMaxGroomDabs)
      f.fail("strokes", "holds more than " + std::to_string(kMaxGroomDabs) + " dabs in all");
    for (const json& dab : dabs) {
      if (!dab.is_array() || dab.size() != 6) e.fail("dabs", "each dab is [x, y, z, mx, my, mz]");
      float v[6];
      for (int k = 0; k < 6; ++k) {
        if (!dab[k].is_number() || !std::isfinite(dab[k].get<double>()) ||
            std::abs(dab[k].get<double>()) > kMaxDistance)
          e.fail("dabs", "each dab holds six numbers of magnitude at most 100 (metres)");
        v[k] = dab[k].get<float>();
      }
      stroke.dabs.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5]}});
    }
    strokes.push_back(std::move(stroke));
  }
  return strokes;
}

json strokesToJson(const std::vector<GroomStroke>& strokes) {
  json out = json::array();
  for (const GroomStroke& s : strokes) {
    json dabs = json::array();
    for (const GroomDab& d : s.dabs)
      dabs.push_back({tidy(d.position.x), tidy(d.position.y), tidy(d.position.z), tidy(d.motion.x), tidy(d.motion.y),
                      tidy(d.motion.z)});
    json stroke{{"brush", groomBrushName(s.brush)},
                {"radius", tidy(s.radius)},
                {"strength", tidy(s.strength)},
                {"mirror", s.mirror},
                {"dabs", dabs}};
    if (isPaintBrush(s.brush)) stroke["value"] = tidy(s.value);
    out.push_back(std::move(stroke));
  }
  return out;
}

glm::vec3 color(const JsonFields& f, std::string_view key, glm::vec3 fallback) {
  const glm::vec3 c = f.vec3(key, fallback, 1.0f);
  if (c.x < 0.0f || c.y < 0.0f || c.z < 0.0f) f.fail(key, "must hold numbers between 0 and 1");
  return c;
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

HairShadingParams hairShadingFromJson(const json& j, const HairShadingParams& base, const std::string& path) {
  const JsonFields f(j, path);
  HairShadingParams s = base;
  s.model = hairShadingModelFromName(f.string("model", hairShadingModelName(s.model)));
  s.melanin = f.nonNegative("melanin", s.melanin, 50.0);
  s.pheomelanin = f.nonNegative("pheomelanin", s.pheomelanin, 50.0);
  s.roughness = f.number("roughness", s.roughness, 0.05, 1.0);
  return s;
}

json toJson(const HairShadingParams& s) {
  return {{"model", hairShadingModelName(s.model)},
          {"melanin", tidy(s.melanin)},
          {"pheomelanin", tidy(s.pheomelanin)},
          {"roughness", tidy(s.roughness)}};
}

HairDynamicsParams hairDynamicsFromJson(const json& j, const HairDynamicsParams& base, const std::string& path) {
  const JsonFields f(j, path);
  f.allowOnly({"volume", "friction", "adaptive_wisps"});
  HairDynamicsParams d = base;
  d.volume = f.number("volume", d.volume, 0.0, 1.0);
  d.friction = f.number("friction", d.friction, 0.0, 1.0);
  d.adaptiveWisps = f.boolean("adaptive_wisps", d.adaptiveWisps);
  return d;
}

json toJson(const HairDynamicsParams& d) {
  json out = {{"volume", tidy(d.volume)}, {"friction", tidy(d.friction)}};
  if (d.adaptiveWisps) out["adaptive_wisps"] = true;
  return out;
}

HairStyle hairStyleFromJson(const json& j, const std::string& path) {
  if (j.is_string()) {
    try {
      return builtinHairStyle(j.get<std::string>());
    } catch (const Error& e) {
      throw Error(path + ": " + e.what());
    }
  }
  if (!j.is_object()) throw Error(path + ": must be a built-in style name or an object");
  const JsonFields f(j, path);
  HairStyle s = f.has("preset") ? hairStyleFromJson(f.raw("preset"), f.pathOf("preset")) : HairStyle{};
  s.name = f.string("name", s.name);
  readPrimitives(f, s.primitives);
  s.scalpOutflow = f.number("scalp_outflow", s.scalpOutflow, -1.0e3, 1.0e3);
  s.noiseAmplitude = f.nonNegative("noise_amplitude", s.noiseAmplitude, 100.0);
  s.noiseScale = f.positive("noise_scale", s.noiseScale, kMaxDistance);
  s.density = f.nonNegative("density", s.density, 10000.0);
  s.maxStrands = int(f.integer("max_strands", s.maxStrands, 0, kMaxStrands));
  s.guideCount = int(f.integer("guides", s.guideCount, 1, kMaxStrands));
  s.length = f.positive("length", s.length, 10.0);
  s.lengthVariation = f.number("length_variation", s.lengthVariation, 0.0, 1.0);
  if (f.has("length_map")) {
    s.lengthMap.clear();
    for (size_t i = 0; i < f.array("length_map").size(); ++i) {
      const JsonFields e = f.element("length_map", i);
      LengthPoint p;
      p.position = e.vec3("position", p.position, kMaxDistance);
      p.scale = e.nonNegative("scale", p.scale, 100.0);
      p.radius = e.positive("radius", p.radius, kMaxDistance);
      s.lengthMap.push_back(p);
    }
  }
  s.pointsPerStrand = int(f.integer("points_per_strand", s.pointsPerStrand, 2, 1024));
  s.strandNoise = f.nonNegative("strand_noise", s.strandNoise, 10.0);
  s.waveAmplitude = f.nonNegative("wave_amplitude", s.waveAmplitude, 10.0);
  s.waveLength = f.positive("wave_length", s.waveLength, kMaxDistance);
  s.curlRadius = f.nonNegative("curl_radius", s.curlRadius, 10.0);
  s.curlLength = f.positive("curl_length", s.curlLength, kMaxDistance);
  s.clumping = f.number("clumping", s.clumping, 0.0, 1.0);
  s.clumpShape = f.number("clump_shape", s.clumpShape, 0.01, 100.0);
  s.frizz = f.nonNegative("frizz", s.frizz, 10.0);
  s.frizzFrequency = f.nonNegative("frizz_frequency", s.frizzFrequency, 1.0e5);
  s.rootColor = color(f, "root_color", s.rootColor);
  s.tipColor = color(f, "tip_color", s.tipColor);
  s.seed = uint32_t(f.integer("seed", s.seed, 0, 4294967295LL));
  if (f.has("shading")) s.shading = hairShadingFromJson(f.raw("shading"), s.shading, f.pathOf("shading"));
  if (f.has("dynamics")) s.dynamics = hairDynamicsFromJson(f.raw("dynamics"), s.dynamics, f.pathOf("dynamics"));
  if (f.has("strokes")) s.strokes = readStrokes(f);
  return s;
}

ScalpRegion scalpRegionFromJson(const json& j, const std::string& path) {
  ScalpRegion r;
  if (j.is_null()) return r;
  const JsonFields f(j, path);
  const std::string kind = f.string("kind", "tagged");
  if (kind == "tagged") {
    r.kind = ScalpRegion::Kind::Tagged;
  } else if (kind == "bone_cone") {
    r.kind = ScalpRegion::Kind::BoneCone;
    r.bone = f.string("bone", r.bone);
    r.axis = f.vec3("axis", r.axis, 1.0e3f);
    r.angleDegrees = f.number("angle", r.angleDegrees, 0.0, 180.0);
    if (glm::length(r.axis) <= 0.0f) f.fail("axis", "must not be zero");
  } else if (kind == "faces") {
    r.kind = ScalpRegion::Kind::Faces;
    r.bone = f.string("bone", r.bone);  // the head bone the body proxy follows
    r.mesh = int(f.integer("mesh", r.mesh, 0, 1 << 20));
    const json& faces = f.array("faces");
    r.faces.clear();
    r.faces.reserve(faces.size());
    for (size_t i = 0; i < faces.size(); ++i) {
      if (!faces[i].is_number_unsigned() || faces[i].get<unsigned long long>() > 0x7fffffffULL)
        f.fail("faces", "must hold face indices (whole numbers from 0)");
      r.faces.push_back(faces[i].get<uint32_t>());
    }
  } else {
    f.fail("kind", "unknown scalp kind '" + kind + "' (tagged, bone_cone or faces)");
  }
  return r;
}

HairSection hairSectionFromJson(const json& j, const std::string& path) {
  HairSection section;
  if (j.is_null()) return section;
  const JsonFields f(j, path);
  if (f.has("style")) {
    const json& style = f.raw("style");
    section.style = hairStyleFromJson(style, f.pathOf("style"));
    section.fitToHead = style.is_string() || style.contains("preset");
  }
  if (f.has("scalp")) {
    section.scalp = scalpRegionFromJson(f.raw("scalp"), f.pathOf("scalp"));
    section.scalpGiven = true;
  }
  section.strands = size_t(f.integer("strands", 0, 0, kMaxStrands));
  if (f.has("shading"))
    section.style.shading = hairShadingFromJson(f.raw("shading"), section.style.shading, f.pathOf("shading"));
  return section;
}

json toJson(const HairStyle& s) {
  json streams = json::array(), sources = json::array(), vortices = json::array(), lengthMap = json::array();
  for (const UniformStream& e : s.primitives.streams)
    streams.push_back({{"direction", vec(e.direction)}, {"strength", tidy(e.strength)}});
  for (const PointSource& e : s.primitives.sources)
    sources.push_back({{"position", vec(e.position)}, {"strength", tidy(e.strength)}, {"radius", tidy(e.radius)}});
  for (const Vortex& e : s.primitives.vortices)
    vortices.push_back({{"position", vec(e.position)},
                        {"axis", vec(e.axis)},
                        {"strength", tidy(e.strength)},
                        {"radius", tidy(e.radius)}});
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
  if (s.dynamics != HairDynamicsParams{}) out["dynamics"] = toJson(s.dynamics);
  if (!s.strokes.empty()) out["strokes"] = strokesToJson(s.strokes);
  return out;
}

json toJson(const ScalpRegion& r) {
  switch (r.kind) {
    case ScalpRegion::Kind::BoneCone:
      return {{"kind", "bone_cone"}, {"bone", r.bone}, {"axis", vec(r.axis)}, {"angle", tidy(r.angleDegrees)}};
    case ScalpRegion::Kind::Faces:
      return {{"kind", "faces"}, {"bone", r.bone}, {"mesh", r.mesh}, {"faces", r.faces}};
    case ScalpRegion::Kind::Tagged:
    default:
      return {{"kind", "tagged"}};
  }
}

json toJson(const HairSection& section) {
  return {{"style", toJson(section.style)}, {"scalp", toJson(section.scalp)}, {"strands", section.strands}};
}

}  // namespace mq
