#include "core/io/gltf_reader.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <numeric>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

#include "core/io/gltf_document.h"
#include "core/io/gltf_materials.h"
#include "core/mesh/tangents.h"
#include "core/util/error.h"

namespace mq {
namespace {

using gltf::Document;
using nlohmann::json;

// The node hierarchy of the default scene.
struct NodeGraph {
  std::vector<int> parent;  // -1 for roots
  std::vector<bool> inScene;
  std::vector<int> preorder;     // scene nodes, parents before children
  std::vector<glm::mat4> local;  // each node's local matrix
  std::vector<Trs> trs;          // the same split into parts
  std::vector<int> boneOfNode;   // -1 for nodes that are not bones
};

Trs nodeTrs(const json& node) {
  if (node.contains("matrix")) {
    const std::vector<float> m = node["matrix"].get<std::vector<float>>();
    if (m.size() != 16) throw std::invalid_argument("a node matrix needs 16 numbers");
    return Trs::fromMatrix(glm::make_mat4(m.data()));
  }
  Trs trs;
  if (node.contains("translation")) {
    const auto t = node["translation"].get<std::vector<float>>();
    if (t.size() == 3) trs.translation = {t[0], t[1], t[2]};
  }
  if (node.contains("rotation")) {
    const auto r = node["rotation"].get<std::vector<float>>();
    if (r.size() == 4) trs.rotation = glm::normalize(glm::quat(r[3], r[0], r[1], r[2]));
  }
  if (node.contains("scale")) {
    const auto s = node["scale"].get<std::vector<float>>();
    if (s.size() == 3) trs.scale = {s[0], s[1], s[2]};
  }
  return trs;
}

glm::mat4 nodeMatrix(const json& node, const Trs& trs) {
  if (!node.contains("matrix")) return trs.matrix();
  const std::vector<float> m = node["matrix"].get<std::vector<float>>();
  return glm::make_mat4(m.data());
}

std::vector<int> sceneRoots(const Document& doc, const std::vector<int>& parent) {
  const json& j = doc.json();
  if (j.contains("scenes") && !j["scenes"].empty()) {
    const int scene = j.value("scene", 0);
    return doc.element("scenes", scene).value("nodes", std::vector<int>{});
  }
  std::vector<int> roots;  // no scenes: every parentless node
  for (size_t n = 0; n < parent.size(); ++n)
    if (parent[n] < 0) roots.push_back(static_cast<int>(n));
  return roots;
}

NodeGraph buildGraph(const Document& doc) {
  const json& nodes = doc.json().value("nodes", json::array());
  const int count = static_cast<int>(nodes.size());
  NodeGraph g;
  g.parent.assign(count, -1);
  g.inScene.assign(count, false);
  for (int n = 0; n < count; ++n) {
    g.trs.push_back(nodeTrs(nodes[n]));
    g.local.push_back(nodeMatrix(nodes[n], g.trs.back()));
    for (int c : nodes[n].value("children", std::vector<int>{})) {
      if (c < 0 || c >= count) doc.fail("node " + std::to_string(n) + " has a missing child " + std::to_string(c));
      if (g.parent[c] >= 0 || c == n) doc.fail("node " + std::to_string(c) + " has more than one parent");
      g.parent[c] = n;
    }
  }
  std::vector<int> stack = sceneRoots(doc, g.parent);
  std::reverse(stack.begin(), stack.end());
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    if (n < 0 || n >= count) doc.fail("scene refers to missing node " + std::to_string(n));
    if (g.inScene[n]) doc.fail("node " + std::to_string(n) + " is reachable twice (cycle or shared child)");
    g.inScene[n] = true;
    g.preorder.push_back(n);
    const auto children = nodes[n].value("children", std::vector<int>{});
    for (auto it = children.rbegin(); it != children.rend(); ++it) stack.push_back(*it);
  }
  return g;
}

// Nodes that become bones: every skin joint and every node an animation moves.
std::vector<bool> boneNodes(const Document& doc, const NodeGraph& g) {
  std::vector<bool> isBone(g.parent.size(), false);
  auto mark = [&](int n, const char* what) {
    if (n < 0 || n >= static_cast<int>(isBone.size())) doc.fail(std::string(what) + " refers to a missing node");
    if (g.inScene[n]) isBone[n] = true;
  };
  for (const json& skin : doc.json().value("skins", json::array()))
    for (int j : skin.at("joints").get<std::vector<int>>()) mark(j, "skin joint");
  for (const json& anim : doc.json().value("animations", json::array()))
    for (const json& ch : anim.at("channels")) {
      const json& target = ch.at("target");
      const std::string path = target.at("path").get<std::string>();
      if (target.contains("node") && path != "weights") mark(target["node"].get<int>(), "animation channel");
    }
  return isBone;
}

// Nearest bone strictly above `node`; `offset` gets the product of the
// non-bone node matrices passed on the way (outermost first).
int nearestBoneAbove(const NodeGraph& g, int node, glm::mat4& offset) {
  offset = glm::mat4(1.0f);
  for (int n = g.parent[node]; n >= 0; n = g.parent[n]) {
    if (g.boneOfNode[n] >= 0) return g.boneOfNode[n];
    offset = g.local[n] * offset;
  }
  return -1;
}

Skeleton buildSkeleton(const Document& doc, NodeGraph& g) {
  const std::vector<bool> isBone = boneNodes(doc, g);
  const json& nodes = doc.json()["nodes"];
  g.boneOfNode.assign(g.parent.size(), -1);
  Skeleton skeleton;
  for (int n : g.preorder) {
    if (!isBone[n]) continue;
    Bone bone;
    bone.name = nodes[n].value("name", "node" + std::to_string(n));
    bone.rest = g.trs[n];
    bone.parent = nearestBoneAbove(g, n, bone.parentFromOffset);
    g.boneOfNode[n] = skeleton.addBone(std::move(bone));
  }
  return skeleton;
}

// --- meshes -------------------------------------------------------------

int attributeAccessor(const json& attributes, const std::string& name) {
  return attributes.contains(name) ? attributes[name].get<int>() : -1;
}

int skinSetCount(const json& attributes) {
  int sets = 0;
  while (attributes.contains("JOINTS_" + std::to_string(sets)) &&
         attributes.contains("WEIGHTS_" + std::to_string(sets)))
    ++sets;
  return sets;
}

// Triangles of one primitive in its own vertex numbering, per the spec's
// expansion of strips and fans; points and lines give none.
std::vector<uint32_t> primitiveTriangles(const Document& doc, const json& prim, size_t vertexCount) {
  std::vector<uint32_t> idx;
  if (prim.contains("indices")) {
    idx = doc.readUints(prim["indices"].get<int>());
  } else {
    idx.resize(vertexCount);
    std::iota(idx.begin(), idx.end(), 0u);
  }
  for (uint32_t i : idx)
    if (i >= vertexCount)
      doc.fail("primitive index " + std::to_string(i) + " out of range (" + std::to_string(vertexCount) + " vertices)");
  const int mode = prim.value("mode", 4);
  std::vector<uint32_t> tri;
  if (mode == 4) {
    tri.assign(idx.begin(), idx.begin() + (idx.size() / 3) * 3);
  } else if (mode == 5) {
    for (size_t i = 0; i + 2 < idx.size(); ++i) {
      const size_t odd = i % 2;
      tri.insert(tri.end(), {idx[i], idx[i + 1 + odd], idx[i + 2 - odd]});
    }
  } else if (mode == 6) {
    for (size_t i = 0; i + 2 < idx.size(); ++i) tri.insert(tri.end(), {idx[i + 1], idx[i + 2], idx[0]});
  }
  return tri;
}

void appendSkin(const Document& doc, const json& attributes, size_t vertexCount, int influences, size_t jointCount,
                SkinBinding& skin) {
  const int sets = skinSetCount(attributes);
  const size_t base = skin.joints.size();
  skin.joints.resize(base + vertexCount * influences, 0);
  skin.weights.resize(base + vertexCount * influences, 0.0f);
  for (int s = 0; s < sets; ++s) {
    int jc = 0, wc = 0;
    const auto joints = doc.readUints(attributes["JOINTS_" + std::to_string(s)].get<int>(), &jc);
    const auto weights = doc.readFloats(attributes["WEIGHTS_" + std::to_string(s)].get<int>(), &wc);
    if (jc != 4 || wc != 4 || joints.size() != 4 * vertexCount || weights.size() != 4 * vertexCount)
      doc.fail("JOINTS_/WEIGHTS_ accessors must be VEC4 with one element per vertex");
    for (size_t v = 0; v < vertexCount; ++v)
      for (int i = 0; i < 4; ++i) {
        const size_t slot = base + v * influences + 4 * s + i;
        const float w = weights[4 * v + i];
        const uint32_t j = joints[4 * v + i];
        if (w < 0.0f) doc.fail("negative skin weight");
        if (j >= jointCount && w != 0.0f) doc.fail("joint index " + std::to_string(j) + " is not in the skin");
        skin.joints[slot] = w != 0.0f ? static_cast<uint16_t>(j) : 0;
        skin.weights[slot] = w;
      }
  }
}

void appendMorphTargets(const Document& doc, const json& prim, size_t vertexCount, Mesh& mesh) {
  const json targets = prim.value("targets", json::array());
  if (targets.size() != mesh.morphTargets.size())
    doc.fail("primitives of mesh '" + mesh.name + "' have different morph target counts");
  for (size_t t = 0; t < targets.size(); ++t) {
    MorphTarget& target = mesh.morphTargets[t];
    for (const auto& [attribute, deltas] :
         {std::pair{"POSITION", &target.positionDeltas}, std::pair{"NORMAL", &target.normalDeltas}}) {
      std::vector<float> values(3 * vertexCount, 0.0f);
      if (targets[t].contains(attribute)) {
        values = doc.readFloats(targets[t][attribute].get<int>());
        if (values.size() != 3 * vertexCount) doc.fail("morph target size differs from its primitive's vertex count");
      }
      deltas->insert(deltas->end(), values.begin(), values.end());
    }
  }
}

// Which optional vertex attributes any primitive of a mesh has: the mesh gets
// the array when one does (zeros, or computed, for the others).
struct OptionalAttributes {
  bool uvs0 = false;
  bool uvs1 = false;
  bool tangents = false;
};

// An optional per-vertex attribute of `n` elements of `width` floats, or
// `fallback` (already sized) when the primitive lacks it.
void appendAttribute(const Document& doc, const json& attributes, const char* name, size_t n, int width,
                     std::vector<float> fallback, std::vector<float>& out) {
  std::vector<float> values = std::move(fallback);
  if (const int a = attributeAccessor(attributes, name); a >= 0) values = doc.readFloats(a);
  if (values.size() != static_cast<size_t>(width) * n)
    doc.fail(std::string(name) + " count differs from POSITION count");
  out.insert(out.end(), values.begin(), values.end());
}

void appendPrimitive(const Document& doc, const json& prim, int influences, size_t jointCount,
                     const OptionalAttributes& optional, Mesh& mesh) {
  const json& attributes = prim.at("attributes");
  const int positionAccessor = attributeAccessor(attributes, "POSITION");
  if (positionAccessor < 0) doc.fail("a primitive of mesh '" + mesh.name + "' has no POSITION");
  int components = 0;
  const std::vector<float> positions = doc.readFloats(positionAccessor, &components);
  if (components != 3) doc.fail("POSITION must be VEC3");
  const size_t n = positions.size() / 3;
  const uint32_t base = static_cast<uint32_t>(mesh.vertexCount());

  const std::vector<uint32_t> triangles = primitiveTriangles(doc, prim, n);
  std::vector<float> normals;
  if (const int a = attributeAccessor(attributes, "NORMAL"); a >= 0) {
    normals = doc.readFloats(a);
    if (normals.size() != 3 * n) doc.fail("NORMAL count differs from POSITION count");
  } else {
    computeVertexNormals(positions, triangles, normals);
  }
  mesh.submeshes.push_back({static_cast<uint32_t>(mesh.triangleCount()), static_cast<uint32_t>(triangles.size() / 3),
                            prim.value("material", -1)});
  mesh.positions.insert(mesh.positions.end(), positions.begin(), positions.end());
  mesh.normals.insert(mesh.normals.end(), normals.begin(), normals.end());
  for (uint32_t i : triangles) mesh.triangles.push_back(base + i);
  if (optional.uvs0) appendAttribute(doc, attributes, "TEXCOORD_0", n, 2, std::vector<float>(2 * n, 0.0f), mesh.uvs);
  if (optional.uvs1) appendAttribute(doc, attributes, "TEXCOORD_1", n, 2, std::vector<float>(2 * n, 0.0f), mesh.uvs1);
  if (optional.tangents) {
    // A primitive without tangents gets them from its uvs, as the spec asks.
    std::vector<float> computed(4 * n, 0.0f);
    if (attributeAccessor(attributes, "TANGENT") < 0 && optional.uvs0) {
      const std::vector<float> uvs(mesh.uvs.end() - static_cast<std::ptrdiff_t>(2 * n), mesh.uvs.end());
      computeVertexTangents(positions, normals, uvs, triangles, computed);
    }
    appendAttribute(doc, attributes, "TANGENT", n, 4, std::move(computed), mesh.tangents);
  }
  if (influences > 0) appendSkin(doc, attributes, n, influences, jointCount, mesh.skin);
  appendMorphTargets(doc, prim, n, mesh);
}

void normaliseMorphDeltas(Mesh& mesh) {
  for (MorphTarget& t : mesh.morphTargets)
    if (std::all_of(t.normalDeltas.begin(), t.normalDeltas.end(), [](float x) { return x == 0.0f; }))
      t.normalDeltas.clear();
}

void bindSkin(const Document& doc, const NodeGraph& g, int skinIndex, Mesh& mesh) {
  const json& skin = doc.element("skins", skinIndex);
  const auto joints = skin.at("joints").get<std::vector<int>>();
  std::vector<float> inverseBind;
  if (skin.contains("inverseBindMatrices")) {
    inverseBind = doc.readFloats(skin["inverseBindMatrices"].get<int>());
    if (inverseBind.size() != 16 * joints.size())
      doc.fail("skin " + std::to_string(skinIndex) + ": inverseBindMatrices count differs from joint count");
  }
  for (size_t j = 0; j < joints.size(); ++j) {
    const int bone = g.boneOfNode[joints[j]];
    if (bone < 0) doc.fail("skin " + std::to_string(skinIndex) + " has a joint outside the default scene");
    mesh.skin.jointBones.push_back(bone);
    mesh.skin.inverseBind.push_back(inverseBind.empty() ? glm::mat4(1.0f) : glm::make_mat4(&inverseBind[16 * j]));
  }
  mesh.skin.normalise();
}

Mesh readNodeMesh(const Document& doc, const NodeGraph& g, int nodeIndex) {
  const json& node = doc.json()["nodes"][nodeIndex];
  const json& gm = doc.element("meshes", node["mesh"].get<int>());
  Mesh mesh;
  mesh.name = gm.value("name", node.value("name", "mesh" + std::to_string(node["mesh"].get<int>())));
  const json& prims = gm.at("primitives");
  const bool skinned = node.contains("skin");
  size_t jointCount = 0;
  int influences = 0;
  OptionalAttributes optional;
  for (const json& p : prims) {
    const json& attributes = p.at("attributes");
    influences = std::max(influences, 4 * skinSetCount(attributes));
    optional.uvs0 = optional.uvs0 || attributes.contains("TEXCOORD_0");
    optional.uvs1 = optional.uvs1 || attributes.contains("TEXCOORD_1");
    optional.tangents = optional.tangents || attributes.contains("TANGENT");
  }
  if (skinned) {
    jointCount = doc.element("skins", node["skin"].get<int>()).at("joints").size();
    mesh.skin.influencesPerVertex = influences;
  } else {
    influences = 0;
  }
  if (!prims.empty()) {
    const json targets = prims[0].value("targets", json::array());
    mesh.morphTargets.resize(targets.size());
    const json names = gm.contains("extras") ? gm["extras"].value("targetNames", json::array()) : json::array();
    for (size_t t = 0; t < targets.size(); ++t)
      mesh.morphTargets[t].name =
          t < names.size() && names[t].is_string() ? names[t].get<std::string>() : "target" + std::to_string(t);
  }
  for (const json& p : prims) appendPrimitive(doc, p, influences, jointCount, optional, mesh);
  normaliseMorphDeltas(mesh);

  const auto weights = node.contains("weights") ? node["weights"] : gm.value("weights", json::array());
  mesh.morphWeights.assign(mesh.morphTargets.size(), 0.0f);
  for (size_t t = 0; t < weights.size() && t < mesh.morphWeights.size(); ++t)
    mesh.morphWeights[t] = weights[t].get<float>();

  if (skinned && influences > 0) {
    bindSkin(doc, g, node["skin"].get<int>(), mesh);
  } else if (g.boneOfNode[nodeIndex] >= 0) {
    mesh.attachBone = g.boneOfNode[nodeIndex];
  } else {
    mesh.attachBone = nearestBoneAbove(g, nodeIndex, mesh.boneFromMesh);
    mesh.boneFromMesh = mesh.boneFromMesh * g.local[nodeIndex];
  }
  return mesh;
}

// --- animations ---------------------------------------------------------

Interpolation interpolationOf(const Document& doc, const std::string& name) {
  if (name == "LINEAR") return Interpolation::Linear;
  if (name == "STEP") return Interpolation::Step;
  if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
  doc.fail("unknown animation interpolation '" + name + "'");
}

Track readTrack(const Document& doc, const json& sampler, const std::string& path) {
  Track track;
  track.interpolation = interpolationOf(doc, sampler.value("interpolation", std::string("LINEAR")));
  track.times = doc.readFloats(sampler.at("input").get<int>());
  track.values = doc.readFloats(sampler.at("output").get<int>());
  const size_t keys = track.times.size();
  const size_t perKeyValues = track.interpolation == Interpolation::CubicSpline ? 3 : 1;
  if (keys == 0) doc.fail("animation sampler has no keys");
  if (path == "weights") {
    track.components = static_cast<int>(track.values.size() / (keys * perKeyValues));
  } else {
    track.components = path == "rotation" ? 4 : 3;
    track.isRotation = path == "rotation";
  }
  try {
    track.validate();
  } catch (const std::invalid_argument& e) {
    doc.fail("animation " + path + " sampler: " + e.what());
  }
  return track;
}

Clip readAnimation(const Document& doc, const NodeGraph& g, const std::map<int, int>& meshOfNode, const json& anim,
                   int index) {
  Clip clip;
  clip.name = anim.value("name", std::string());
  if (clip.name.empty()) clip.name = "clip" + std::to_string(index);
  std::map<int, size_t> channelOfBone;
  const json& samplers = anim.at("samplers");
  for (const json& ch : anim.at("channels")) {
    const json& target = ch.at("target");
    if (!target.contains("node")) continue;
    const int node = target["node"].get<int>();
    const std::string path = target.at("path").get<std::string>();
    const int s = ch.at("sampler").get<int>();
    if (s < 0 || s >= static_cast<int>(samplers.size())) doc.fail("animation channel refers to a missing sampler");
    if (node < 0 || node >= static_cast<int>(g.parent.size()) || !g.inScene[node]) continue;
    if (path == "weights") {
      if (auto m = meshOfNode.find(node); m != meshOfNode.end())
        clip.morphChannels.push_back({m->second, readTrack(doc, samplers[s], path)});
      continue;
    }
    const int bone = g.boneOfNode[node];
    auto [it, added] = channelOfBone.emplace(bone, clip.boneChannels.size());
    if (added) clip.boneChannels.push_back({bone, {}, {}, {}});
    BoneChannel& bc = clip.boneChannels[it->second];
    if (path == "translation")
      bc.translation = readTrack(doc, samplers[s], path);
    else if (path == "rotation")
      bc.rotation = readTrack(doc, samplers[s], path);
    else if (path == "scale")
      bc.scale = readTrack(doc, samplers[s], path);
  }
  return clip;
}

// Extensions that change how geometry is stored (Draco, meshopt) would be
// read wrongly; refuse them clearly. Material, texture and light extensions
// do not touch what we read, and quantised attributes are plain accessors.
void checkRequiredExtensions(const Document& doc) {
  for (const json& e : doc.json().value("extensionsRequired", json::array())) {
    const std::string name = e.get<std::string>();
    const bool harmless = name.rfind("KHR_materials_", 0) == 0 || name.rfind("KHR_texture_", 0) == 0 ||
                          name == "KHR_mesh_quantization" || name == "KHR_lights_punctual";
    if (!harmless) doc.fail("requires the extension " + name + ", which this importer does not support");
  }
}

Character buildCharacter(const Document& doc) {
  checkRequiredExtensions(doc);
  Character character;
  character.name = std::filesystem::path(doc.path()).stem().string();
  character.sourcePath = doc.path();
  NodeGraph graph = buildGraph(doc);
  character.skeleton = buildSkeleton(doc, graph);
  gltf::readMaterials(doc, character);

  std::map<int, int> meshOfNode;
  const json& nodes = doc.json().value("nodes", json::array());
  for (int n = 0; n < static_cast<int>(nodes.size()); ++n) {
    if (!graph.inScene[n] || !nodes[n].contains("mesh")) continue;
    meshOfNode[n] = static_cast<int>(character.meshes.size());
    character.meshes.push_back(readNodeMesh(doc, graph, n));
  }
  character.addMissingTangents();
  const json anims = doc.json().value("animations", json::array());
  for (size_t a = 0; a < anims.size(); ++a)
    character.clips.push_back(readAnimation(doc, graph, meshOfNode, anims[a], static_cast<int>(a)));
  return character;
}

}  // namespace

Character readGltfCharacter(const std::string& path) {
  const Document doc = Document::load(path);
  Character character;
  try {
    character = buildCharacter(doc);
    character.validate();
  } catch (const json::exception& e) {
    doc.fail("malformed glTF: " + jsonProblem(e));
  } catch (const std::invalid_argument& e) {
    doc.fail(e.what());
  } catch (const FileError&) {
    throw;
  } catch (const std::runtime_error& e) {
    doc.fail(e.what());
  }
  return character;
}

}  // namespace mq
