#include "core/scene/scene_document.h"

#include <cmath>
#include <filesystem>

#include "core/io/json_fields.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace mq {
namespace {

constexpr const char* kFormatName = "mannequin-scene";

using json = nlohmann::json;

glm::vec3 readVec3(const json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3) throw Error(what + " must be an array of 3 numbers");
  glm::vec3 v;
  for (int i = 0; i < 3; ++i) {
    if (!j[i].is_number()) throw Error(what + " must be an array of 3 numbers");
    v[i] = j[i].get<float>();
    if (!std::isfinite(v[i])) throw Error(what + " is not finite");
  }
  return v;
}

glm::quat readQuat(const json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 4) throw Error(what + " must be a quaternion [x, y, z, w]");
  float q[4];
  for (int i = 0; i < 4; ++i) {
    if (!j[i].is_number()) throw Error(what + " must be a quaternion [x, y, z, w]");
    q[i] = j[i].get<float>();
    if (!std::isfinite(q[i])) throw Error(what + " is not finite");
  }
  const glm::quat r(q[3], q[0], q[1], q[2]);
  const float len = glm::length(r);
  if (len < 1e-6f) throw Error(what + " is a zero quaternion");
  return r / len;
}

std::string readString(const json& object, const char* key, const std::string& fallback = "") {
  if (!object.contains(key) || object[key].is_null()) return fallback;
  if (!object[key].is_string()) throw Error(std::string("\"") + key + "\" must be a string");
  return object[key].get<std::string>();
}

SceneDocument fromJson(const json& root) {
  if (!root.is_object()) throw Error("not a Mannequin scene document (the top level is not a JSON object)");
  if (root.value("format", std::string()) != kFormatName)
    throw Error(std::string("not a Mannequin scene document (no \"format\": \"") + kFormatName + "\")");
  if (!root.contains("version") || !root["version"].is_number_integer())
    throw Error("scene document has no integer \"version\"");
  const int version = root["version"].get<int>();
  if (version > SceneDocument::kFormatVersion)
    throw Error("written by a newer version of Mannequin (format version " + std::to_string(version) +
                ", this build reads up to " + std::to_string(SceneDocument::kFormatVersion) + ")");
  if (version < 1) throw Error("invalid format version " + std::to_string(version));

  SceneDocument doc;
  doc.character =
      root.contains("character") && root["character"].is_null() ? "" : readString(root, "character", "default");
  if (root.contains("motion") && !root["motion"].is_null()) {
    const json& m = root["motion"];
    if (!m.is_object()) throw Error("\"motion\" must be an object with a \"file\"");
    doc.motionFile = readString(m, "file");
    doc.motionMapFile = readString(m, "map");
    if (m.contains("inPlace")) {
      if (!m["inPlace"].is_boolean()) throw Error("\"motion\".\"inPlace\" must be true or false");
      doc.motionInPlace = m["inPlace"].get<bool>();
    }
  }
  if (root.contains("animation")) {
    const json& a = root["animation"];
    if (!a.is_object()) throw Error("\"animation\" must be an object");
    if (a.contains("clip"))
      doc.clip = a["clip"].is_number_integer() ? std::to_string(a["clip"].get<int>()) : readString(a, "clip");
    if (a.contains("time")) {
      if (!a["time"].is_number()) throw Error("\"animation.time\" must be a number");
      doc.time = a["time"].get<float>();
      if (!std::isfinite(doc.time)) throw Error("\"animation.time\" is not finite");
    }
  }
  if (root.contains("pose")) {
    if (!root["pose"].is_object()) throw Error("\"pose\" must map bone names to quaternions");
    for (const auto& [bone, q] : root["pose"].items())
      doc.poseRotations[bone] = readQuat(q, "pose of bone '" + bone + "'");
  }
  if (root.contains("view")) {
    const json& v = root["view"];
    if (!v.is_object()) throw Error("\"view\" must be an object");
    doc.view.showSkeleton = v.value("skeleton", false);
    for (const auto& [key, flag] : {std::pair<const char*, bool*>{"weights", &doc.view.showWeights},
                                    std::pair<const char*, bool*>{"cones", &doc.view.showCones}})
      if (v.contains(key)) {
        if (!v[key].is_boolean()) throw Error(std::string("view.") + key + " must be true or false");
        *flag = v[key].get<bool>();
      }
    doc.view.look = readString(v, "look", "auto");
    if (doc.view.look != "auto" && doc.view.look != "skin" && doc.view.look != "mannequin" && doc.view.look != "plain")
      throw Error("view.look: unknown look '" + doc.view.look + "' (expected auto, skin, mannequin or plain)");
    if (v.contains("camera")) {
      doc.view.hasCamera = true;
      doc.view.cameraPosition = readVec3(v["camera"].value("position", json()), "view.camera.position");
      doc.view.cameraFocus = readVec3(v["camera"].value("focus", json()), "view.camera.focus");
    }
  }
  if (root.contains("skinning")) {
    const json& k = root["skinning"];
    if (!k.is_object()) throw Error("\"skinning\" must be an object");
    const std::string method = readString(k, "method", "lbs");
    const auto parsed = parseSkinningMethod(method);
    if (!parsed)
      throw Error("skinning.method: unknown method '" + method + "' (expected " + skinningMethodChoices() + ")");
    doc.skinning = *parsed;
    if (k.contains("helper_bones")) {
      if (!k["helper_bones"].is_boolean()) throw Error("skinning.helper_bones must be true or false");
      doc.helperBones = k["helper_bones"].get<bool>();
    }
    if (k.contains("weights")) doc.weights = weightSettingsFromJson(k["weights"], "skinning.weights");
  }
  if (root.contains("scale")) {
    if (!root["scale"].is_number()) throw Error("\"scale\" must be a number");
    doc.scale = root["scale"].get<float>();
    if (!std::isfinite(doc.scale) || doc.scale <= 0.0f || doc.scale > 1e4f)
      throw Error("\"scale\" must be positive and at most 10000");
  }
  if (root.contains("auto_rig")) {
    if (!root["auto_rig"].is_boolean()) throw Error("\"auto_rig\" must be true or false");
    doc.autoRig = root["auto_rig"].get<bool>();
  }
  if (root.contains("materials")) {
    if (!root["materials"].is_object()) throw Error("\"materials\" must map material names to changes");
    for (const auto& [name, changes] : root["materials"].items())
      doc.materials[name] = MaterialOverride::fromJson(changes, "materials." + name);
  }
  for (auto [key, section] : {std::pair{"hair", &doc.hair},
                              {"garments", &doc.garments},
                              {"cloth", &doc.cloth},
                              {"colliders", &doc.colliders}})
    if (root.contains(key)) *section = root[key];
  return doc;
}

json array3(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

}  // namespace

bool isSceneDocumentPath(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".mqscene" || ext == ".json";
}

SceneDocument parseSceneDocument(const std::string& text, const std::string& pathForErrors) {
  const json root = parseJsonText(text, pathForErrors);
  try {
    return fromJson(root);
  } catch (const json::exception& e) {
    throw FileError(pathForErrors, "bad scene document: " + jsonProblem(e));
  } catch (const Error& e) {
    throw FileError(pathForErrors, e.what());
  }
}

SceneDocument loadSceneDocument(const std::string& path) { return parseSceneDocument(readFileText(path), path); }

json toJson(const SceneDocument& doc) {
  json root;
  root["format"] = kFormatName;
  root["version"] = SceneDocument::kFormatVersion;
  root["character"] = doc.hasCharacter() ? json(doc.character) : json();
  if (!doc.motionFile.empty()) {
    root["motion"] = {{"file", doc.motionFile}};
    if (!doc.motionMapFile.empty()) root["motion"]["map"] = doc.motionMapFile;
    if (doc.motionInPlace) root["motion"]["inPlace"] = true;
  }
  root["animation"] = {{"clip", doc.clip}, {"time", doc.time}};
  json pose = json::object();
  for (const auto& [bone, q] : doc.poseRotations) pose[bone] = json::array({q.x, q.y, q.z, q.w});
  root["pose"] = pose;
  root["view"] = {{"skeleton", doc.view.showSkeleton}, {"look", doc.view.look}};
  if (doc.view.showWeights) root["view"]["weights"] = true;
  if (doc.view.showCones) root["view"]["cones"] = true;
  if (doc.view.hasCamera)
    root["view"]["camera"] = {{"position", array3(doc.view.cameraPosition)}, {"focus", array3(doc.view.cameraFocus)}};
  root["skinning"] = {{"method", skinningMethodName(doc.skinning)}};
  if (doc.helperBones) root["skinning"]["helper_bones"] = true;
  if (doc.weights.active()) root["skinning"]["weights"] = toJson(doc.weights);
  if (doc.scale != 1.0f) root["scale"] = doc.scale;
  if (doc.autoRig) root["auto_rig"] = true;
  json materials = json::object();
  for (const auto& [name, changes] : doc.materials)
    if (!changes.empty()) materials[name] = changes.toJson();
  if (!materials.empty()) root["materials"] = materials;
  if (!doc.hair.is_null()) root["hair"] = doc.hair;
  if (!doc.garments.is_null()) root["garments"] = doc.garments;
  if (!doc.cloth.is_null()) root["cloth"] = doc.cloth;
  if (!doc.colliders.is_null()) root["colliders"] = doc.colliders;
  return root;
}

void saveSceneDocument(const SceneDocument& document, const std::string& path) {
  const std::string text = toJson(document).dump(2, ' ', false, json::error_handler_t::replace) + "\n";
  writeFileAtomically(path, [&](std::ostream& out) { out << text; });
}

std::string resolveDocumentPath(const std::string& documentPath, const std::string& stored) {
  const std::filesystem::path p(stored);
  if (p.is_absolute() || documentPath.empty()) return stored;
  return (std::filesystem::path(documentPath).parent_path() / p).lexically_normal().string();
}

void rebaseDocumentPaths(SceneDocument& document, const std::string& fromPath, const std::string& toPath) {
  const std::filesystem::path folder = std::filesystem::absolute(toPath).parent_path();
  auto rebase = [&](std::string& stored) {
    if (stored.empty()) return;
    const std::filesystem::path file = std::filesystem::absolute(resolveDocumentPath(fromPath, stored));
    stored = file.lexically_normal().lexically_proximate(folder).string();
  };
  if (document.character != "default") rebase(document.character);
  rebase(document.motionFile);
  rebase(document.motionMapFile);
}

}  // namespace mq
