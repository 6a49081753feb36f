#include "core/garment/body_capsules.h"

#include <algorithm>
#include <cmath>

#include "core/character/character.h"
#include "core/character/posed_character.h"

namespace mq {
namespace {

// Number of bones below `bone` (itself excluded).
int descendants(const Skeleton& skeleton, int bone) {
  int count = 0;
  for (int child : skeleton.children(bone)) count += 1 + descendants(skeleton, child);
  return count;
}

// Unit direction of a bone: towards the child with the largest subtree, else
// away from its parent, else up.
glm::vec3 boneDirection(const Skeleton& skeleton, const std::vector<glm::mat4>& world, int bone) {
  glm::vec3 head(world[bone][3]);
  int best = -1, bestSize = -1;
  for (int child : skeleton.children(bone)) {
    int size = descendants(skeleton, child);
    glm::vec3 d = glm::vec3(world[child][3]) - head;
    if (size > bestSize && glm::length(d) > 1e-4f) best = child, bestSize = size;
  }
  if (best >= 0) return glm::normalize(glm::vec3(world[best][3]) - head);
  int parent = skeleton.bone(bone).parent;
  if (parent >= 0) {
    glm::vec3 d = head - glm::vec3(world[parent][3]);
    if (glm::length(d) > 1e-4f) return glm::normalize(d);
  }
  return {0.0f, 1.0f, 0.0f};
}

// The skeleton bone each vertex follows most.
std::vector<int> dominantBones(const Mesh& mesh) {
  std::vector<int> bones(mesh.vertexCount(), mesh.attachBone);
  const SkinBinding& skin = mesh.skin;
  if (skin.empty()) return bones;
  int k = skin.influencesPerVertex;
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    float best = 0.0f;
    for (int i = 0; i < k; ++i) {
      float w = skin.weights[v * k + i];
      if (w > best) best = w, bones[v] = skin.jointBones[skin.joints[v * k + i]];
    }
  }
  return bones;
}

}  // namespace

float BodyCapsule::distance(const glm::vec3& p) const {
  glm::vec3 ab = b - a;
  float lengthSquared = glm::dot(ab, ab);
  float t = lengthSquared > 0.0f ? std::clamp(glm::dot(p - a, ab) / lengthSquared, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * ab)) - radius;
}

namespace {

// The smallest capsule (by volume) along `direction` through `head` that
// encloses `points`: the segment's ends are pulled in from the points'
// extent by a search over a few fractions, the radius is the farthest point.
BodyCapsule tightCapsule(const std::vector<glm::vec3>& points, glm::vec3 head, glm::vec3 direction) {
  float tMin = 1e30f, tMax = -1e30f;
  for (const glm::vec3& p : points) {
    float t = glm::dot(p - head, direction);
    tMin = std::min(tMin, t), tMax = std::max(tMax, t);
  }
  BodyCapsule best;
  float bestVolume = 1e30f;
  constexpr int kSteps = 8;
  float extent = tMax - tMin;
  for (int i = 0; i < kSteps; ++i) {
    for (int j = 0; j < kSteps; ++j) {
      float t0 = tMin + 0.5f * extent * float(i) / kSteps, t1 = tMax - 0.5f * extent * float(j) / kSteps;
      BodyCapsule c;
      c.a = head + t0 * direction, c.b = head + std::max(t1, t0) * direction;
      for (const glm::vec3& p : points) c.radius = std::max(c.radius, c.distance(p) + c.radius);
      float r = c.radius, length = glm::length(c.b - c.a);
      float volume = 3.14159265f * r * r * (length + 4.0f / 3.0f * r);
      if (volume < bestVolume) bestVolume = volume, best = c;
    }
  }
  return best;
}

}  // namespace

std::vector<BodyCapsule> fitBodyCapsules(const Character& character, int minVertices) {
  PosedCharacter rest;
  rest.evaluate(character, -1, 0.0f, nullptr, nullptr);
  const Skeleton& skeleton = character.skeleton;
  const std::vector<glm::mat4>& world = rest.worldFromBone();
  std::vector<std::vector<glm::vec3>> pointsOf(skeleton.boneCount());
  for (size_t m = 0; m < character.meshes.size(); ++m) {
    std::vector<int> bones = dominantBones(character.meshes[m]);
    const std::vector<float>& positions = rest.meshes()[m].positions;
    for (size_t v = 0; v < bones.size(); ++v)
      if (bones[v] >= 0) pointsOf[bones[v]].push_back({positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]});
  }
  std::vector<BodyCapsule> capsules;
  for (int b = 0; b < skeleton.boneCount(); ++b) {
    if (int(pointsOf[b].size()) < minVertices) continue;
    BodyCapsule c = tightCapsule(pointsOf[b], glm::vec3(world[b][3]), boneDirection(skeleton, world, b));
    c.bone = b;
    c.boneName = skeleton.bone(b).name;
    capsules.push_back(c);
  }
  return capsules;
}

const BodyCapsule* findCapsule(const std::vector<BodyCapsule>& capsules, const std::string& boneName) {
  for (const BodyCapsule& c : capsules)
    if (c.boneName == boneName) return &c;
  return nullptr;
}

float distanceToCapsules(const std::vector<BodyCapsule>& capsules, const glm::vec3& p) {
  float nearest = 1e30f;
  for (const BodyCapsule& c : capsules) nearest = std::min(nearest, c.distance(p));
  return nearest;
}

}  // namespace mq
