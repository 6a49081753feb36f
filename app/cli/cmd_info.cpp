// mannequin-cli info FILE [--json]: what a character file holds.
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/command.h"
#include "core/scene/open_scene.h"
#include "core/util/error.h"

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
  args.allowOnly({"--json", "--scale"});
  if (args.positional().size() != 1) throw Error("info needs exactly one FILE");
  LoadedScene scene = openScene(args.positional()[0]);
  printMotionMatch(scene);
  applyScaleOption(args, scene);
  for (const std::string& warning : loadNotices(scene)) std::cerr << "warning: " << warning << "\n";
  if (args.has("--json"))
    std::cout << std::setw(2) << describe(scene.character) << "\n";
  else
    printText(scene.character, std::cout);
  return 0;
}

static Registration reg({"info", "FILE [--json] [--scale S]",
                         "meshes (vertices, triangles), bones (name, parent), max influences, materials, clips (name, duration)",
                         runInfo});

}  // namespace
}  // namespace mq::cli
