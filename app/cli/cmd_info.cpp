// mannequin-cli info FILE [--json]: what a character file holds.
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/scene/open_scene.h"
#include "core/skinning/weight_regeneration.h"
#include "core/util/error.h"
#include "sim/cloth/bake_cache.h"

namespace mq::cli {
namespace {

// A material's factors and the images its textures sample.
nlohmann::json describe(const Material& m, const Character& c) {
  nlohmann::json textures = nlohmann::json::object();
  for (const TextureSlot& slot : m.textureSlots())
    if (slot.ref->present() && slot.ref->image < static_cast<int>(c.images.size()))
      textures[slot.key] = c.images[slot.ref->image].name;
  const glm::vec4& base = m.baseColorFactor;
  return {{"name", m.name},
          {"base_color", {base.x, base.y, base.z, base.w}},
          {"metallic", m.metallicFactor},
          {"roughness", m.roughnessFactor},
          {"alpha_mode", alphaModeName(m.alphaMode)},
          {"double_sided", m.doubleSided},
          {"skin", m.skin},
          {"textures", textures}};
}

nlohmann::json describe(const Character& c) {
  nlohmann::json j;
  j["name"] = c.name;
  j["source"] = c.sourcePath;
  j["meshes"] = nlohmann::json::array();
  for (const Mesh& m : c.meshes)
    j["meshes"].push_back({{"name", m.name},
                           {"vertices", m.vertexCount()},
                           {"triangles", m.triangleCount()},
                           {"skinned", !m.skin.empty()},
                           {"morph_targets", m.morphTargets.size()}});
  j["bones"] = nlohmann::json::array();
  const std::vector<glm::mat4> rest = c.skeleton.worldTransforms(c.skeleton.restPose());
  for (int b = 0; b < c.skeleton.boneCount(); ++b) {
    const Bone& bone = c.skeleton.bone(b);
    const glm::vec3 head(rest[b][3]);
    j["bones"].push_back({{"name", bone.name}, {"parent", bone.parent}, {"head", {head.x, head.y, head.z}}});
  }
  j["materials"] = nlohmann::json::array();
  for (const Material& m : c.materials) j["materials"].push_back(describe(m, c));
  j["skinning"] = skinningMethodName(c.skinning);
  j["helper_bones"] = c.helperBones.size();
  j["vertices"] = c.vertexCount();
  j["triangles"] = c.triangleCount();
  j["max_influences"] = c.maxInfluences();
  j["clips"] = nlohmann::json::array();
  for (const Clip& clip : c.clips)
    j["clips"].push_back(
        {{"name", clip.name}, {"duration", clip.duration()}, {"start", clip.startTime()}, {"end", clip.endTime()}});
  return j;
}

// The garment bake the editor saved beside a scene document, if any: what it
// holds, or why it cannot be read (the editor then reports it and bakes anew).
std::optional<nlohmann::json> describeSavedBake(const std::string& documentPath) {
  const std::string path = cloth::bakeCachePath(documentPath);
  if (!std::filesystem::exists(path)) return std::nullopt;
  nlohmann::json j = {{"file", path}};
  try {
    const cloth::BakeCache cache = cloth::readBakeCache(path);
    j["clip"] = cache.clip;
    j["start"] = cache.start;
    j["garments"] = cache.garments.size();
    j["frames"] = cache.garments.empty() ? 0 : cache.garments[0].frameCount();
    j["fps"] = cache.garments.empty() ? 0.0f : cache.garments[0].fps();
  } catch (const std::exception& e) {
    j["error"] = e.what();
  }
  return j;
}

void printSavedBake(const nlohmann::json& bake, std::ostream& out) {
  if (bake.contains("error")) {
    out << "  garment bake: unreadable (" << bake["error"].get<std::string>() << ")\n";
    return;
  }
  out << "  garment bake: " << bake["frames"] << " frames at " << bake["fps"] << " fps of clip [" << bake["clip"]
      << "] from " << bake["start"] << " s, " << bake["garments"] << " garment(s), in "
      << bake["file"].get<std::string>() << "\n";
}

void printBoneTree(const Skeleton& skeleton, int bone, int depth, std::ostream& out) {
  out << "    " << std::string(2 * depth, ' ') << skeleton.bone(bone).name << "\n";
  for (int child : skeleton.children(bone)) printBoneTree(skeleton, child, depth + 1, out);
}

void printText(const Character& c, std::ostream& out) {
  out << c.name << " (" << c.sourcePath << ")\n";
  out << "  meshes: " << c.meshes.size() << ", " << c.vertexCount() << " vertices, " << c.triangleCount()
      << " triangles\n";
  for (const Mesh& m : c.meshes)
    out << "    " << m.name << ": " << m.vertexCount() << " vertices, " << m.triangleCount() << " triangles"
        << (m.skin.empty() ? "" : ", skinned") << "\n";
  out << "  bones: " << c.skeleton.boneCount() << ", max influences per vertex: " << c.maxInfluences() << "\n";
  for (int b = 0; b < c.skeleton.boneCount(); ++b)
    if (c.skeleton.bone(b).parent < 0) printBoneTree(c.skeleton, b, 0, out);
  out << "  materials: " << c.materials.size() << "\n";
  for (const Material& m : c.materials)
    out << "    " << m.name << (m.textured() ? ", textured" : "") << (m.skin ? ", skin" : "")
        << (m.alphaMode != AlphaMode::Opaque ? std::string(", alpha ") + alphaModeName(m.alphaMode) : "") << "\n";
  out << "  clips: " << c.clips.size() << "\n";
  for (size_t i = 0; i < c.clips.size(); ++i)
    out << "    [" << i << "] " << c.clips[i].name << ": " << c.clips[i].duration() << " s (keys "
        << c.clips[i].startTime() << " .. " << c.clips[i].endTime() << " s)\n";
}

int runInfo(const std::vector<std::string>& argv) {
  const Args args(argv);
  args.allowOnly({"--json", "--scale", "--auto-rig"});
  if (args.positional().size() != 1) throw Error("info needs exactly one FILE");
  LoadedScene scene = openScene(args.positional()[0]);
  printMotionMatch(scene);
  applyCharacterOptions(args, scene);
  for (const std::string& warning : loadNotices(scene)) std::cerr << "warning: " << warning << "\n";
  const std::optional<nlohmann::json> bake =
      scene.documentPath.empty() ? std::nullopt : describeSavedBake(scene.documentPath);
  if (args.has("--json")) {
    nlohmann::json j = describe(scene.character);
    // The file's weights, or how the scene rebuilt them.
    j["weights"] = scene.document.weights.active() ? toJson(scene.document.weights) : nlohmann::json("file");
    if (bake) j["garment_bake"] = *bake;
    std::cout << std::setw(2) << j << "\n";
  } else {
    printText(scene.character, std::cout);
    if (bake) printSavedBake(*bake, std::cout);
  }
  return 0;
}

static Registration reg(
    {"info", "FILE [--json] [--scale S] [--auto-rig]",
     "meshes (vertices, triangles), bones (name, parent), max influences, materials, clips (name, duration),\n"
     "and the garment bake the editor saved beside a scene document (NAME.mqbake)",
     runInfo});

}  // namespace
}  // namespace mq::cli
