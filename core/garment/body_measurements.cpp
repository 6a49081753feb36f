#include "core/garment/body_measurements.h"

#include <algorithm>
#include <cmath>

#include "core/character/auto_rig.h"
#include "core/character/character.h"
#include "core/character/posed_character.h"
#include "core/skeleton/humanoid_roles.h"
#include "core/util/error.h"

namespace mq {
namespace {

struct RestBody {
  std::vector<glm::mat4> world;
  std::vector<glm::vec3> positions;  // all meshes
  std::vector<int> dominantBone;
};

RestBody restBody(const Character& character) {
  PosedCharacter rest;
  rest.evaluate(character, -1, 0.0f, nullptr, nullptr);
  RestBody body;
  body.world = rest.worldFromBone();
  for (size_t m = 0; m < character.meshes.size(); ++m) {
    const Mesh& mesh = character.meshes[m];
    const std::vector<float>& p = rest.meshes()[m].positions;
    const SkinBinding& skin = mesh.skin;
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
      body.positions.push_back({p[3 * v], p[3 * v + 1], p[3 * v + 2]});
      int bone = mesh.attachBone;
      float best = 0.0f;
      for (int i = 0; i < skin.influencesPerVertex; ++i) {
        float w = skin.weights[v * skin.influencesPerVertex + i];
        if (w > best) best = w, bone = skin.jointBones[skin.joints[v * skin.influencesPerVertex + i]];
      }
      body.dominantBone.push_back(bone);
    }
  }
  return body;
}

// Ramanujan's approximation of an ellipse's perimeter.
float ellipsePerimeter(float a, float b) {
  float h = (a - b) * (a - b) / std::max((a + b) * (a + b), 1e-12f);
  return float(M_PI) * (a + b) * (1.0f + 3.0f * h / (10.0f + std::sqrt(4.0f - 3.0f * h)));
}

// Girth of the slice of skin across `axis` at `center`, from the vertices of
// `bones`: an ellipse through the slice's extents along e1 and e2.
float girth(const RestBody& body, const std::vector<int>& bones, glm::vec3 center, glm::vec3 axis, glm::vec3 e1) {
  e1 = glm::normalize(e1 - glm::dot(e1, axis) * axis);
  glm::vec3 e2 = glm::cross(axis, e1);
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (size_t v = 0; v < body.positions.size(); ++v) {
    if (std::find(bones.begin(), bones.end(), body.dominantBone[v]) == bones.end()) continue;
    glm::vec3 d = body.positions[v] - center;
    if (std::abs(glm::dot(d, axis)) > 0.012f) continue;
    glm::vec2 q(glm::dot(d, e1), glm::dot(d, e2));
    lo = glm::min(lo, q), hi = glm::max(hi, q);
  }
  if (lo.x > hi.x) return 0.0f;
  return ellipsePerimeter(0.5f * (hi.x - lo.x), 0.5f * (hi.y - lo.y));
}

}  // namespace

glm::vec3 BodyMeasurements::torsoAxisAt(float y) const {
  return {0.5f * (pelvis.x + chest.x), y, 0.5f * (pelvis.z + chest.z)};
}

BodyMeasurements measureBody(const Character& character) {
  if (character.skeleton.boneCount() == 0) {  // a static mesh: measured on its auto-rig
    Character rigged = character;
    try {
      autoRigHumanoid(rigged, /*blend=*/false);  // each vertex's region is what is measured
    } catch (const Error& e) {
      throw Error("character '" + character.name + "' has no skeleton, and " + e.what());
    }
    return measureBody(rigged);
  }
  const Skeleton& skeleton = character.skeleton;
  RestBody body = restBody(character);
  HumanoidBones roles;
  try {
    roles = findHumanoidBones(skeleton, body.world);
  } catch (const Error& e) {
    throw Error("character '" + character.name + "': " + e.what());
  }
  if (glm::length(roles.facing) > 0.0f && roles.facing.z < 0.5f)
    throw Error("character '" + character.name + "' does not face +Z (its toes point to (" +
                std::to_string(roles.facing.x) + ", " + std::to_string(roles.facing.z) +
                ")): the built-in garments are made for a character facing +Z with its left on +X");
  auto joint = [&](int b) { return glm::vec3(body.world[b][3]); };

  BodyMeasurements m;
  const int pelvis = roles.pelvis, spine = roles.spine, chest = roles.chest;
  m.pelvis = joint(pelvis), m.waist = joint(spine), m.chest = joint(chest), m.neck = joint(roles.neck);
  m.spineBone = skeleton.bone(spine).name;
  const int* upperArm = roles.upperArm;
  const int* thigh = roles.thigh;
  for (int s = 0; s < 2; ++s) {
    m.upperArmBone[s] = skeleton.bone(upperArm[s]).name;
    m.shoulder[s] = joint(upperArm[s]), m.elbow[s] = joint(roles.forearm[s]), m.wrist[s] = joint(roles.hand[s]);
    m.hip[s] = joint(thigh[s]), m.knee[s] = joint(roles.shin[s]), m.ankle[s] = joint(roles.foot[s]);
  }
  glm::vec3 up(0, 1, 0), across(1, 0, 0);
  // A third of the way from chest to neck joint, but at least a fifth of the
  // way from shoulders to hips below the shoulders (a chest joint at the
  // shoulders' height, as on CesiumMan, would measure the neck's base).
  const float shoulderY = 0.5f * (m.shoulder[0].y + m.shoulder[1].y), hipY0 = 0.5f * (m.hip[0].y + m.hip[1].y);
  float chestY = std::min(glm::mix(m.chest.y, m.neck.y, 0.35f), shoulderY - 0.2f * (shoulderY - hipY0));
  m.chestGirth = girth(body, {chest, spine}, m.torsoAxisAt(chestY), up, across);
  m.waistGirth = girth(body, {spine, pelvis}, m.torsoAxisAt(m.waist.y), up, across);
  float hipY = m.hip[0].y - 0.03f;
  m.hipGirth = girth(body, {pelvis, thigh[0], thigh[1]}, m.torsoAxisAt(hipY), up, across);
  // A body widest above its hip joints (a belly, as on CesiumMan): the hips
  // are that wide, or a skirt or trousers sized to them slide up the body.
  for (float y = hipY + 0.01f; y < m.waist.y; y += 0.01f)
    m.hipGirth = std::max(m.hipGirth, girth(body, {pelvis, spine, thigh[0], thigh[1]}, m.torsoAxisAt(y), up, across));
  glm::vec3 armAxis = glm::normalize(m.elbow[0] - m.shoulder[0]);
  m.upperArmGirth = girth(body, {upperArm[0]}, glm::mix(m.shoulder[0], m.elbow[0], 0.3f), armAxis, {0, 0, 1});
  glm::vec3 legAxis = glm::normalize(m.knee[0] - m.hip[0]);
  m.thighGirth = girth(body, {thigh[0]}, glm::mix(m.hip[0], m.knee[0], 0.25f), legAxis, {1, 0, 0});
  // Bones of the neck and above (index + 1: a vertex without bone is -1).
  std::vector<bool> headOrNeck(skeleton.boneCount() + 1, false);
  for (int b = 0; b < skeleton.boneCount(); ++b)
    for (int a = b; a >= 0 && !headOrNeck[b + 1]; a = skeleton.bone(a).parent) headOrNeck[b + 1] = a == roles.neck;
  for (int s = 0; s < 2; ++s) {
    const glm::vec3 axis = m.torsoAxisAt(m.shoulder[s].y);
    const float inner = 0.5f * std::abs(m.shoulder[s].x - axis.x), outer = 2.0f * inner;
    m.shoulderTop[s] = m.shoulder[s].y;
    for (size_t v = 0; v < body.positions.size(); ++v) {
      const glm::vec3& p = body.positions[v];
      if (headOrNeck[body.dominantBone[v] + 1]) continue;  // a big head close to the shoulders
      const float across = (p.x - axis.x) * (m.shoulder[s].x > axis.x ? 1.0f : -1.0f);
      if (across >= inner && across <= outer && std::abs(p.z - axis.z) < 0.05f && p.y < m.shoulder[s].y + 0.3f)
        m.shoulderTop[s] = std::max(m.shoulderTop[s], p.y);
    }
  }
  {
    const float hipY = std::min(m.hip[0].y, m.hip[1].y), kneeY = std::max(m.knee[0].y, m.knee[1].y);
    const glm::vec3 axis = m.torsoAxisAt(hipY);
    m.crotchY = hipY;
    bool found = false;
    for (const glm::vec3& p : body.positions)
      if (std::abs(p.x - axis.x) < 0.015f && p.y < hipY && p.y > kneeY && (!found || p.y < m.crotchY))
        m.crotchY = p.y, found = true;
    if (!found) m.crotchY = hipY - 0.07f;
  }
  // A skeleton without skin: proportions of the stature (ISO 8559 averages).
  float stature = std::max(m.neck.y / 0.82f, 1.0f);
  if (m.chestGirth <= 0.0f) m.chestGirth = 0.55f * stature;
  if (m.waistGirth <= 0.0f) m.waistGirth = 0.47f * stature;
  if (m.hipGirth <= 0.0f) m.hipGirth = 0.56f * stature;
  if (m.upperArmGirth <= 0.0f) m.upperArmGirth = 0.17f * stature;
  if (m.thighGirth <= 0.0f) m.thighGirth = 0.32f * stature;
  m.capsules = fitBodyCapsules(character);
  return m;
}

}  // namespace mq
