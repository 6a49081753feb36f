#include "core/character/auto_rig.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/character/posed_character.h"
#include "core/skeleton/skeleton_from_joints.h"
#include "core/skinning/weight_regeneration.h"
#include "core/util/error.h"

namespace mq {
namespace {

// Fractions of the stature (Drillis and Contini) where the mesh cannot tell.
constexpr float kAnkle = 0.045f, kLowerShin = 0.09f;
constexpr float kLegReach = 0.15f;               // a leg's vertices lie within this of the midline
constexpr float kArmStart = 0.18f;               // farther from the midline than this, above the knees: the arm
constexpr float kBand = 0.015f;                  // half the height of a cross-section
constexpr float kStep = 0.005f;                  // of a scan along the body or the arm
constexpr float kElbow = 0.40f, kWrist = 0.75f;  // along shoulder -> fingertip (the mannequin's arm)
// Along the spine, from the hip joints (0) to the shoulders (1): the mannequin's.
constexpr float kPelvis = 0.08f, kSpine = 0.28f, kChest = 0.59f;

struct Body {
  std::vector<glm::vec3> points;
  float floor = 0.0f, height = 0.0f, midX = 0.0f, midZ = 0.0f;
  float y(float fraction) const { return floor + fraction * height; }
};

float median(std::vector<float> values) {
  if (values.empty()) return 0.0f;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// The centroid of the points in a horizontal band around height `y` that
// `keep` accepts; `fallback` when none does.
template <typename Keep>
glm::vec3 bandCentre(const Body& body, float y, Keep keep, glm::vec3 fallback) {
  glm::vec3 sum(0.0f);
  int n = 0;
  for (const glm::vec3& p : body.points)
    if (std::abs(p.y - y) <= kBand * body.height && keep(p)) sum += p, ++n;
  return n > 0 ? glm::vec3(sum.x / n, y, sum.z / n) : fallback;
}

Body measureStance(const Character& character) {
  PosedCharacter rest;
  rest.evaluate(character, -1, 0.0f, nullptr, nullptr);
  Body body;
  float top = -1e30f;
  body.floor = 1e30f;
  for (const PosedMesh& mesh : rest.meshes())
    for (size_t k = 0; k + 2 < mesh.positions.size(); k += 3) {
      body.points.emplace_back(mesh.positions[k], mesh.positions[k + 1], mesh.positions[k + 2]);
      body.floor = std::min(body.floor, mesh.positions[k + 1]);
      top = std::max(top, mesh.positions[k + 1]);
    }
  body.height = top - body.floor;
  if (body.points.size() < 100 || !(body.height > 1.0f))
    throw Error("'" + character.name + "' is " + std::to_string(body.height) +
                " m tall: too short for a standing person (scale it to metres first)");
  constexpr float kTorso = 0.6f;  // every stance has the torso at 0.6 of the height
  std::vector<float> xs, zs;
  for (const glm::vec3& p : body.points)
    if (std::abs(p.y - body.y(kTorso)) <= 3 * kBand * body.height) xs.push_back(p.x);
  body.midX = median(xs);
  for (const glm::vec3& p : body.points)
    if (std::abs(p.y - body.y(kTorso)) <= 3 * kBand * body.height && std::abs(p.x - body.midX) < 0.08f * body.height)
      zs.push_back(p.z);
  body.midZ = median(zs);
  return body;
}

// The joint nearest `guess` centred in the limb: the centroid of the points
// within `reach` of the line through it along `axis`, in a slab across it.
glm::vec3 centreAcross(const Body& body, glm::vec3 guess, glm::vec3 axis, float reach) {
  glm::vec3 sum(0.0f);
  int n = 0;
  for (const glm::vec3& p : body.points) {
    const glm::vec3 d = p - guess;
    const float along = glm::dot(d, axis);
    if (std::abs(along) <= kBand * body.height && glm::length(d - along * axis) <= reach) sum += p, ++n;
  }
  return n > 0 ? sum / float(n) : guess;
}

struct Arm {
  glm::vec3 shoulder, elbow, wrist, tip;
};

// The arm's axis through its vertices' centroid (their principal direction,
// pointing out of the body) and its fingertip (the farthest vertex out).
struct ArmAxis {
  glm::vec3 centre{0.0f}, direction{0.0f}, tip{0.0f};
};

ArmAxis armAxis(const Body& body, float side, const std::string& name) {
  const float h = body.height;
  std::vector<glm::vec3> arm;
  for (const glm::vec3& p : body.points)
    if (side * (p.x - body.midX) > kArmStart * h && p.y > body.y(0.35f)) arm.push_back(p);
  if (arm.size() < 20)
    throw Error("'" + name + "' holds its arms along its body: the auto-rig needs them away from it (A or T pose)");
  ArmAxis axis;
  for (const glm::vec3& p : arm) axis.centre += p / float(arm.size());
  glm::mat3 covariance(0.0f);
  for (const glm::vec3& p : arm) covariance += glm::outerProduct(p - axis.centre, p - axis.centre);
  glm::vec3 d(side, 0.0f, 0.0f);  // power iteration from the outward guess
  for (int i = 0; i < 32; ++i) d = glm::normalize(covariance * d);
  axis.direction = side * d.x < 0.0f ? -d : d;
  float farthest = -1e30f;
  for (const glm::vec3& p : arm)
    if (glm::dot(p - axis.centre, axis.direction) > farthest)
      farthest = glm::dot(p - axis.centre, axis.direction), axis.tip = p;
  return axis;
}

// The vertices in a slab across the arm's axis at `t`, within `reach` of the
// axis: their largest distance from it, and the nearest of them beyond
// `beyond` (the torso's first point, once it enters the slab).
struct Slab {
  float radius = 0.0f;
  float nearestBeyond = 1e30f;
  glm::vec3 contact{0.0f};
};

Slab slabAt(const Body& body, const ArmAxis& axis, float t, float reach, float beyond) {
  const glm::vec3 at = axis.centre + t * axis.direction;
  Slab slab;
  for (const glm::vec3& p : body.points) {
    const glm::vec3 d = p - at;
    const float along = glm::dot(d, axis.direction);
    if (std::abs(along) > kBand * body.height) continue;
    const float across = glm::length(d - along * axis.direction);
    if (across > reach) continue;
    slab.radius = std::max(slab.radius, across);
    if (across > beyond && across < slab.nearestBeyond) slab.nearestBeyond = across, slab.contact = p;
  }
  return slab;
}

Arm findArm(const Body& body, float side, const std::string& name) {
  const float h = body.height;
  const ArmAxis axis = armAxis(body, side, name);
  // From the fingertip inwards, the slab holds the arm alone until the
  // torso enters it under the armpit. The shoulder joint is on the arm's
  // axis, straight above (or beside) that first point of the torso.
  const float tipT = glm::dot(axis.tip - axis.centre, axis.direction);
  const float reach = 0.1f * h;  // twice a thick arm's radius
  std::vector<float> radii;
  std::vector<glm::vec3> centres;  // of the arm's slabs, tip first
  Arm arm;
  arm.tip = axis.tip;
  arm.shoulder = axis.centre + (tipT - 0.42f * h) * axis.direction;  // the mannequin's arm, when no torso shows
  for (float t = tipT - 0.1f * h; t > tipT - 0.6f * h; t -= kStep * h) {
    std::vector<float> sorted = radii;
    const float typical = radii.size() >= 8 ? median(sorted) : 1e30f;
    const Slab slab = slabAt(body, axis, t, reach, 1.5f * typical);
    if (slab.radius > 1.8f * typical && centres.size() >= 8) {
      // The upper arm's own axis, through its last slabs' centres, carried to the torso's first point.
      const glm::vec3 a = centres[centres.size() - 8], b = centres.back();
      const glm::vec3 d = glm::normalize(b - a);
      const float along = std::abs(d.x) > 0.2f ? (slab.contact.x - b.x) / d.x : 0.0f;
      arm.shoulder = b + std::max(along, 0.0f) * d;
      break;
    }
    radii.push_back(slab.radius);
    centres.push_back(centreAcross(body, axis.centre + t * axis.direction, axis.direction, 1.3f * slab.radius));
  }
  const glm::vec3 out = glm::normalize(arm.tip - arm.shoulder);
  const float length = glm::length(arm.tip - arm.shoulder);
  arm.elbow = centreAcross(body, arm.shoulder + kElbow * length * out, out, 0.06f * h);
  arm.wrist = centreAcross(body, arm.shoulder + kWrist * length * out, out, 0.06f * h);
  return arm;
}

// The crotch: scanning up from the shins, the first height where the mesh
// crosses the midline between the legs.
float crotchHeight(const Body& body) {
  const float h = body.height;
  for (float f = 0.15f; f < 0.8f; f += kStep) {
    int onMidline = 0;
    for (const glm::vec3& p : body.points)
      onMidline += std::abs(p.y - body.y(f)) <= kStep * h && std::abs(p.x - body.midX) < 0.006f * h;
    if (onMidline >= 3) return body.y(f);
  }
  return body.y(0.47f);
}

// The hip joints: at the widest the hips are (the greater trochanters),
// within a tenth of the height above the crotch; arms are out of reach.
float hipHeight(const Body& body, float crotchY) {
  const float h = body.height;
  float best = crotchY + 0.05f * h, widest = -1.0f;
  for (float y = crotchY; y < crotchY + 0.1f * h; y += kStep * h) {
    float lo = 1e30f, hi = -1e30f;
    for (const glm::vec3& p : body.points)
      if (std::abs(p.y - y) <= kStep * h && std::abs(p.x - body.midX) < kLegReach * h)
        lo = std::min(lo, p.x), hi = std::max(hi, p.x);
    if (hi > lo && hi - lo > widest + 1e-4f * h) widest = hi - lo, best = y;
  }
  return best;
}

// The neck: the narrowest cross-section between the shoulders and the top.
float neckHeight(const Body& body, float shoulderY) {
  const float h = body.height;
  float best = shoulderY + 0.05f * h, narrowest = 1e30f;
  for (float y = shoulderY + 0.02f * h; y < body.floor + 0.95f * h; y += kStep * h) {
    float lo = 1e30f, hi = -1e30f;
    for (const glm::vec3& p : body.points)
      if (std::abs(p.y - y) <= kStep * h && std::abs(p.x - body.midX) < 0.15f * h)
        lo = std::min(lo, p.x), hi = std::max(hi, p.x);
    if (hi > lo && hi - lo < narrowest) narrowest = hi - lo, best = y;
  }
  return best;
}

std::vector<JointSpec> jointsOf(const Body& body, const std::string& name) {
  const float h = body.height;
  auto midline = [&](float y) {
    return bandCentre(
        body, y, [&](const glm::vec3& p) { return std::abs(p.x - body.midX) < 0.08f * h; },
        glm::vec3(body.midX, y, body.midZ));
  };
  Arm arms[2] = {findArm(body, 1.0f, name), findArm(body, -1.0f, name)};  // the character's left is +X
  const float shoulderY = 0.5f * (arms[0].shoulder.y + arms[1].shoulder.y);
  for (Arm& arm : arms) arm.shoulder.z = midline(arm.shoulder.y).z;  // in the torso's plane
  const float hipY = hipHeight(body, crotchHeight(body));
  const float neckY = neckHeight(body, shoulderY);
  auto alongSpine = [&](float f) { return midline(hipY + f * (shoulderY - hipY)); };
  const glm::vec3 neck = midline(shoulderY + 0.015f * h), headBase = midline(neckY + 0.02f * h);
  const glm::vec3 top(headBase.x, body.floor + h, headBase.z);
  std::vector<JointSpec> joints = {
      {"pelvis", "", alongSpine(kPelvis), alongSpine(kSpine)},
      {"spine", "pelvis", alongSpine(kSpine), alongSpine(kChest)},
      {"chest", "spine", alongSpine(kChest), neck},
      {"neck", "chest", neck, headBase},
      {"head", "neck", headBase, top},
  };
  for (int i = 0; i < 2; ++i) {
    const float side = i == 0 ? 1.0f : -1.0f;
    const std::string s = i == 0 ? "_l" : "_r";
    auto leg = [&](float y) {
      return bandCentre(
          body, y,
          [&](const glm::vec3& p) {
            return side * (p.x - body.midX) > 0.0f && side * (p.x - body.midX) < kLegReach * h;
          },
          glm::vec3(body.midX + side * 0.05f * h, y, body.midZ));
    };
    glm::vec3 hip = leg(hipY - 0.08f * h);
    hip.y = hipY;
    glm::vec3 ankle = leg(body.y(kLowerShin));
    ankle.y = body.y(kAnkle);
    const glm::vec3 knee = leg(0.5f * (hipY + ankle.y));
    glm::vec3 toe = ankle;  // the foot's farthest point forward
    for (const glm::vec3& p : body.points)
      if (p.y < body.y(kLowerShin) && side * (p.x - body.midX) > 0.0f && side * (p.x - body.midX) < kLegReach * h &&
          p.z > toe.z)
        toe = p;
    toe.y = body.floor + 0.012f * h;
    const glm::vec3 ball = glm::mix(ankle, toe, 0.65f);
    const glm::vec3 ballOnFloor(ball.x, body.floor + 0.015f * h, ball.z);
    const Arm& arm = arms[i];
    const glm::vec3 clavicleRoot(body.midX + side * 0.012f * h, arm.shoulder.y, neck.z + 0.02f * h);
    joints.push_back({"clavicle" + s, "chest", clavicleRoot, arm.shoulder});
    joints.push_back({"upperarm" + s, "clavicle" + s, arm.shoulder, arm.elbow});
    joints.push_back({"forearm" + s, "upperarm" + s, arm.elbow, arm.wrist});
    joints.push_back({"hand" + s, "forearm" + s, arm.wrist, arm.tip});
    joints.push_back({"thigh" + s, "pelvis", hip, knee});
    joints.push_back({"shin" + s, "thigh" + s, knee, ankle});
    joints.push_back({"foot" + s, "shin" + s, ankle, ballOnFloor});
    joints.push_back({"toes" + s, "foot" + s, ballOnFloor, toe});
  }
  return joints;
}

// Distance from p to the segment ab.
float segmentDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 ab = b - a;
  const float t = glm::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-12f), 0.0f, 1.0f);
  return glm::length(p - (a + t * ab));
}

// The bone each vertex belongs to, by the region it lies in: the head and
// neck above their joints, an arm beyond its shoulder and near its axis, a
// leg below the hips on its side, the torso by height (a clavicle at the top
// corners). Regions, not nearest segments: a short bone (a clavicle) would
// otherwise take the jaw, and the garments measure each bone's vertices.
class RegionBinder {
 public:
  RegionBinder(const Body& body, const std::vector<JointSpec>& joints) : body_(body), joints_(joints) {}

  int boneOf(const glm::vec3& p) const {
    const float h = body_.height, x = p.x - body_.midX;
    const int side = x >= 0.0f ? 0 : 1;
    const char* s = side == 0 ? "_l" : "_r";
    if (const int arm = armBone(p, s); arm >= 0) return arm;
    if (p.y >= joint("head").head.y && std::abs(x) < 0.15f * h) return index("head");
    if (p.y >= joint("neck").head.y &&
        std::abs(x) < std::abs(joint(std::string("upperarm") + s).head.x - body_.midX) * 0.6f)
      return index("neck");
    const float hipY = std::min(joint("thigh_l").head.y, joint("thigh_r").head.y);
    if (p.y < hipY - 0.02f * h && std::abs(x) < kLegReach * h) return nearest(p, {"thigh", "shin", "foot", "toes"}, s);
    const JointSpec& chest = joint("chest");
    if (p.y >= chest.head.y + 0.6f * (chest.tail.y - chest.head.y) &&
        std::abs(x) > 0.5f * std::abs(joint(std::string("clavicle") + s).tail.x - body_.midX))
      return index(std::string("clavicle") + s);
    if (p.y < joint("spine").head.y) return index("pelvis");
    return p.y < chest.head.y ? index("spine") : index("chest");
  }

 private:
  int index(const std::string& name) const {
    for (size_t i = 0; i < joints_.size(); ++i)
      if (joints_[i].name == name) return int(i);
    throw Error("auto-rig: no joint named " + name);
  }
  const JointSpec& joint(const std::string& name) const { return joints_[index(name)]; }

  // The arm bone holding p, or -1 when p is not on that side's arm.
  int armBone(const glm::vec3& p, const char* s) const {
    const glm::vec3 shoulder = joint(std::string("upperarm") + s).head, tip = joint(std::string("hand") + s).tail;
    const glm::vec3 out = glm::normalize(tip - shoulder);
    const float u = glm::dot(p - shoulder, out);
    const float side = shoulder.x >= body_.midX ? 1.0f : -1.0f;
    if (u <= 0.0f || side * (p.x - shoulder.x) < -0.02f * body_.height) return -1;
    if (segmentDistance(p, shoulder, tip) > 0.06f * body_.height) return -1;
    const float elbow = glm::dot(joint(std::string("forearm") + s).head - shoulder, out);
    const float wrist = glm::dot(joint(std::string("hand") + s).head - shoulder, out);
    return index(std::string(u < elbow ? "upperarm" : u < wrist ? "forearm" : "hand") + s);
  }

  int nearest(const glm::vec3& p, std::initializer_list<const char*> names, const char* s) const {
    int best = -1;
    float bestDistance = 1e30f;
    for (const char* name : names) {
      const JointSpec& j = joint(std::string(name) + s);
      const float d = segmentDistance(p, j.head, j.tail);
      if (d < bestDistance) bestDistance = d, best = index(std::string(name) + s);
    }
    return best;
  }

  const Body& body_;
  const std::vector<JointSpec>& joints_;
};

void bindByRegions(Mesh& mesh, const Skeleton& skeleton, const RegionBinder& regions) {
  const size_t n = mesh.vertexCount();
  SkinBinding& skin = mesh.skin;
  skin = SkinBinding();
  skin.influencesPerVertex = 1;
  skin.inverseBind = skeleton.inverseBindMatrices();
  for (int b = 0; b < skeleton.boneCount(); ++b) skin.jointBones.push_back(b);
  skin.weights.assign(n, 1.0f);
  skin.joints.resize(n);
  for (size_t v = 0; v < n; ++v) skin.joints[v] = uint16_t(regions.boneOf(mesh.position(v)));
}

// Static meshes hold their placement in boneFromMesh: the skin wants world space.
void bakePlacement(Mesh& mesh) {
  if (mesh.boneFromMesh == glm::mat4(1.0f)) return;
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(mesh.boneFromMesh)));
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    const glm::vec3 p = glm::vec3(mesh.boneFromMesh * glm::vec4(mesh.position(v), 1.0f));
    for (int d = 0; d < 3; ++d) mesh.positions[3 * v + d] = p[d];
    if (mesh.normals.size() == mesh.positions.size()) {
      const glm::vec3 nrm = glm::normalize(
          normalMatrix * glm::vec3(mesh.normals[3 * v], mesh.normals[3 * v + 1], mesh.normals[3 * v + 2]));
      for (int d = 0; d < 3; ++d) mesh.normals[3 * v + d] = nrm[d];
    }
  }
  mesh.boneFromMesh = glm::mat4(1.0f);
}

}  // namespace

void autoRigHumanoid(Character& character, bool blend, ThreadPool* pool) {
  if (character.skeleton.boneCount() > 0)
    throw Error("'" + character.name + "' already has a skeleton (" + std::to_string(character.skeleton.boneCount()) +
                " bones)");
  if (character.meshes.empty()) throw Error("'" + character.name + "' has no mesh to rig");
  const Body body = measureStance(character);
  const std::vector<JointSpec> joints = jointsOf(body, character.name);
  character.skeleton = skeletonFromJoints(joints);
  const RegionBinder regions(body, joints);
  for (Mesh& mesh : character.meshes) {
    bakePlacement(mesh);
    mesh.attachBone = -1;
    bindByRegions(mesh, character.skeleton, regions);
    mesh.dropSkinningBindings();
  }
  if (!blend) return;
  WeightSettings settings;  // blended across the joints, as a skin to pose
  settings.smooth = true;
  regenerateWeights(character, settings, pool);
}

}  // namespace mq
