#include "core/hair/head_fit.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/character/posed_character.h"
#include "core/hair/static_head.h"
#include "core/util/error.h"

namespace mq {
namespace {

std::string lowercase(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool drivenBy(const Skeleton& skeleton, int bone, int ancestor) {
  for (int b = bone; b >= 0; b = skeleton.bone(b).parent)
    if (b == ancestor) return true;
  return false;
}

glm::vec3 vertexOf(const std::vector<float>& p, uint32_t v) { return {p[3 * v], p[3 * v + 1], p[3 * v + 2]}; }

bool hasTaggedScalp(const Character& character) {
  for (const Mesh& mesh : character.meshes)
    if (mesh.vertexTags.size() == mesh.vertexCount() &&
        std::find(mesh.vertexTags.begin(), mesh.vertexTags.end(), TagScalp) != mesh.vertexTags.end())
      return true;
  return false;
}

}  // namespace

float headSize(const BodyProxy& proxy) {
  if (proxy.ellipsoids.empty()) return 0.0f;
  const glm::vec3 r = proxy.ellipsoids[0].radii;
  return std::cbrt(r.x * r.y * r.z);
}

HairStyle scaledHairStyle(const HairStyle& style, float k) {
  HairStyle s = style;
  for (PointSource& p : s.primitives.sources) {
    p.position *= k;
    p.radius *= k;
    p.strength *= k;  // its speed falls as 1/distance^2: the same streamlines at k times the size
  }
  for (Vortex& v : s.primitives.vortices) {
    v.position *= k;
    v.radius *= k;  // speed depends on distance / radius alone
  }
  for (LengthPoint& p : s.lengthMap) {
    p.position *= k;
    p.radius *= k;
  }
  for (GroomStroke& stroke : s.strokes) {
    stroke.radius *= k;
    for (GroomDab& dab : stroke.dabs) {
      dab.position *= k;
      dab.motion *= k;
    }
  }
  s.noiseScale *= k;
  s.density /= k * k;
  s.length *= k;
  s.strandNoise *= k;
  s.waveAmplitude *= k;
  s.waveLength *= k;
  s.curlRadius *= k;
  s.curlLength *= k;
  s.frizz *= k;
  s.frizzFrequency /= k;
  return s;
}

HairStyle fitHairStyleToHead(const HairStyle& style, const BodyProxy& proxy) {
  const float size = headSize(proxy);
  if (!(size > 0.0f)) return style;
  const float scale = size / kReferenceHeadSize;
  return std::abs(scale - 1.0f) < 1e-3f ? style : scaledHairStyle(style, scale);
}

int findHeadBone(const Character& character) {
  const Skeleton& skeleton = character.skeleton;
  int named = -1;
  for (int b = 0; b < skeleton.boneCount(); ++b) {
    const std::string name = lowercase(skeleton.bone(b).name);
    if (name == "head") return b;
    if (named < 0 && name.find("head") != std::string::npos && name.find("end") == std::string::npos &&
        name.find("top") == std::string::npos)
      named = b;
  }
  if (named >= 0) return named;
  // The bone whose own vertices sit highest (at least a few of them).
  PosedCharacter rest;
  rest.evaluate(character, -1, 0.0f, nullptr, nullptr);
  std::vector<double> heightSum(skeleton.boneCount(), 0.0);
  std::vector<int> counts(skeleton.boneCount(), 0);
  for (size_t m = 0; m < character.meshes.size(); ++m)
    for (size_t v = 0; v < character.meshes[m].vertexCount(); ++v) {
      const int bone = dominantBone(character.meshes[m], v);
      if (bone < 0 || bone >= skeleton.boneCount()) continue;
      heightSum[bone] += rest.meshes()[m].positions[3 * v + 1];
      ++counts[bone];
    }
  int best = -1;
  for (int b = 0; b < skeleton.boneCount(); ++b)
    if (counts[b] >= 10 && (best < 0 || heightSum[b] / counts[b] > heightSum[best] / counts[best])) best = b;
  return best;
}

ScalpRegion automaticScalpRegion(const Character& character) {
  ScalpRegion region;
  const int head = findHeadBone(character);
  if (head >= 0) region.bone = character.skeleton.bone(head).name;
  if (hasTaggedScalp(character)) return region;
  if (character.meshes.empty()) throw Error("there is no character mesh to grow hair on");
  // The head's vertices: those the head bone drives, or for a mesh without
  // bones those at its top.
  const bool staticMesh = character.skeleton.boneCount() == 0;
  if (head < 0 && !staticMesh) throw Error("character '" + character.name + "' has no head bone to grow hair on");
  if (staticMesh) region.bone.clear();
  const std::vector<std::vector<uint8_t>> staticHead =
      staticMesh ? staticHeadVertices(character) : std::vector<std::vector<uint8_t>>{};
  auto isHead = [&](size_t m, uint32_t v) {
    return staticMesh ? staticHead[m][v] != 0
                      : drivenBy(character.skeleton, dominantBone(character.meshes[m], v), head);
  };
  PosedCharacter rest;
  rest.evaluate(character, -1, 0.0f, nullptr, nullptr);
  // The mesh with most of the head, and the centre of the head: of its
  // vertices, or for a static mesh of its box (a scan's face is meshed far
  // more densely than the back of its head, and would pull the centre, and
  // the hairline, down to the eyes).
  int bestMesh = -1;
  size_t bestCount = 0, total = 0;
  glm::dvec3 centreSum(0.0);
  Aabb box;
  for (size_t m = 0; m < character.meshes.size(); ++m) {
    size_t count = 0;
    for (uint32_t v = 0; v < character.meshes[m].vertexCount(); ++v)
      if (isHead(m, v)) {
        ++count;
        centreSum += glm::dvec3(vertexOf(rest.meshes()[m].positions, v));
        box.extend(vertexOf(rest.meshes()[m].positions, v));
      }
    total += count;
    if (count > bestCount) {
      bestCount = count;
      bestMesh = int(m);
    }
  }
  if (bestMesh < 0) throw Error("the head of character '" + character.name + "' has no vertex");
  const glm::vec3 centre = staticMesh ? box.center() : glm::vec3(centreSum / double(total));
  const float tilt = glm::radians(25.0f);
  const glm::vec3 axis(0.0f, std::cos(tilt), -std::sin(tilt));  // up and back: the character faces +Z
  const float cosLimit = std::cos(glm::radians(75.0f));
  const Mesh& mesh = character.meshes[bestMesh];
  const std::vector<float>& positions = rest.meshes()[bestMesh].positions;
  region.kind = ScalpRegion::Kind::Faces;
  region.mesh = bestMesh;
  for (uint32_t f = 0; f < mesh.triangleCount(); ++f) {
    bool onHead = true;
    glm::vec3 faceCentre(0.0f);
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.triangles[3 * f + k];
      onHead &= isHead(size_t(bestMesh), v);
      faceCentre += vertexOf(positions, v) / 3.0f;
    }
    const glm::vec3 d = faceCentre - centre;
    if (onHead && glm::dot(d, axis) >= cosLimit * glm::length(d)) region.faces.push_back(f);
  }
  if (region.faces.empty())
    throw Error("no face on the top of the head of character '" + character.name + "' to grow hair on");
  return region;
}

}  // namespace mq
