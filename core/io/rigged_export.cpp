#include "core/io/rigged_export.h"

#include <algorithm>
#include <cmath>

#include "core/io/file_bytes.h"
#include "core/io/gltf_material_export.h"
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

int addPositionAccessor(GltfWriter& writer, const std::vector<float>& positions) {
  const int accessor = writer.addAccessor(positions.data(), positions.size() / 3, "VEC3", 3, GltfWriter::kFloat,
                                          GltfWriter::kArrayBuffer);
  const Aabb box = boundsOf(positions);  // the spec requires POSITION min/max, targets' too
  writer.json()["accessors"][accessor]["min"] = {box.min.x, box.min.y, box.min.z};
  writer.json()["accessors"][accessor]["max"] = {box.max.x, box.max.y, box.max.z};
  return accessor;
}

// The mesh's morph targets on each of its primitives, their default weights
// and their names (extras.targetNames, which Blender and three.js read).
void addMorphTargets(GltfWriter& writer, const Mesh& mesh, json& primitives, json& gltfMesh) {
  if (mesh.morphTargets.empty()) return;
  const size_t n = mesh.vertexCount();
  json targets = json::array(), names = json::array();
  for (const MorphTarget& target : mesh.morphTargets) {
    json attributes = {{"POSITION", addPositionAccessor(writer, target.positionDeltas)}};
    if (target.normalDeltas.size() == 3 * n)
      attributes["NORMAL"] =
          writer.addAccessor(target.normalDeltas.data(), n, "VEC3", 3, GltfWriter::kFloat, GltfWriter::kArrayBuffer);
    targets.push_back(attributes);
    names.push_back(target.name);
  }
  for (json& primitive : primitives) primitive["targets"] = targets;
  std::vector<float> weights = mesh.morphWeights;
  weights.resize(mesh.morphTargets.size(), 0.0f);
  gltfMesh["weights"] = weights;
  gltfMesh["extras"]["targetNames"] = names;
}

// Returns the index of the node that holds the mesh.
int addMesh(GltfWriter& writer, const Mesh& mesh, int boneCount, size_t materialCount) {
  json& gltf = writer.json();
  const size_t n = mesh.vertexCount();
  json attributes;
  attributes["POSITION"] = addPositionAccessor(writer, mesh.positions);
  if (mesh.normals.size() == 3 * n)
    attributes["NORMAL"] =
        writer.addAccessor(mesh.normals.data(), n, "VEC3", 3, GltfWriter::kFloat, GltfWriter::kArrayBuffer);
  if (mesh.uvs.size() == 2 * n)
    attributes["TEXCOORD_0"] =
        writer.addAccessor(mesh.uvs.data(), n, "VEC2", 2, GltfWriter::kFloat, GltfWriter::kArrayBuffer);
  const bool skinned = !mesh.skin.empty();
  if (skinned) addSkinAttributes(writer, mesh.skin, n, attributes);
  json primitives = gltfPrimitives(writer, mesh, attributes, materialCount);
  json gltfMesh = {{"name", mesh.name}};
  addMorphTargets(writer, mesh, primitives, gltfMesh);
  gltfMesh["primitives"] = primitives;
  const int meshIndex = int(gltf["meshes"].size());
  gltf["meshes"].push_back(gltfMesh);

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
  return nodeIndex;
}

// Sample times of an animation: on the clip's axis (to pose the character)
// and in the file (from 0 for a take).
struct Samples {
  std::vector<float> clipTimes, fileTimes;
};

Samples clipSamples(const Clip& clip, float fps) {
  const int frames = std::max(1, int(std::ceil(clip.duration() * fps - 1e-4f))) + 1;
  Samples s;
  for (int f = 0; f < frames; ++f) s.clipTimes.push_back(std::min(clip.startTime() + f / fps, clip.endTime()));
  s.fileTimes = s.clipTimes;
  return s;
}

Samples takeSamples(const ExportTake& take) {
  Samples s;
  for (int f = 0; f < take.frames; ++f) {
    s.clipTimes.push_back(take.start + f / take.fps);
    s.fileTimes.push_back(f / take.fps);
  }
  return s;
}

// One animation being written: its sample times and its channels.
class AnimationBuilder {
 public:
  AnimationBuilder(GltfWriter& writer, const std::vector<float>& times) : writer_(writer) {
    input_ = writer.addAccessor(times.data(), times.size(), "SCALAR", 1, GltfWriter::kFloat);
    writer.json()["accessors"][input_]["min"] = {times.front()};
    writer.json()["accessors"][input_]["max"] = {times.back()};
  }
  void addChannel(int node, const char* path, const std::vector<float>& values, const char* type, int size) {
    const int output = writer_.addAccessor(values.data(), values.size() / size, type, size, GltfWriter::kFloat);
    samplers_.push_back({{"input", input_}, {"output", output}, {"interpolation", "LINEAR"}});
    channels_.push_back({{"sampler", samplers_.size() - 1}, {"target", {{"node", node}, {"path", path}}}});
  }
  void finish(const std::string& name) {
    writer_.json()["animations"].push_back({{"name", name}, {"samplers", samplers_}, {"channels", channels_}});
  }

 private:
  GltfWriter& writer_;
  int input_ = -1;
  json samplers_ = json::array(), channels_ = json::array();
};

// Every bone's node transform at each sample of `clipIndex` (-1: the rest pose).
void addBoneChannels(AnimationBuilder& animation, const Character& character, int clipIndex,
                     const std::vector<float>& times, const PoseEdits* edits) {
  const int bones = character.skeleton.boneCount();
  std::vector<std::vector<float>> translations(bones), rotations(bones), scales(bones);
  for (float t : times) {
    const Pose pose = samplePose(character, clipIndex, t, edits);
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
  for (int b = 0; b < bones; ++b) {
    animation.addChannel(b, "translation", translations[b], "VEC3", 3);
    animation.addChannel(b, "rotation", rotations[b], "VEC4", 4);
    animation.addChannel(b, "scale", scales[b], "VEC3", 3);
  }
}

// The morph weights of the meshes the clip animates, at each sample.
void addMorphChannels(AnimationBuilder& animation, const Character& character, int clipIndex,
                      const std::vector<float>& times, const std::vector<int>& meshNodes) {
  if (clipIndex < 0) return;
  const Clip& clip = character.clips[clipIndex];
  for (const MorphChannel& channel : clip.morphChannels) {
    if (channel.mesh < 0 || channel.mesh >= int(character.meshes.size())) continue;
    const Mesh& mesh = character.meshes[channel.mesh];
    if (mesh.morphTargets.empty()) continue;
    std::vector<std::vector<float>> meshWeights(character.meshes.size());
    std::vector<float> values;  // samples x targets, as glTF lays out weights
    for (float t : times) {
      meshWeights[channel.mesh] = mesh.morphWeights;
      meshWeights[channel.mesh].resize(mesh.morphTargets.size(), 0.0f);
      clip.applyToMorphWeights(t, meshWeights);
      values.insert(values.end(), meshWeights[channel.mesh].begin(), meshWeights[channel.mesh].end());
    }
    animation.addChannel(meshNodes[channel.mesh], "weights", values, "SCALAR", 1);
  }
}

// A baked surface as a mesh in world space: frame 0 as its base, frame f as
// morph target f - 1; returns its node.
int addBakedSurface(GltfWriter& writer, const BakedSurface& surface) {
  json& gltf = writer.json();
  const std::vector<float>& base = surface.frames.front();
  const size_t n = base.size() / 3;
  const bool lines = surface.triangles.empty();
  json attributes = {{"POSITION", addPositionAccessor(writer, base)}};
  if (surface.colors.size() == base.size())
    attributes["COLOR_0"] =
        writer.addAccessor(surface.colors.data(), n, "VEC3", 3, GltfWriter::kFloat, GltfWriter::kArrayBuffer);
  std::vector<float> baseNormals;
  if (!lines) {
    computeVertexNormals(base, surface.triangles, baseNormals);
    attributes["NORMAL"] =
        writer.addAccessor(baseNormals.data(), n, "VEC3", 3, GltfWriter::kFloat, GltfWriter::kArrayBuffer);
  }
  json targets = json::array();
  std::vector<float> delta(base.size()), normals, normalDelta(base.size());
  for (size_t f = 1; f < surface.frames.size(); ++f) {
    for (size_t k = 0; k < base.size(); ++k) delta[k] = surface.frames[f][k] - base[k];
    json target = {{"POSITION", addPositionAccessor(writer, delta)}};
    if (!lines) {
      computeVertexNormals(surface.frames[f], surface.triangles, normals);
      for (size_t k = 0; k < base.size(); ++k) normalDelta[k] = normals[k] - baseNormals[k];
      target["NORMAL"] =
          writer.addAccessor(normalDelta.data(), n, "VEC3", 3, GltfWriter::kFloat, GltfWriter::kArrayBuffer);
    }
    targets.push_back(target);
  }
  const std::vector<uint32_t>& indices = lines ? surface.lines : surface.triangles;
  const glm::vec4& c = surface.color;
  gltf["materials"].push_back(
      {{"name", surface.name},
       {"pbrMetallicRoughness",
        {{"baseColorFactor", {c.x, c.y, c.z, c.w}}, {"metallicFactor", 0.0f}, {"roughnessFactor", 0.8f}}},
       {"doubleSided", true}});
  json primitive = {{"attributes", attributes},
                    {"mode", lines ? 1 : 4},
                    {"material", gltf["materials"].size() - 1},
                    {"indices", writer.addAccessor(indices.data(), indices.size(), "SCALAR", 1,
                                                   GltfWriter::kUnsignedInt, GltfWriter::kElementArrayBuffer)}};
  json mesh = {{"name", surface.name}, {"primitives", json::array()}};
  if (!targets.empty()) {
    primitive["targets"] = targets;
    mesh["weights"] = std::vector<float>(targets.size(), 0.0f);
  }
  mesh["primitives"].push_back(primitive);
  gltf["meshes"].push_back(mesh);
  const int node = int(gltf["nodes"].size());
  gltf["nodes"].push_back({{"name", surface.name}, {"mesh", gltf["meshes"].size() - 1}});
  gltf["scenes"][0]["nodes"].push_back(node);
  return node;
}

// Frame f shows morph target f - 1 alone (frame 0: the base); linear
// interpolation between two frames blends their two targets.
void addBakedChannel(AnimationBuilder& animation, int node, size_t frames) {
  if (frames < 2) return;
  const size_t targets = frames - 1;
  std::vector<float> values(frames * targets, 0.0f);
  for (size_t f = 1; f < frames; ++f) values[f * targets + (f - 1)] = 1.0f;
  animation.addChannel(node, "weights", values, "SCALAR", 1);
}

void checkBaked(const std::string& path, const RiggedExportOptions& options) {
  if (options.baked.empty()) return;
  if (!options.take) throw FileError(path, "baked surfaces need a take (the frames they were simulated on)");
  for (const BakedSurface& s : options.baked) {
    if (int(s.frames.size()) != options.take->frames)
      throw FileError(path, "'" + s.name + "' has " + std::to_string(s.frames.size()) + " frames, the take " +
                                std::to_string(options.take->frames));
    for (const auto& frame : s.frames)
      if (frame.size() != s.frames.front().size() || frame.empty())
        throw FileError(path, "'" + s.name + "' changes its vertex count between frames");
    const size_t n = s.frames.front().size() / 3;
    for (uint32_t i : s.triangles.empty() ? s.lines : s.triangles)
      if (i >= n) throw FileError(path, "'" + s.name + "' indexes a vertex it does not have");
  }
}

}  // namespace

bool isRiggedExportPath(const std::string& path) {
  const std::string ext = fileExtension(path);
  return ext == "gltf" || ext == "glb";
}

std::vector<std::string> exportRiggedCharacter(const Character& character, const std::string& path,
                                               const RiggedExportOptions& options) {
  if (!isRiggedExportPath(path)) throw FileError(path, "a rigged export is glTF: use .gltf or .glb");
  const float fps = options.take ? options.take->fps : options.fps;
  if (!(fps > 0.0f && fps <= 1000.0f)) throw FileError(path, "the animation rate must be between 0 and 1000 fps");
  if (options.take && options.take->frames < 1) throw FileError(path, "a take needs at least one frame");
  checkBaked(path, options);
  GltfWriter writer("mannequin rigged export");
  addSkeleton(writer, character.skeleton);
  std::vector<std::string> warnings = addGltfMaterials(writer, character);
  std::vector<int> meshNodes;
  for (const Mesh& mesh : character.meshes)
    meshNodes.push_back(addMesh(writer, mesh, character.skeleton.boneCount(), character.materials.size()));
  if (options.take) {
    const ExportTake& take = *options.take;
    const int clip = take.clip >= 0 && take.clip < int(character.clips.size()) ? take.clip : -1;
    const Samples samples = takeSamples(take);
    AnimationBuilder animation(writer, samples.fileTimes);
    addBoneChannels(animation, character, clip, samples.clipTimes, take.edits);
    addMorphChannels(animation, character, clip, samples.clipTimes, meshNodes);
    for (const BakedSurface& surface : options.baked)
      addBakedChannel(animation, addBakedSurface(writer, surface), surface.frames.size());
    animation.finish(take.name);
  } else {
    for (int c = 0; c < int(character.clips.size()); ++c) {
      const Samples samples = clipSamples(character.clips[c], fps);
      AnimationBuilder animation(writer, samples.fileTimes);
      addBoneChannels(animation, character, c, samples.clipTimes, nullptr);
      addMorphChannels(animation, character, c, samples.clipTimes, meshNodes);
      animation.finish(character.clips[c].name);
    }
  }
  const bool binary = fileExtension(path) == "glb";
  writeFileAtomically(
      path, [&](std::ostream& out) { binary ? writer.writeGlb(out) : writer.writeGltf(out); }, binary);
  return warnings;
}

}  // namespace mq
