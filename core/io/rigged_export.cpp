#include "core/io/rigged_export.h"

#include <algorithm>
#include <cmath>

#include "core/io/file_bytes.h"
#include "core/io/gltf_writer.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace mq {
namespace {

using nlohmann::json;

// A bone's node transform: its fixed offset (non-bone nodes of the source
// file) folded into its local transform.
Trs nodeTransform(const Bone& bone, const Trs& local) {
  if (bone.parentFromOffset == glm::mat4(1.0f)) return local;
  return Trs::fromMatrix(bone.parentFromOffset * local.matrix());
}

json trsJson(const Trs& t) {
  return {{"translation", {t.translation.x, t.translation.y, t.translation.z}},
          {"rotation", {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w}},
          {"scale", {t.scale.x, t.scale.y, t.scale.z}}};
}

void addSkeleton(GltfWriter& writer, const Skeleton& skeleton) {
  json& gltf = writer.json();
  for (int b = 0; b < skeleton.boneCount(); ++b) {
    json node = trsJson(nodeTransform(skeleton.bone(b), skeleton.bone(b).rest));
    node["name"] = skeleton.bone(b).name;
    const std::vector<int> children = skeleton.children(b);
    if (!children.empty()) node["children"] = children;
    gltf["nodes"].push_back(node);
    if (skeleton.bone(b).parent < 0) gltf["scenes"][0]["nodes"].push_back(b);
  }
}

// JOINTS_0 / WEIGHTS_0: the four heaviest influences of each vertex. An
// unused slot names joint 0: glTF wants a zero weight on a zero joint index.
void addSkinAttributes(GltfWriter& writer, const SkinBinding& skin, size_t vertices, json& attributes) {
  SkinBinding four = skin;
  four.limitInfluences(4);
  const int k = four.influencesPerVertex;
  std::vector<uint16_t> joints(4 * vertices, 0);
  std::vector<float> weights(4 * vertices, 0.0f);
  for (size_t v = 0; v < vertices; ++v)
    for (int i = 0; i < k; ++i) {
      const float weight = four.weights[v * k + i];
      joints[4 * v + i] = weight > 0.0f ? four.joints[v * k + i] : 0;
      weights[4 * v + i] = weight;
    }
  attributes["JOINTS_0"] =
      writer.addAccessor(joints.data(), vertices, "VEC4", 4, GltfWriter::kUnsignedShort, GltfWriter::kArrayBuffer);
  attributes["WEIGHTS_0"] =
      writer.addAccessor(weights.data(), vertices, "VEC4", 4, GltfWriter::kFloat, GltfWriter::kArrayBuffer);
}

void addMesh(GltfWriter& writer, const Mesh& mesh, int boneCount) {
  json& gltf = writer.json();
  const size_t n = mesh.vertexCount();
  json attributes;
  const int position =
      writer.addAccessor(mesh.positions.data(), n, "VEC3", 3, GltfWriter::kFloat, GltfWriter::kArrayBuffer);
  const Aabb box = boundsOf(mesh.positions);
  gltf["accessors"][position]["min"] = {box.min.x, box.min.y, box.min.z};
  gltf["accessors"][position]["max"] = {box.max.x, box.max.y, box.max.z};
  attributes["POSITION"] = position;
  if (mesh.normals.size() == 3 * n)
    attributes["NORMAL"] =
        writer.addAccessor(mesh.normals.data(), n, "VEC3", 3, GltfWriter::kFloat, GltfWriter::kArrayBuffer);
  if (mesh.uvs.size() == 2 * n)
    attributes["TEXCOORD_0"] =
        writer.addAccessor(mesh.uvs.data(), n, "VEC2", 2, GltfWriter::kFloat, GltfWriter::kArrayBuffer);
  const bool skinned = !mesh.skin.empty();
  if (skinned) addSkinAttributes(writer, mesh.skin, n, attributes);
  json primitive = {{"attributes", attributes}, {"mode", 4}};
  if (!mesh.triangles.empty())
    primitive["indices"] = writer.addAccessor(mesh.triangles.data(), mesh.triangles.size(), "SCALAR", 1,
                                              GltfWriter::kUnsignedInt, GltfWriter::kElementArrayBuffer);
  const int meshIndex = int(gltf["meshes"].size());
  gltf["meshes"].push_back({{"name", mesh.name}, {"primitives", {primitive}}});

  json node = {{"name", mesh.name}, {"mesh", meshIndex}};
  const int nodeIndex = int(gltf["nodes"].size());
  if (skinned) {
    std::vector<float> inverseBind;
    for (const glm::mat4& m : mesh.skin.inverseBind)
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) inverseBind.push_back(m[c][r]);  // column-major, as glTF
    const int matrices =
        writer.addAccessor(inverseBind.data(), mesh.skin.inverseBind.size(), "MAT4", 16, GltfWriter::kFloat);
    gltf["skins"].push_back({{"joints", mesh.skin.jointBones}, {"inverseBindMatrices", matrices}});
    node["skin"] = gltf["skins"].size() - 1;
    gltf["scenes"][0]["nodes"].push_back(nodeIndex);
  } else {
    const glm::mat4& m = mesh.boneFromMesh;
    if (m != glm::mat4(1.0f)) node["matrix"] = std::vector<float>(&m[0][0], &m[0][0] + 16);
    if (mesh.attachBone >= 0 && mesh.attachBone < boneCount)
      gltf["nodes"][mesh.attachBone]["children"].push_back(nodeIndex);
    else
      gltf["scenes"][0]["nodes"].push_back(nodeIndex);
  }
  gltf["nodes"].push_back(node);
}

// One animation per clip: every bone's node transform sampled at fps.
void addClip(GltfWriter& writer, const Character& character, int clipIndex, float fps) {
  const Clip& clip = character.clips[clipIndex];
  const int frames = std::max(1, int(std::ceil(clip.duration() * fps - 1e-4f))) + 1;
  std::vector<float> times(frames);
  for (int f = 0; f < frames; ++f) times[f] = std::min(clip.startTime() + f / fps, clip.endTime());
  const int bones = character.skeleton.boneCount();
  std::vector<std::vector<float>> translations(bones), rotations(bones), scales(bones);
  for (float t : times) {
    const Pose pose = samplePose(character, clipIndex, t);
    for (int b = 0; b < bones; ++b) {
      const Trs node = nodeTransform(character.skeleton.bone(b), pose[b]);
      translations[b].insert(translations[b].end(), {node.translation.x, node.translation.y, node.translation.z});
      glm::quat q = node.rotation;
      // Keep consecutive keys in one hemisphere so linear interpolation takes the short way.
      const size_t keys = rotations[b].size() / 4;
      if (keys > 0) {
        const float* last = &rotations[b][4 * (keys - 1)];
        if (q.x * last[0] + q.y * last[1] + q.z * last[2] + q.w * last[3] < 0.0f) q = -q;
      }
      rotations[b].insert(rotations[b].end(), {q.x, q.y, q.z, q.w});
      scales[b].insert(scales[b].end(), {node.scale.x, node.scale.y, node.scale.z});
    }
  }
  const int input = writer.addAccessor(times.data(), times.size(), "SCALAR", 1, GltfWriter::kFloat);
  json& gltf = writer.json();
  gltf["accessors"][input]["min"] = {times.front()};
  gltf["accessors"][input]["max"] = {times.back()};
  json samplers = json::array(), channels = json::array();
  auto addChannel = [&](int bone, const char* path, const std::vector<float>& values, const char* type, int size) {
    const int output = writer.addAccessor(values.data(), values.size() / size, type, size, GltfWriter::kFloat);
    samplers.push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
    channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", bone}, {"path", path}}}});
  };
  for (int b = 0; b < bones; ++b) {
    addChannel(b, "translation", translations[b], "VEC3", 3);
    addChannel(b, "rotation", rotations[b], "VEC4", 4);
    addChannel(b, "scale", scales[b], "VEC3", 3);
  }
  gltf["animations"].push_back({{"name", clip.name}, {"samplers", samplers}, {"channels", channels}});
}

}  // namespace

bool isRiggedExportPath(const std::string& path) {
  const std::string ext = fileExtension(path);
  return ext == "gltf" || ext == "glb";
}

void exportRiggedCharacter(const Character& character, const std::string& path, float fps) {
  if (!isRiggedExportPath(path)) throw FileError(path, "a rigged export is glTF: use .gltf or .glb");
  if (!(fps > 0.0f && fps <= 1000.0f)) throw FileError(path, "the animation rate must be between 0 and 1000 fps");
  GltfWriter writer("mannequin rigged export");
  addSkeleton(writer, character.skeleton);
  for (const Mesh& mesh : character.meshes) addMesh(writer, mesh, character.skeleton.boneCount());
  for (int c = 0; c < int(character.clips.size()); ++c) addClip(writer, character, c, fps);
  const bool binary = fileExtension(path) == "glb";
  writeFileAtomically(
      path, [&](std::ostream& out) { binary ? writer.writeGlb(out) : writer.writeGltf(out); }, binary);
}

}  // namespace mq
