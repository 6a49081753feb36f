#include "core/io/rigged_export.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/io/file_bytes.h"
#include "core/io/gltf_material_export.h"
#include "core/io/gltf_writer.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "core/util/utf8.h"

namespace mq {
namespace {

// A bone's node transform: its fixed offset (non-bone nodes of the source
// file) folded into its local transform.
Trs nodeTransform(const Bone& bone, const Trs& local) {
  if (bone.parentFromOffset == glm::mat4(1.0f)) return local;
  return Trs::fromMatrix(bone.parentFromOffset * local.matrix());
}

void setTrs(tinygltf::Node& node, const Trs& t) {
  node.translation = {t.translation.x, t.translation.y, t.translation.z};
  node.rotation = {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
  node.scale = {t.scale.x, t.scale.y, t.scale.z};
}

void addSkeleton(GltfWriter& writer, const Skeleton& skeleton) {
  for (int b = 0; b < skeleton.boneCount(); ++b) {
    tinygltf::Node node;
    setTrs(node, nodeTransform(skeleton.bone(b), skeleton.bone(b).rest));
    node.name = skeleton.bone(b).name;
    node.children = skeleton.children(b);
    writer.addNode(std::move(node), skeleton.bone(b).parent < 0);
  }
}

// JOINTS_0 / WEIGHTS_0: the four heaviest influences of each vertex. An
// unused slot names joint 0: glTF wants a zero weight on a zero joint index.
void addSkinAttributes(GltfWriter& writer, const SkinBinding& skin, size_t vertices,
                       std::map<std::string, int>& attributes) {
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
  attributes["JOINTS_0"] = writer.addAccessor(joints.data(), vertices, TINYGLTF_TYPE_VEC4,
                                              TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TARGET_ARRAY_BUFFER);
  attributes["WEIGHTS_0"] = writer.addVertexAttribute(weights, TINYGLTF_TYPE_VEC4);
}

// The mesh's morph targets on each of its primitives, their default weights
// and their names (extras.targetNames, which Blender and three.js read).
void addMorphTargets(GltfWriter& writer, const Mesh& mesh, tinygltf::Mesh& gltfMesh) {
  if (mesh.morphTargets.empty()) return;
  const size_t n = mesh.vertexCount();
  std::vector<std::map<std::string, int>> targets;
  tinygltf::Value::Array names;
  for (const MorphTarget& target : mesh.morphTargets) {
    std::map<std::string, int> attributes = {{"POSITION", writer.addPositionAccessor(target.positionDeltas)}};
    if (target.normalDeltas.size() == 3 * n)
      attributes["NORMAL"] = writer.addVertexAttribute(target.normalDeltas, TINYGLTF_TYPE_VEC3);
    targets.push_back(std::move(attributes));
    names.emplace_back(repairedUtf8(target.name));
  }
  for (tinygltf::Primitive& primitive : gltfMesh.primitives) primitive.targets = targets;
  std::vector<float> weights = mesh.morphWeights;
  weights.resize(mesh.morphTargets.size(), 0.0f);
  gltfMesh.weights.assign(weights.begin(), weights.end());
  gltfMesh.extras = tinygltf::Value(tinygltf::Value::Object{{"targetNames", tinygltf::Value(std::move(names))}});
}

// Returns the index of the node that holds the mesh.
int addMesh(GltfWriter& writer, const Mesh& mesh, int boneCount, size_t materialCount) {
  tinygltf::Model& model = writer.model();
  const size_t n = mesh.vertexCount();
  std::map<std::string, int> attributes;
  attributes["POSITION"] = writer.addPositionAccessor(mesh.positions);
  if (mesh.normals.size() == 3 * n) attributes["NORMAL"] = writer.addVertexAttribute(mesh.normals, TINYGLTF_TYPE_VEC3);
  if (mesh.uvs.size() == 2 * n) attributes["TEXCOORD_0"] = writer.addVertexAttribute(mesh.uvs, TINYGLTF_TYPE_VEC2);
  const bool skinned = !mesh.skin.empty();
  if (skinned) addSkinAttributes(writer, mesh.skin, n, attributes);
  tinygltf::Mesh gltfMesh;
  gltfMesh.name = mesh.name;
  gltfMesh.primitives = gltfPrimitives(writer, mesh, attributes, materialCount);
  addMorphTargets(writer, mesh, gltfMesh);
  model.meshes.push_back(std::move(gltfMesh));

  tinygltf::Node node;
  node.name = mesh.name;
  node.mesh = int(model.meshes.size()) - 1;
  if (skinned) {
    std::vector<float> inverseBind;
    for (const glm::mat4& m : mesh.skin.inverseBind)
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) inverseBind.push_back(m[c][r]);  // column-major, as glTF
    tinygltf::Skin skin;
    skin.inverseBindMatrices = writer.addAccessor(inverseBind.data(), mesh.skin.inverseBind.size(), TINYGLTF_TYPE_MAT4,
                                                  TINYGLTF_COMPONENT_TYPE_FLOAT);
    skin.joints = mesh.skin.jointBones;
    model.skins.push_back(std::move(skin));
    node.skin = int(model.skins.size()) - 1;
    return writer.addNode(std::move(node), true);
  }
  const glm::mat4& m = mesh.boneFromMesh;
  if (m != glm::mat4(1.0f)) node.matrix.assign(&m[0][0], &m[0][0] + 16);
  const bool attached = mesh.attachBone >= 0 && mesh.attachBone < boneCount;
  const int index = writer.addNode(std::move(node), !attached);
  if (attached) model.nodes[mesh.attachBone].children.push_back(index);
  return index;
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
    input_ = writer.addAccessor(times.data(), times.size(), TINYGLTF_TYPE_SCALAR, TINYGLTF_COMPONENT_TYPE_FLOAT);
    writer.model().accessors[input_].minValues = {times.front()};
    writer.model().accessors[input_].maxValues = {times.back()};
  }
  void addChannel(int node, const char* path, const std::vector<float>& values, int type, int size) {
    tinygltf::AnimationSampler sampler;
    sampler.input = input_;
    sampler.output = writer_.addAccessor(values.data(), values.size() / size, type, TINYGLTF_COMPONENT_TYPE_FLOAT);
    sampler.interpolation = "LINEAR";
    animation_.samplers.push_back(std::move(sampler));
    tinygltf::AnimationChannel channel;
    channel.sampler = int(animation_.samplers.size()) - 1;
    channel.target_node = node;
    channel.target_path = path;
    animation_.channels.push_back(std::move(channel));
  }
  void finish(const std::string& name) {
    animation_.name = name;
    writer_.model().animations.push_back(std::move(animation_));
  }

 private:
  GltfWriter& writer_;
  int input_ = -1;
  tinygltf::Animation animation_;
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
    animation.addChannel(b, "translation", translations[b], TINYGLTF_TYPE_VEC3, 3);
    animation.addChannel(b, "rotation", rotations[b], TINYGLTF_TYPE_VEC4, 4);
    animation.addChannel(b, "scale", scales[b], TINYGLTF_TYPE_VEC3, 3);
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
    animation.addChannel(meshNodes[channel.mesh], "weights", values, TINYGLTF_TYPE_SCALAR, 1);
  }
}

// A baked surface as a mesh in world space: frame 0 as its base, frame f as
// morph target f - 1; returns its node.
int addBakedSurface(GltfWriter& writer, const BakedSurface& surface) {
  tinygltf::Model& model = writer.model();
  const std::vector<float>& base = surface.frames.front();
  const bool lines = surface.triangles.empty();
  tinygltf::Primitive primitive;
  primitive.attributes["POSITION"] = writer.addPositionAccessor(base);
  if (surface.colors.size() == base.size())
    primitive.attributes["COLOR_0"] = writer.addVertexAttribute(surface.colors, TINYGLTF_TYPE_VEC3);
  std::vector<float> baseNormals;
  if (!lines) {
    computeVertexNormals(base, surface.triangles, baseNormals);
    primitive.attributes["NORMAL"] = writer.addVertexAttribute(baseNormals, TINYGLTF_TYPE_VEC3);
  }
  std::vector<float> delta(base.size()), normals, normalDelta(base.size());
  for (size_t f = 1; f < surface.frames.size(); ++f) {
    for (size_t k = 0; k < base.size(); ++k) delta[k] = surface.frames[f][k] - base[k];
    std::map<std::string, int> target = {{"POSITION", writer.addPositionAccessor(delta)}};
    if (!lines) {
      computeVertexNormals(surface.frames[f], surface.triangles, normals);
      for (size_t k = 0; k < base.size(); ++k) normalDelta[k] = normals[k] - baseNormals[k];
      target["NORMAL"] = writer.addVertexAttribute(normalDelta, TINYGLTF_TYPE_VEC3);
    }
    primitive.targets.push_back(std::move(target));
  }
  const std::vector<uint32_t>& indices = lines ? surface.lines : surface.triangles;
  primitive.indices = writer.addIndices(indices.data(), indices.size());
  primitive.mode = lines ? TINYGLTF_MODE_LINE : TINYGLTF_MODE_TRIANGLES;

  tinygltf::Material material;
  material.name = surface.name;
  const glm::vec4& c = surface.color;
  material.pbrMetallicRoughness.baseColorFactor = {c.x, c.y, c.z, c.w};
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = 0.8;
  material.doubleSided = true;
  model.materials.push_back(std::move(material));
  primitive.material = int(model.materials.size()) - 1;

  tinygltf::Mesh mesh;
  mesh.name = surface.name;
  mesh.weights.assign(primitive.targets.size(), 0.0);
  mesh.primitives.push_back(std::move(primitive));
  model.meshes.push_back(std::move(mesh));
  tinygltf::Node node;
  node.name = surface.name;
  node.mesh = int(model.meshes.size()) - 1;
  return writer.addNode(std::move(node), true);
}

// Frame f shows morph target f - 1 alone (frame 0: the base); linear
// interpolation between two frames blends their two targets.
void addBakedChannel(AnimationBuilder& animation, int node, size_t frames) {
  if (frames < 2) return;
  const size_t targets = frames - 1;
  std::vector<float> values(frames * targets, 0.0f);
  for (size_t f = 1; f < frames; ++f) values[f * targets + (f - 1)] = 1.0f;
  animation.addChannel(node, "weights", values, TINYGLTF_TYPE_SCALAR, 1);
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
      path, [&](std::ostream& out) { writer.write(out, binary); }, binary);
  return warnings;
}

}  // namespace mq
