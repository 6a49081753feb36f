#include "core/io/assimp_import.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include "core/io/collada_clips.h"
#include "core/io/file_bytes.h"
#include "core/util/error.h"
#include "core/util/isolated_run.h"
#include "core/util/utf8.h"

namespace mq {
namespace {

glm::mat4 toGlm(const aiMatrix4x4& a) {
  glm::mat4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = a[r][c];  // Assimp is row-major
  return m;
}

// Collada's float arrays may carry whitespace around their numbers, which is
// valid XML but Assimp 5.2.5 refuses ("Cannot parse string ... as a real
// number"). Trims the whitespace around every text node that holds data.
std::string trimTextNodes(const std::string& xml) {
  std::string out;
  out.reserve(xml.size());
  size_t i = 0;
  while (i < xml.size()) {
    const size_t close = xml.find('>', i);
    if (close == std::string::npos) break;
    out.append(xml, i, close + 1 - i);
    const size_t open = xml.find('<', close + 1);
    const size_t end = open == std::string::npos ? xml.size() : open;
    const std::string_view text(xml.data() + close + 1, end - close - 1);
    const size_t first = text.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos)
      out.append(text);
    else
      out.append(text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1));
    i = end;
  }
  out.append(xml, i, std::string::npos);
  return out;
}

// A Collada element declares its size (count="N") before its data; Assimp
// reserves that much before reading. No count can exceed the file's bytes.
void checkColladaCounts(const std::string& text, const std::string& path) {
  static const std::string attribute = "count=\"";
  for (size_t at = text.find(attribute); at != std::string::npos; at = text.find(attribute, at + 1)) {
    const size_t digits = at + attribute.size();
    double count = 0.0;
    for (size_t i = digits; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i)
      count = count * 10.0 + (text[i] - '0');
    if (count > double(text.size())) {
      const long line = 1 + std::count(text.begin(), text.begin() + long(at), '\n');
      throw FileError(path, "line " + std::to_string(line) + ": count=\"" +
                                text.substr(digits, text.find('"', digits) - digits) +
                                "\" is more than the file holds");
    }
  }
}

// Assimp 5.2.5 reads Collada's number lists by skipping to the next digit
// and converting: a list holding something else ("<p> p 1 2 </p>") makes it
// loop, appending zeros until memory runs out. Every list must hold numbers only.
void checkColladaNumbers(const std::string& text, const std::string& path) {
  struct List {
    const char* tag;
    const char* allowed;  // besides whitespace
  };
  static const List lists[] = {{"p", "0123456789+-"},         {"vcount", "0123456789+-"},
                               {"v", "0123456789+-"},         {"h", "0123456789+-"},
                               {"int_array", "0123456789+-"}, {"float_array", "0123456789+-.eEnaifNAIF"}};
  for (const List& list : lists) {
    const std::string open = std::string("<") + list.tag;
    for (size_t at = text.find(open); at != std::string::npos; at = text.find(open, at + 1)) {
      const size_t after = at + open.size();
      if (after >= text.size() || !(text[after] == '>' || std::isspace(static_cast<unsigned char>(text[after]))))
        continue;  // a longer tag (<param>, <polylist>)
      const size_t begin = text.find('>', after);
      if (begin == std::string::npos || text[begin - 1] == '/') continue;
      const size_t end = std::min(text.find('<', begin), text.size());
      for (size_t i = begin + 1; i < end; ++i) {
        const char c = text[i];
        if (std::isspace(static_cast<unsigned char>(c)) || std::strchr(list.allowed, c)) continue;
        const long line = 1 + std::count(text.begin(), text.begin() + long(i), '\n');
        const size_t wordEnd = std::min({text.find_first_of(" \t\r\n<", i), i + 20, text.size()});
        throw FileError(path, "line " + std::to_string(line) + ": <" + list.tag + "> holds \"" +
                                  text.substr(i, wordEnd - i) + "\", not a number");
      }
    }
  }
}

unsigned importFlags(const std::string& ext) {
  unsigned flags = aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_ValidateDataStructure;
  // Assimp expands Collada's indexed vertices per face corner, OBJ indexes
  // positions, normals and uvs apart and STL repeats every corner: welding
  // identical corners restores a connected surface.
  if (ext == "dae" || ext == "obj" || ext == "ply" || ext == "stl") flags |= aiProcess_JoinIdenticalVertices;
  if (ext == "stl") flags |= aiProcess_DropNormals;  // per-face normals would keep the corners apart
  return flags;
}

const aiScene* readWith(Assimp::Importer& importer, const std::string& path, const std::string& colladaText) {
  importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, false);       // no $AssimpFbx$ helper nodes
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_USE_COLLADA_NAMES, true);  // "Bone", not "id-bone-3"
  const std::string ext = fileExtension(path);
  if (ext == "dae") return importer.ReadFileFromMemory(colladaText.data(), colladaText.size(), importFlags(ext), "dae");
  return importer.ReadFile(path, importFlags(ext));
}

// Assimp asserts (aborting the process) or allocates without bound on some
// damaged files: a first read in a bounded child process finds those. Only a
// file the child read is read again here: one it refused (Assimp catches its
// own std::bad_alloc under the child's memory limit and returns nothing)
// would run unbounded in this process.
void checkAssimpSurvives(const std::string& path, const std::string& colladaText) {
  const IsolatedOutcome outcome = runIsolated([&](std::string& reason) {
    Assimp::Importer importer;
    if (readWith(importer, path, colladaText)) return true;
    reason = importer.GetErrorString();
    return false;
  });
  if (outcome.ok) return;
  if (outcome.problem == "failed" && outcome.reason.find("bad_alloc") == std::string::npos)
    throw FileError(path, "cannot import: " + (outcome.reason.empty() ? std::string("unreadable") : outcome.reason));
  if (outcome.problem == "failed")  // Assimp caught running out of the child's memory itself
    throw FileError(path, "cannot import: the importer (Assimp) ran out of memory (limit " +
                              std::to_string(IsolationLimits{}.memoryBytes >> 30) +
                              " GiB) reading this file: it is damaged or not a format Mannequin reads");
  throw FileError(path, "cannot import: the importer (Assimp) " + outcome.problem +
                            " reading this file: it is damaged or not a format Mannequin reads");
}

// Collada text (whitespace-trimmed) is returned in `colladaText` for the clip reader.
const aiScene* readScene(Assimp::Importer& importer, const std::string& path, std::string& colladaText) {
  if (fileExtension(path) == "dae") {
    const std::string text = loadFileText(path);
    checkColladaCounts(text, path);
    checkColladaNumbers(text, path);
    colladaText = trimTextNodes(text);
  } else {
    (void)readFileBytes(path);  // clear message for missing files
  }
  checkAssimpSurvives(path, colladaText);
  const aiScene* scene = readWith(importer, path, colladaText);
  if (!scene || !scene->mRootNode) {
    std::string why = importer.GetErrorString();
    if (why.empty()) why = "unreadable";
    throw FileError(path, "cannot import: " + why);
  }
  return scene;
}

struct NodeTable {
  std::vector<const aiNode*> nodes;  // preorder: parents before children
  std::vector<int> parent;
  std::vector<glm::mat4> local, worldRest;
  std::map<std::string, int> byName;
  std::vector<int> boneOfNode;

  void collect(const aiNode* node, int parentIndex) {
    const int index = static_cast<int>(nodes.size());
    nodes.push_back(node);
    parent.push_back(parentIndex);
    local.push_back(toGlm(node->mTransformation));
    worldRest.push_back(parentIndex < 0 ? local.back() : worldRest[parentIndex] * local.back());
    byName.emplace(node->mName.C_Str(), index);
    for (unsigned c = 0; c < node->mNumChildren; ++c) collect(node->mChildren[c], index);
  }
  int find(const aiString& name) const {
    auto it = byName.find(name.C_Str());
    return it == byName.end() ? -1 : it->second;
  }
};

// Nearest bone strictly above `node`, and the product of the non-bone
// transforms passed on the way (outermost first).
int nearestBoneAbove(const NodeTable& t, int node, glm::mat4& offset) {
  offset = glm::mat4(1.0f);
  for (int n = t.parent[node]; n >= 0; n = t.parent[n]) {
    if (t.boneOfNode[n] >= 0) return t.boneOfNode[n];
    offset = t.local[n] * offset;
  }
  return -1;
}

// An animation before bones are known: tracks keyed by node.
struct NodeChannel {
  int node = -1;
  Track translation, rotation, scale;
};
struct RawClip {
  std::string name;
  std::vector<NodeChannel> channels;
};

// True when the track holds the node's rest value at every key: such a node
// is not really animated (exporters key the armature object too) and stays
// a fixed transform instead of becoming a bone.
bool keepsRestValue(const Track& track, const float* rest) {
  for (int k = 0; k < track.keyCount(); ++k) {
    const float* v = &track.values[size_t(k) * track.components];
    if (track.isRotation) {
      const float dot = v[0] * rest[0] + v[1] * rest[1] + v[2] * rest[2] + v[3] * rest[3];
      if (std::abs(dot) < 1.0f - 1e-6f) return false;
    } else {
      for (int c = 0; c < track.components; ++c)
        if (std::abs(v[c] - rest[c]) > 1e-5f * (1.0f + std::abs(rest[c]))) return false;
    }
  }
  return true;
}

bool movesNode(const NodeChannel& ch, const NodeTable& t) {
  const Trs rest = Trs::fromMatrix(t.local[ch.node]);
  const float q[4] = {rest.rotation.x, rest.rotation.y, rest.rotation.z, rest.rotation.w};
  return !keepsRestValue(ch.translation, &rest.translation.x) || !keepsRestValue(ch.rotation, q) ||
         !keepsRestValue(ch.scale, &rest.scale.x);
}

Skeleton buildSkeleton(const aiScene* scene, const std::vector<RawClip>& clips,
                       const std::vector<std::string>& extraJoints, NodeTable& t, const std::string& path) {
  std::set<int> boneNodes;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m)
    for (unsigned b = 0; b < scene->mMeshes[m]->mNumBones; ++b) {
      const aiString& name = scene->mMeshes[m]->mBones[b]->mName;
      const int n = t.find(name);
      if (n < 0) throw FileError(path, std::string("bone '") + name.C_Str() + "' has no node");
      boneNodes.insert(n);
    }
  for (const RawClip& clip : clips)
    for (const NodeChannel& ch : clip.channels)
      if (movesNode(ch, t)) boneNodes.insert(ch.node);

  for (const std::string& joint : extraJoints)  // joints without weights: Assimp drops their aiBone
    if (const int n = t.find(aiString(joint)); n >= 0) boneNodes.insert(n);

  Skeleton skeleton;
  t.boneOfNode.assign(t.nodes.size(), -1);
  for (int n = 0; n < static_cast<int>(t.nodes.size()); ++n) {
    if (!boneNodes.count(n)) continue;
    Bone bone;
    bone.name = repairedUtf8(t.nodes[n]->mName.C_Str());
    bone.rest = Trs::fromMatrix(t.local[n]);
    bone.parent = nearestBoneAbove(t, n, bone.parentFromOffset);
    t.boneOfNode[n] = skeleton.addBone(std::move(bone));
  }
  return skeleton;
}

// boneFromMesh at bind time. FBX: from the rest pose of the nodes, because
// Assimp 5.2's FBX bone offsets are wrong for many files (assimp issue 4620;
// with Assimp's offsets the test FBX's rest pose comes out bent by ~5% of its
// length instead of reproducing the mesh). Other formats: Assimp's offset,
// which carries the file's own bind pose.
glm::mat4 inverseBindOf(const aiBone* bone, const NodeTable& t, int boneNode, int meshNode, bool fromNodes) {
  if (fromNodes) return glm::inverse(t.worldRest[boneNode]) * t.worldRest[meshNode];
  return toGlm(bone->mOffsetMatrix);
}

void bindSkin(const aiMesh* am, const NodeTable& t, int meshNode, Mesh& mesh, bool bindFromNodes) {
  const size_t n = am->mNumVertices;
  std::vector<std::vector<std::pair<int, float>>> influences(n);
  SkinBinding& skin = mesh.skin;
  for (unsigned b = 0; b < am->mNumBones; ++b) {
    const aiBone* bone = am->mBones[b];
    const int node = t.find(bone->mName);
    skin.jointBones.push_back(t.boneOfNode[node]);
    skin.inverseBind.push_back(inverseBindOf(bone, t, node, meshNode, bindFromNodes));
    for (unsigned w = 0; w < bone->mNumWeights; ++w) {
      const aiVertexWeight& vw = bone->mWeights[w];
      if (vw.mVertexId < n && vw.mWeight > 0.0f && std::isfinite(vw.mWeight))
        influences[vw.mVertexId].push_back({static_cast<int>(b), vw.mWeight});
    }
  }
  size_t k = 1;
  for (const auto& list : influences) k = std::max(k, list.size());
  skin.influencesPerVertex = static_cast<int>(k);
  skin.joints.assign(n * k, 0);
  skin.weights.assign(n * k, 0.0f);
  for (size_t v = 0; v < n; ++v)
    for (size_t i = 0; i < influences[v].size(); ++i) {
      skin.joints[v * k + i] = static_cast<uint16_t>(influences[v][i].first);
      skin.weights[v * k + i] = influences[v][i].second;
    }
  skin.normalise();
}

Mesh convertMesh(const aiMesh* am, const NodeTable& t, int node, bool bindFromNodes) {
  Mesh mesh;
  mesh.name = repairedUtf8(am->mName.length > 0 ? am->mName.C_Str() : t.nodes[node]->mName.C_Str());
  const size_t n = am->mNumVertices;
  mesh.positions.resize(3 * n);
  for (size_t v = 0; v < n; ++v)
    for (int d = 0; d < 3; ++d) mesh.positions[3 * v + d] = am->mVertices[v][d];
  for (unsigned f = 0; f < am->mNumFaces; ++f)
    if (am->mFaces[f].mNumIndices == 3)
      for (int i = 0; i < 3; ++i) mesh.triangles.push_back(am->mFaces[f].mIndices[i]);
  if (am->HasNormals()) {
    mesh.normals.resize(3 * n);
    for (size_t v = 0; v < n; ++v)
      for (int d = 0; d < 3; ++d) mesh.normals[3 * v + d] = am->mNormals[v][d];
  } else {
    computeVertexNormals(mesh.positions, mesh.triangles, mesh.normals);
  }
  if (am->HasTextureCoords(0)) {
    mesh.uvs.resize(2 * n);
    for (size_t v = 0; v < n; ++v) {
      mesh.uvs[2 * v] = am->mTextureCoords[0][v].x;
      mesh.uvs[2 * v + 1] = 1.0f - am->mTextureCoords[0][v].y;  // Assimp's origin is bottom left
    }
  }
  if (am->HasTextureCoords(1)) {
    mesh.uvs1.resize(2 * n);
    for (size_t v = 0; v < n; ++v) {
      mesh.uvs1[2 * v] = am->mTextureCoords[1][v].x;
      mesh.uvs1[2 * v + 1] = 1.0f - am->mTextureCoords[1][v].y;
    }
  }
  if (am->HasBones()) {
    bindSkin(am, t, node, mesh, bindFromNodes);
  } else if (t.boneOfNode[node] >= 0) {
    mesh.attachBone = t.boneOfNode[node];
  } else {
    mesh.attachBone = nearestBoneAbove(t, node, mesh.boneFromMesh);
    mesh.boneFromMesh = mesh.boneFromMesh * t.local[node];
  }
  return mesh;
}

template <typename Key, typename Write>
Track keyTrack(const Key* keys, unsigned count, double ticksPerSecond, int components, Write write) {
  Track track;
  track.components = components;
  track.isRotation = components == 4;
  for (unsigned k = 0; k < count; ++k) {
    const float time = static_cast<float>(keys[k].mTime / ticksPerSecond);
    if (!track.times.empty() && time <= track.times.back()) continue;  // drop repeated keys
    track.times.push_back(time);
    write(keys[k].mValue, track.values);
  }
  return track;
}

RawClip convertAnimation(const aiAnimation* anim, const NodeTable& t, int index, const std::string& path) {
  RawClip clip;
  clip.name = anim->mName.length > 0 ? repairedUtf8(anim->mName.C_Str()) : "clip" + std::to_string(index);
  const double tps = anim->mTicksPerSecond > 0.0 ? anim->mTicksPerSecond : 25.0;
  auto vec3 = [](const aiVector3D& v, std::vector<float>& out) { out.insert(out.end(), {v.x, v.y, v.z}); };
  auto quat = [](const aiQuaternion& q, std::vector<float>& out) { out.insert(out.end(), {q.x, q.y, q.z, q.w}); };
  for (unsigned c = 0; c < anim->mNumChannels; ++c) {
    const aiNodeAnim* ch = anim->mChannels[c];
    NodeChannel nc;
    nc.node = t.find(ch->mNodeName);
    if (nc.node < 0) throw FileError(path, std::string("animated node '") + ch->mNodeName.C_Str() + "' does not exist");
    nc.translation = keyTrack(ch->mPositionKeys, ch->mNumPositionKeys, tps, 3, vec3);
    nc.rotation = keyTrack(ch->mRotationKeys, ch->mNumRotationKeys, tps, 4, quat);
    nc.scale = keyTrack(ch->mScalingKeys, ch->mNumScalingKeys, tps, 3, vec3);
    clip.channels.push_back(std::move(nc));
  }
  return clip;
}

Track emptyTrackLike(int components, bool rotation, bool step) {
  Track t;
  t.components = components;
  t.isRotation = rotation;
  t.interpolation = step ? Interpolation::Step : Interpolation::Linear;
  return t;
}

// The track restricted to [start, end], with keys sampled at both ends.
Track cropTrack(const Track& track, float start, float end) {
  if (track.empty() || end <= start) return track;
  Track out = track;
  out.times.clear();
  out.values.clear();
  std::vector<float> v(track.components);
  auto add = [&](float t) {
    track.sample(t, v.data());
    out.times.push_back(t);
    out.values.insert(out.values.end(), v.begin(), v.end());
  };
  add(start);
  for (float t : track.times)
    if (t > start && t < end) add(t);
  add(end);
  return out;
}

RawClip convertColladaClip(const ColladaClip& clip, const NodeTable& t, const std::string& path) {
  RawClip raw;
  raw.name = clip.name;
  for (const ColladaNodeTrack& track : clip.tracks) {
    NodeChannel nc;
    nc.node = t.find(aiString(track.nodeName));
    if (nc.node < 0) nc.node = t.find(aiString(track.nodeId));
    if (nc.node < 0) throw FileError(path, "clip '" + clip.name + "' animates unknown node '" + track.nodeId + "'");
    nc.translation = emptyTrackLike(3, false, track.step);
    nc.rotation = emptyTrackLike(4, true, track.step);
    nc.scale = emptyTrackLike(3, false, track.step);
    for (size_t k = 0; k < track.times.size(); ++k) {
      const Trs trs = Trs::fromMatrix(track.matrices[k]);
      for (Track* tr : {&nc.translation, &nc.rotation, &nc.scale}) tr->times.push_back(track.times[k]);
      nc.translation.values.insert(nc.translation.values.end(),
                                   {trs.translation.x, trs.translation.y, trs.translation.z});
      nc.rotation.values.insert(nc.rotation.values.end(),
                                {trs.rotation.x, trs.rotation.y, trs.rotation.z, trs.rotation.w});
      nc.scale.values.insert(nc.scale.values.end(), {trs.scale.x, trs.scale.y, trs.scale.z});
    }
    const float end = clip.end >= 0.0f ? clip.end : track.times.back();
    nc.translation = cropTrack(nc.translation, clip.start, end);
    nc.rotation = cropTrack(nc.rotation, clip.start, end);
    nc.scale = cropTrack(nc.scale, clip.start, end);
    raw.channels.push_back(std::move(nc));
  }
  return raw;
}

// --- materials ----------------------------------------------------------

TextureWrap wrapOf(aiTextureMapMode mode) {
  switch (mode) {
    case aiTextureMapMode_Clamp:
      return TextureWrap::ClampToEdge;
    case aiTextureMapMode_Mirror:
      return TextureWrap::MirroredRepeat;
    default:
      return TextureWrap::Repeat;
  }
}

// An image by its Assimp texture path: "*N" is the scene's embedded texture N;
// anything else a file beside the model (tried as written, then by its bare
// name, since exporters write absolute or Windows paths).
int imageFor(const aiScene* scene, const std::string& texturePath, const std::string& modelPath,
             std::map<std::string, int>& imageOfPath, Character& character) {
  if (auto found = imageOfPath.find(texturePath); found != imageOfPath.end()) return found->second;
  ImageSource image;
  image.name = texturePath;
  if (const aiTexture* embedded = scene->GetEmbeddedTexture(texturePath.c_str())) {
    if (embedded->mHeight != 0) {
      character.loadWarnings.push_back(modelPath + ": embedded texture '" + texturePath +
                                       "' is stored as raw texels, which are not read; its material uses its colours");
      return imageOfPath[texturePath] = -1;
    }
    const auto* bytes = reinterpret_cast<const uint8_t*>(embedded->pcData);
    image.encoded.assign(bytes, bytes + embedded->mWidth);
  } else {
    std::string portable = texturePath;
    std::replace(portable.begin(), portable.end(), '\\', '/');
    const std::filesystem::path folder = std::filesystem::path(modelPath).parent_path();
    std::filesystem::path file = folder / portable;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) file = folder / std::filesystem::path(portable).filename();
    image.path = file.string();
    if (!std::filesystem::is_regular_file(file, ec))
      character.loadWarnings.push_back(modelPath + ": texture image '" + texturePath +
                                       "' not found; its material falls back to its colours");
  }
  character.images.push_back(std::move(image));
  return imageOfPath[texturePath] = static_cast<int>(character.images.size()) - 1;
}

TextureRef textureOf(const aiScene* scene, const aiMaterial* m, std::initializer_list<aiTextureType> types,
                     const std::string& modelPath, std::map<std::string, int>& imageOfPath, Character& character) {
  TextureRef ref;
  for (aiTextureType type : types) {
    if (m->GetTextureCount(type) == 0) continue;
    aiString texturePath;
    unsigned uvIndex = 0;
    aiTextureMapMode modes[2] = {aiTextureMapMode_Wrap, aiTextureMapMode_Wrap};
    if (m->GetTexture(type, 0, &texturePath, nullptr, &uvIndex, nullptr, nullptr, modes) != AI_SUCCESS) continue;
    ref.image = imageFor(scene, texturePath.C_Str(), modelPath, imageOfPath, character);
    ref.texCoord = uvIndex <= 1 ? static_cast<int>(uvIndex) : 0;
    ref.sampler.wrapS = wrapOf(modes[0]);
    ref.sampler.wrapT = wrapOf(modes[1]);
    if (ref.present()) return ref;
  }
  return ref;
}

// FBX and Collada materials are Phong-style: a diffuse colour and map, a
// specular map, a shininess; mapped onto metallic-roughness.
Material convertMaterial(const aiScene* scene, const aiMaterial* m, int index, const std::string& modelPath,
                         std::map<std::string, int>& imageOfPath, Character& character) {
  Material material;
  aiString name;
  material.name = m->Get(AI_MATKEY_NAME, name) == AI_SUCCESS && name.length > 0 ? repairedUtf8(name.C_Str())
                                                                                : "material" + std::to_string(index);
  aiColor4D diffuse(0.8f, 0.8f, 0.8f, 1.0f);
  m->Get(AI_MATKEY_COLOR_DIFFUSE, diffuse);
  float opacity = 1.0f;
  m->Get(AI_MATKEY_OPACITY, opacity);
  // Authoring tools show these colours as picked on screen, so sRGB.
  material.baseColorFactor = {srgbToLinear(diffuse.r), srgbToLinear(diffuse.g), srgbToLinear(diffuse.b),
                              std::clamp(opacity, 0.0f, 1.0f)};
  if (material.baseColorFactor.w < 1.0f) material.alphaMode = AlphaMode::Blend;
  material.metallicFactor = 0.0f;
  float shininess = 0.0f;
  // Blinn-Phong exponent to roughness: alpha^2 = 2 / (n + 2), roughness = sqrt(alpha).
  material.roughnessFactor = m->Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && shininess > 0.0f
                                 ? std::sqrt(std::sqrt(2.0f / (shininess + 2.0f)))
                                 : 0.8f;
  int twoSided = 0;
  if (m->Get(AI_MATKEY_TWOSIDED, twoSided) == AI_SUCCESS) material.doubleSided = twoSided != 0;
  material.baseColorTexture =
      textureOf(scene, m, {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}, modelPath, imageOfPath, character);
  material.normalTexture =
      textureOf(scene, m, {aiTextureType_NORMAL_CAMERA, aiTextureType_NORMALS}, modelPath, imageOfPath, character);
  material.specularTexture = textureOf(scene, m, {aiTextureType_SPECULAR}, modelPath, imageOfPath, character);
  material.emissiveTexture = textureOf(scene, m, {aiTextureType_EMISSIVE}, modelPath, imageOfPath, character);
  if (material.emissiveTexture.present()) material.emissiveFactor = glm::vec3(1.0f);
  return material;
}

void convertMaterials(const aiScene* scene, const std::string& modelPath, Character& character) {
  std::map<std::string, int> imageOfPath;
  for (unsigned i = 0; i < scene->mNumMaterials; ++i)
    character.materials.push_back(
        convertMaterial(scene, scene->mMaterials[i], static_cast<int>(i), modelPath, imageOfPath, character));
}

// A static mesh carries no unit. A person is 1 to 2.2 m tall and a head 0.15
// to 0.35 m: a height outside both as metres, that one of the usual units
// would bring inside, is worth a notice (MakeHuman exports in decimetres).
void noteUnlikelyUnits(Character& character) {
  Aabb box;
  for (const Mesh& m : character.meshes) {
    const Aabb b = boundsOf(m.positions);
    if (b.valid()) box.extend(b.min), box.extend(b.max);
  }
  if (!box.valid()) return;
  const float height = box.max.y - box.min.y;
  auto humanSized = [](float metres) {
    return (metres >= 1.0f && metres <= 2.2f) || (metres >= 0.15f && metres <= 0.35f);
  };
  if (humanSized(height)) return;
  std::string guesses;
  for (const auto& [unit, factor] : {std::pair{"decimetres", 0.1f}, {"centimetres", 0.01f}, {"millimetres", 0.001f}})
    if (humanSized(height * factor)) {
      char line[160];
      std::snprintf(line, sizeof line, "%s%s (--scale %g makes it %.2f m)", guesses.empty() ? "" : " or ", unit, factor,
                    height * factor);
      guesses += line;
    }
  if (guesses.empty()) return;
  char text[96];
  std::snprintf(text, sizeof text, "the mesh is %.3g units tall, not a person's or a head's height in metres", height);
  character.unitNotice = character.sourcePath + ": " + text + "; its units may be " + guesses;
}

Clip resolveClip(const RawClip& raw, const NodeTable& t) {
  Clip clip;
  clip.name = raw.name;
  for (const NodeChannel& nc : raw.channels) {
    const int bone = t.boneOfNode[nc.node];
    if (bone < 0) continue;  // keeps its rest value: folded into parentFromOffset
    clip.boneChannels.push_back({bone, nc.translation, nc.rotation, nc.scale});
  }
  return clip;
}

}  // namespace

Character importWithAssimp(const std::string& path) {
  Assimp::Importer importer;
  std::string colladaText;
  const aiScene* scene = readScene(importer, path, colladaText);
  Character character;
  character.name = std::filesystem::path(path).stem().string();
  character.sourcePath = path;
  NodeTable table;
  table.collect(scene->mRootNode, -1);

  const ColladaExtras collada = readColladaExtras(colladaText, path);
  std::vector<RawClip> clips;
  for (const ColladaClip& c : collada.clips) clips.push_back(convertColladaClip(c, table, path));
  if (clips.empty())
    for (unsigned a = 0; a < scene->mNumAnimations; ++a)
      clips.push_back(convertAnimation(scene->mAnimations[a], table, static_cast<int>(a), path));
  character.skeleton = buildSkeleton(scene, clips, collada.jointNodes, table, path);

  convertMaterials(scene, path, character);
  const bool bindFromNodes = fileExtension(path) == "fbx";
  for (size_t n = 0; n < table.nodes.size(); ++n) {
    const aiNode* node = table.nodes[n];
    for (unsigned m = 0; m < node->mNumMeshes; ++m) {
      if (node->mMeshes[m] >= scene->mNumMeshes) throw FileError(path, "node refers to a missing mesh");
      const aiMesh* am = scene->mMeshes[node->mMeshes[m]];
      character.meshes.push_back(convertMesh(am, table, static_cast<int>(n), bindFromNodes));
      if (am->mMaterialIndex < character.materials.size())
        character.meshes.back().material = static_cast<int>(am->mMaterialIndex);
    }
  }
  character.addMissingTangents();
  if (character.skeleton.boneCount() == 0) noteUnlikelyUnits(character);
  for (const RawClip& raw : clips) character.clips.push_back(resolveClip(raw, table));
  try {
    character.validate();
  } catch (const std::runtime_error& e) {
    throw FileError(path, e.what());
  }
  return character;
}

}  // namespace mq
