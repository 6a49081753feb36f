#include "core/skinning/helper_bones.h"

#include <algorithm>
#include <array>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "core/character/character.h"
#include "core/skeleton/humanoid_roles.h"
#include "core/util/error.h"

namespace mq {
namespace {

constexpr int kMaxInfluences = 4;

using Influences = std::vector<std::pair<int, float>>;  // skin joint, weight

std::vector<Influences> influencesOf(const SkinBinding& skin, size_t vertices) {
  std::vector<Influences> out(vertices);
  const int k = skin.influencesPerVertex;
  for (size_t v = 0; v < vertices; ++v)
    for (int i = 0; i < k; ++i)
      if (skin.weights[v * k + i] > 0.0f) out[v].push_back({skin.joints[v * k + i], skin.weights[v * k + i]});
  return out;
}

// Writes the influences back, the heaviest kMaxInfluences of each vertex,
// normalised.
void setInfluences(SkinBinding& skin, std::vector<Influences>& influences) {
  const int k = std::max(skin.influencesPerVertex, kMaxInfluences);
  skin.influencesPerVertex = k;
  skin.joints.assign(influences.size() * k, 0);
  skin.weights.assign(influences.size() * k, 0.0f);
  for (size_t v = 0; v < influences.size(); ++v) {
    Influences& list = influences[v];
    std::stable_sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    if (list.size() > size_t(kMaxInfluences)) list.resize(kMaxInfluences);
    for (size_t i = 0; i < list.size(); ++i) {
      skin.joints[v * k + i] = static_cast<uint16_t>(list[i].first);
      skin.weights[v * k + i] = list[i].second;
    }
  }
  skin.normalise();
}

float weightIn(const Influences& list, int joint) {
  for (const auto& [j, w] : list)
    if (j == joint) return w;
  return 0.0f;
}

void setWeight(Influences& list, int joint, float weight) {
  for (auto& [j, w] : list)
    if (j == joint) w = weight;
}

void addWeight(Influences& list, int joint, float delta) {
  for (auto& [j, w] : list)
    if (j == joint) {
      w += delta;
      return;
    }
  if (delta != 0.0f) list.push_back({joint, delta});
}

int jointOf(const SkinBinding& skin, int bone) {
  const auto it = std::find(skin.jointBones.begin(), skin.jointBones.end(), bone);
  return it == skin.jointBones.end() ? -1 : int(it - skin.jointBones.begin());
}

void dropEmpty(Influences& list) {
  list.erase(std::remove_if(list.begin(), list.end(), [](const auto& i) { return i.second <= 0.0f; }), list.end());
}

// A vertex shared by `parent` and `driver` moves onto the stages between
// them (parent, helpers[0..n), driver, turning by 0, 1/(n+1), ... 1 of the
// driver's rotation): its place t = driver / (parent + driver) falls between
// two stages, which share the pair's weight linearly. With one helper, a
// 50/50 vertex follows the half angle alone.
void moveToStages(std::vector<Influences>& influences, int parent, int driver, const std::vector<int>& helpers) {
  const int last = int(helpers.size()) + 1;
  auto jointOfStage = [&](int stage) { return stage == 0 ? parent : stage == last ? driver : helpers[stage - 1]; };
  for (Influences& list : influences) {
    const float p = weightIn(list, parent), d = weightIn(list, driver);
    if (p <= 0.0f || d <= 0.0f) continue;
    const float x = d / (p + d) * float(last);
    const int below = std::min(int(x), last - 1);
    const float upper = x - float(below);
    setWeight(list, parent, 0.0f);
    setWeight(list, driver, 0.0f);
    addWeight(list, jointOfStage(below), (p + d) * (1.0f - upper));
    addWeight(list, jointOfStage(below + 1), (p + d) * upper);
    dropEmpty(list);
  }
}

// Shares of the forearm (elbow), the twist joint at a third and the one at
// two thirds for a vertex at t along the forearm: linear between them, all
// on the second twist joint from two thirds on.
std::array<float, 3> twistShares(float t) {
  if (t < 1.0f / 3.0f) return {1.0f - 3.0f * t, 3.0f * t, 0.0f};
  if (t < 2.0f / 3.0f) return {0.0f, 1.0f - (3.0f * t - 1.0f), 3.0f * t - 1.0f};
  return {0.0f, 0.0f, 1.0f};
}

// The forearm's weight spread over the forearm and its twist joints by the
// vertex's place along the forearm.
void spreadOverTwist(const Mesh& mesh, std::vector<Influences>& influences, int forearm, const int twist[2],
                     const glm::mat4& forearmSkinAtRest, const glm::vec3& elbow, const glm::vec3& wrist) {
  const glm::vec3 axis = wrist - elbow;
  const float length2 = glm::dot(axis, axis);
  if (length2 <= 0.0f) return;
  for (size_t v = 0; v < influences.size(); ++v) {
    Influences& list = influences[v];
    const float total = weightIn(list, forearm);
    if (total <= 0.0f) continue;
    const glm::vec3 p(forearmSkinAtRest *
                      glm::vec4(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2], 1.0f));
    const std::array<float, 3> shares = twistShares(std::clamp(glm::dot(p - elbow, axis) / length2, 0.0f, 1.0f));
    setWeight(list, forearm, total * shares[0]);
    addWeight(list, twist[0], total * shares[1]);
    addWeight(list, twist[1], total * shares[2]);
    dropEmpty(list);
  }
}

// Elbow helpers: two, at a third and two thirds of the forearm's rotation,
// so that a forearm twisted half a turn keeps 0.75 of its section at the
// elbow under linear blending (one half-angle helper keeps 0.5).
constexpr int kElbowStages = 2;

class HelperBuilder {
 public:
  HelperBuilder(Character& character)
      : c_(character), restWorld_(character.skeleton.worldTransforms(character.skeleton.restPose())) {}

  int build(const HumanoidBones& roles) {
    for (int side = 0; side < 2; ++side) {
      addHalfAngle(roles.upperArm[side], roles.forearm[side], kElbowStages);
      addHalfAngle(roles.thigh[side], roles.shin[side]);
      addHalfAngle(c_.skeleton.bone(roles.thigh[side]).parent, roles.thigh[side]);
      addHalfAngle(c_.skeleton.bone(roles.upperArm[side]).parent, roles.upperArm[side]);
      addTwists(roles.forearm[side], roles.hand[side]);
    }
    for (Mesh& mesh : c_.meshes) mesh.dropSkinningBindings();
    return added_;
  }

 private:
  // `rest` and `parentFromOffset` may belong to a bone of the skeleton, which
  // adding a bone reallocates: only the copies in `bone` are used after that.
  int addBone(const std::string& name, int parent, const Trs& rest, const glm::mat4& parentFromOffset) {
    Bone bone;
    bone.name = name;
    bone.parent = parent;
    bone.rest = rest;
    bone.parentFromOffset = parentFromOffset;
    restWorld_.push_back((parent >= 0 ? restWorld_[parent] : glm::mat4(1.0f)) * bone.parentFromOffset *
                         bone.rest.matrix());
    const int index = c_.skeleton.addBone(std::move(bone));
    ++added_;
    return index;
  }

  // `stages` helpers at the joint turning 1/(stages+1), 2/(stages+1), ...
  // of the driver's rotation: "_half" for one, "_third1", "_third2" for two.
  void addHalfAngle(int parent, int driver, int stages = 1) {
    if (parent < 0 || driver < 0 || c_.skeleton.bone(driver).parent != parent) return;
    std::vector<int> bones;
    for (int i = 0; i < stages; ++i) {
      const Bone& d = c_.skeleton.bone(driver);  // addBone reallocates: look it up each time
      HelperBone helper;
      helper.kind = HelperBone::Kind::HalfAngle;
      helper.driver = driver;
      helper.share = float(i + 1) / float(stages + 1);
      const std::string suffix = stages == 1 ? "_half" : "_third" + std::to_string(i + 1);
      helper.bone = addBone(d.name + suffix, parent, d.rest, d.parentFromOffset);
      c_.helperBones.push_back(helper);
      bones.push_back(helper.bone);
    }
    for (Mesh& mesh : c_.meshes) {
      const int jp = jointOf(mesh.skin, parent), jd = jointOf(mesh.skin, driver);
      if (mesh.skin.empty() || jp < 0 || jd < 0) continue;
      // At rest the helpers sit where their driver does: same bind.
      std::vector<int> joints;
      for (int bone : bones) joints.push_back(addJoint(mesh.skin, bone, mesh.skin.inverseBind[jd]));
      std::vector<Influences> influences = influencesOf(mesh.skin, mesh.vertexCount());
      moveToStages(influences, jp, jd, joints);
      setInfluences(mesh.skin, influences);
    }
  }

  void addTwists(int forearm, int hand) {
    if (forearm < 0 || hand < 0 || c_.skeleton.bone(hand).parent != forearm) return;
    const glm::mat4 handInForearm = glm::inverse(restWorld_[forearm]) * restWorld_[hand];
    const glm::vec3 towardsHand(handInForearm[3]);
    if (glm::length(towardsHand) <= 0.0f) return;
    int twist[2];
    for (int i = 0; i < 2; ++i) {
      HelperBone helper;
      helper.kind = HelperBone::Kind::Twist;
      helper.driver = hand;
      helper.share = float(i + 1) / 3.0f;
      helper.axis = glm::normalize(towardsHand);
      helper.driverRestInParent = handInForearm;
      Trs rest;
      rest.translation = helper.share * towardsHand;
      helper.bone = twist[i] =
          addBone(c_.skeleton.bone(forearm).name + "_twist" + std::to_string(i + 1), forearm, rest, glm::mat4(1.0f));
      c_.helperBones.push_back(helper);
    }
    for (Mesh& mesh : c_.meshes) {
      const int jf = jointOf(mesh.skin, forearm);
      if (mesh.skin.empty() || jf < 0) continue;
      // At rest each twist joint moves the skin as the forearm does.
      const glm::mat4 forearmSkin = restWorld_[forearm] * mesh.skin.inverseBind[jf];
      int joints[2];
      for (int i = 0; i < 2; ++i)
        joints[i] = addJoint(mesh.skin, twist[i], glm::inverse(restWorld_[twist[i]]) * forearmSkin);
      std::vector<Influences> influences = influencesOf(mesh.skin, mesh.vertexCount());
      spreadOverTwist(mesh, influences, jf, joints, forearmSkin, glm::vec3(restWorld_[forearm][3]),
                      glm::vec3(restWorld_[hand][3]));
      setInfluences(mesh.skin, influences);
    }
  }

  static int addJoint(SkinBinding& skin, int bone, const glm::mat4& inverseBind) {
    skin.jointBones.push_back(bone);
    skin.inverseBind.push_back(inverseBind);
    return int(skin.jointBones.size()) - 1;
  }

  Character& c_;
  std::vector<glm::mat4> restWorld_;
  int added_ = 0;
};

}  // namespace

glm::quat twistAbout(const glm::quat& q, const glm::vec3& axis) {
  const glm::vec3 along = glm::dot(glm::vec3(q.x, q.y, q.z), axis) * axis;
  const glm::quat twist(q.w, along.x, along.y, along.z);
  const float length = glm::length(twist);
  return length > 1e-8f ? twist / length : glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
}

namespace {

// The humanoid's roles, or why helpers cannot be added.
std::string rolesFor(const Character& character, HumanoidBones& roles) {
  if (!character.helperBones.empty()) return "the character has helper bones already";
  try {
    roles = findHumanoidBones(character.skeleton, character.skeleton.worldTransforms(character.skeleton.restPose()));
  } catch (const Error& e) {
    return std::string("helper bones need a humanoid: ") + e.what();
  }
  return {};
}

}  // namespace

std::string helperBonesRefusal(const Character& character) {
  HumanoidBones roles;
  return rolesFor(character, roles);
}

int addHelperBones(Character& character, std::string* why) {
  HumanoidBones roles;
  std::string refusal = rolesFor(character, roles);
  std::vector<SkinBinding> before;
  for (const Mesh& mesh : character.meshes) before.push_back(mesh.skin);
  const int added = refusal.empty() ? HelperBuilder(character).build(roles) : 0;
  if (added > 0) character.skinsBeforeHelpers = std::move(before);
  if (added == 0 && refusal.empty()) refusal = "no shoulder, elbow, hip, knee or forearm joint to add helpers to";
  if (why) *why = refusal;
  return added;
}

void removeHelperBones(Character& character) {
  if (character.helperBones.empty()) return;
  int first = character.skeleton.boneCount();
  for (const HelperBone& h : character.helperBones) first = std::min(first, h.bone);
  for (size_t m = 0; m < character.meshes.size() && m < character.skinsBeforeHelpers.size(); ++m) {
    character.meshes[m].skin = character.skinsBeforeHelpers[m];
    character.meshes[m].dropSkinningBindings();
  }
  Skeleton skeleton;
  for (int b = 0; b < first; ++b) skeleton.addBone(character.skeleton.bone(b));
  character.skeleton = std::move(skeleton);
  character.helperBones.clear();
  character.skinsBeforeHelpers.clear();
}

void driveHelperBones(const std::vector<HelperBone>& helpers, const Skeleton& skeleton, Pose& pose) {
  const glm::quat identity(1.0f, 0.0f, 0.0f, 0.0f);
  for (const HelperBone& h : helpers) {
    if (h.bone < 0 || h.bone >= int(pose.size()) || h.driver < 0 || h.driver >= int(pose.size())) continue;
    const Trs& driver = pose[h.driver];
    Trs& out = pose[h.bone];
    if (h.kind == HelperBone::Kind::HalfAngle) {
      out.translation = driver.translation;
      out.scale = driver.scale;
      out.rotation = slerpShortest(skeleton.bone(h.driver).rest.rotation, driver.rotation, h.share);
      continue;
    }
    const glm::mat4 handInForearm = skeleton.bone(h.driver).parentFromOffset * driver.matrix();
    const glm::quat turn =
        Trs::fromMatrix(handInForearm).rotation * glm::inverse(Trs::fromMatrix(h.driverRestInParent).rotation);
    out.translation = skeleton.bone(h.bone).rest.translation;
    out.rotation = slerpShortest(identity, twistAbout(turn, h.axis), h.share);
  }
}

}  // namespace mq
