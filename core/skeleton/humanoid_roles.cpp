#include "core/skeleton/humanoid_roles.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>

#include "core/util/error.h"

namespace mq {
namespace {

// ---- Names ----------------------------------------------------------------------

std::string canonical(std::string name) {
  size_t colon = name.rfind(':');  // "mixamorig:LeftArm"
  if (colon != std::string::npos) name = name.substr(colon + 1);
  std::string out;
  for (char c : name)
    if (std::isalnum(static_cast<unsigned char>(c))) out += char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Bone names by role; "%" stands for a side: l/r or left/right.
const std::vector<std::pair<std::string, std::vector<std::string>>>& aliases() {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> table = {
      {"pelvis", {"pelvis", "hips", "hip", "root"}},
      {"spine", {"spine", "spine1", "spine01", "abdomen"}},
      {"chest", {"chest", "spine2", "spine02", "upperchest", "thorax"}},
      {"neck", {"neck", "neck1", "neck01"}},
      {"head", {"head"}},
      {"clavicle", {"clavicle%", "%clavicle", "%shoulder", "shoulder%", "collar%", "%collar"}},
      {"upperarm", {"upperarm%", "%upperarm", "%arm", "arm%", "upperarm%"}},
      {"forearm", {"forearm%", "%forearm", "lowerarm%", "%lowerarm"}},
      {"hand", {"hand%", "%hand"}},
      {"thigh", {"thigh%", "%thigh", "%upleg", "upperleg%", "%upperleg"}},
      {"shin", {"shin%", "%shin", "calf%", "%leg", "lowerleg%", "%lowerleg"}},
      {"foot", {"foot%", "%foot"}},
  };
  return table;
}

// ---- Structure ------------------------------------------------------------------

using Chain = std::vector<int>;

struct Rig {
  const Skeleton& skeleton;
  std::vector<glm::vec3> joint;  // rest world positions
  std::vector<std::vector<int>> children;
  float height = 0.0f;  // vertical extent of the joints

  Rig(const Skeleton& s, const std::vector<glm::mat4>& world) : skeleton(s), children(s.boneCount()) {
    float lo = 1e30f, hi = -1e30f;
    for (int b = 0; b < s.boneCount(); ++b) {
      joint.push_back(glm::vec3(world[b][3]));
      lo = std::min(lo, joint[b].y), hi = std::max(hi, joint[b].y);
      if (s.bone(b).parent >= 0) children[s.bone(b).parent].push_back(b);
    }
    height = std::max(hi - lo, 1e-6f);
  }

  // The largest value of `f` over the joints of the subtree at `bone`.
  float maxOver(int bone, const std::function<float(glm::vec3)>& f) const {
    float best = f(joint[bone]);
    for (int c : children[bone]) best = std::max(best, maxOver(c, f));
    return best;
  }

  // From `start`, always into the child whose subtree reaches farthest by `reach`.
  Chain follow(int start, const std::function<float(glm::vec3)>& reach) const {
    Chain chain{start};
    for (int b = start; !children[b].empty();) {
      b = *std::max_element(children[b].begin(), children[b].end(),
                            [&](int x, int y) { return maxOver(x, reach) < maxOver(y, reach); });
      chain.push_back(b);
    }
    return chain;
  }
};

// A chain going down from `bone` by at least a quarter of the body's height.
bool goesDown(const Rig& rig, int parent, int child) {
  const float lowest = -rig.maxOver(child, [](glm::vec3 p) { return -p.y; });
  return rig.joint[parent].y - lowest > 0.25f * rig.height;
}

// The hips: the first bone (parents first) with two children going down, on
// either side of it. Fills `legs` (left, right).
int findHips(const Rig& rig, int legs[2]) {
  for (int b = 0; b < rig.skeleton.boneCount(); ++b) {
    int left = -1, right = -1;
    for (int c : rig.children[b]) {
      if (!goesDown(rig, b, c)) continue;
      // The side of the leg's lowest joint (the foot), not of its first one.
      const float side = rig.joint[rig.follow(c, [](glm::vec3 p) { return -p.y; }).back()].x;
      if (side > rig.joint[b].x && left < 0)
        left = c;
      else if (side < rig.joint[b].x && right < 0)
        right = c;
    }
    if (left >= 0 && right >= 0) {
      legs[0] = left, legs[1] = right;
      return b;
    }
  }
  return -1;
}

// The three joints of a limb in `chain` (upper, middle, lower: upper arm,
// forearm, hand or thigh, shin, foot): the two segments most alike in length,
// starting at the chain's first or second joint (a clavicle or a hip bone
// before the limb proper). Throws when the chain is too short.
void limbJoints(const Rig& rig, const Chain& chain, int& upper, int& middle, int& lower, int& before) {
  float best = 1e30f;
  for (size_t s = 0; s < std::min<size_t>(2, chain.size()); ++s)
    for (size_t e = s + 1; e < chain.size(); ++e)
      for (size_t h = e + 1; h < chain.size(); ++h) {
        const float a = glm::distance(rig.joint[chain[s]], rig.joint[chain[e]]);
        const float b = glm::distance(rig.joint[chain[e]], rig.joint[chain[h]]);
        if (a < 0.05f * rig.height || b < 0.05f * rig.height) continue;
        const float mismatch = std::abs(a - b) / (a + b);
        if (mismatch < best)
          best = mismatch, upper = chain[s], middle = chain[e], lower = chain[h], before = s == 1 ? chain[0] : -1;
      }
  if (best > 1e29f) throw Error("its chain has " + std::to_string(chain.size()) + " bone(s), too short for a limb");
}

// Where the toes point, horizontally: from each foot joint to its first child.
glm::vec3 facingOf(const Rig& rig, const int foot[2]) {
  glm::vec3 sum(0.0f);
  for (int s = 0; s < 2; ++s) {
    if (foot[s] < 0 || rig.children[foot[s]].empty()) continue;
    glm::vec3 toes = rig.joint[rig.children[foot[s]][0]] - rig.joint[foot[s]];
    toes.y = 0.0f;
    if (glm::length(toes) > 1e-6f) sum += glm::normalize(toes);
  }
  return glm::length(sum) > 1e-6f ? glm::normalize(sum) : glm::vec3(0.0f);
}

std::string sideName(int side) { return side == 0 ? " (left)" : " (right)"; }

[[noreturn]] void missing(const std::string& role, const std::string& why) {
  throw Error("no bone for the " + role + ": " + why);
}

// Roles from the skeleton's structure alone.
HumanoidBones structuralRoles(const Rig& rig) {
  HumanoidBones r;
  int legs[2];
  r.pelvis = findHips(rig, legs);
  if (r.pelvis < 0) missing("pelvis", "no bone has two chains going down on either side (the legs)");
  const auto down = [](glm::vec3 p) { return -p.y; };
  for (int s = 0; s < 2; ++s) {
    const Chain leg = rig.follow(legs[s], down);
    int hipBone = -1;  // a bone from the pelvis's centre out to the hip joint
    try {
      limbJoints(rig, leg, r.thigh[s], r.shin[s], r.foot[s], hipBone);
    } catch (const Error& e) {
      missing("thigh" + sideName(s), "the leg starting at '" + rig.skeleton.bone(legs[s]).name + "': " + e.what());
    }
  }

  // The spine: the pelvis's other child reaching highest, then always upwards.
  int spineStart = -1;
  const auto up = [](glm::vec3 p) { return p.y; };
  for (int c : rig.children[r.pelvis])
    if (c != legs[0] && c != legs[1] && (spineStart < 0 || rig.maxOver(c, up) > rig.maxOver(spineStart, up)))
      spineStart = c;
  if (spineStart < 0) missing("spine", "the hips have no chain going up");
  Chain spine{r.pelvis};
  for (int b : rig.follow(spineStart, up)) spine.push_back(b);

  // The arms: the side branches of the spine reaching farthest sideways.
  int armStart[2]{-1, -1};
  size_t armLevel[2]{0, 0};
  float armReach[2]{0.0f, 0.0f};
  for (size_t i = 1; i < spine.size(); ++i)
    for (int c : rig.children[spine[i]]) {
      if (i + 1 < spine.size() && c == spine[i + 1]) continue;
      const float x0 = rig.joint[spine[i]].x;
      for (int s = 0; s < 2; ++s) {
        const float sign = s == 0 ? 1.0f : -1.0f;
        const float reach = rig.maxOver(c, [&](glm::vec3 p) { return sign * (p.x - x0); });
        if (reach > 0.15f * rig.height && reach > armReach[s]) armReach[s] = reach, armStart[s] = c, armLevel[s] = i;
      }
    }
  for (int s = 0; s < 2; ++s) {
    if (armStart[s] < 0) missing("upper arm" + sideName(s), "no chain branches sideways from the spine");
    const glm::vec3 root = rig.joint[armStart[s]];
    const Chain arm = rig.follow(armStart[s], [&](glm::vec3 p) { return glm::distance(p, root); });
    try {
      limbJoints(rig, arm, r.upperArm[s], r.forearm[s], r.hand[s], r.clavicle[s]);
    } catch (const Error& e) {
      missing("upper arm" + sideName(s),
              "the arm starting at '" + rig.skeleton.bone(armStart[s]).name + "': " + e.what());
    }
  }
  if (armStart[0] == armStart[1]) missing("upper arm (left)", "both arms are the same chain");

  // Chest: where the arms branch; neck and head above it; spine between the
  // pelvis and the chest, the bone nearest halfway up.
  const size_t chestLevel = std::min(armLevel[0], armLevel[1]);
  r.chest = spine[chestLevel];
  if (chestLevel + 1 >= spine.size()) missing("neck", "nothing above the bone the arms branch from");
  r.neck = spine[chestLevel + 1];
  if (chestLevel + 2 < spine.size()) r.head = spine[chestLevel + 2];
  if (chestLevel < 2) missing("spine", "no bone between the hips and the bone the arms branch from");
  const float halfway = 0.5f * (rig.joint[r.pelvis].y + rig.joint[r.chest].y);
  r.spine = spine[1];
  for (size_t i = 1; i < chestLevel; ++i)
    if (std::abs(rig.joint[spine[i]].y - halfway) < std::abs(rig.joint[r.spine].y - halfway)) r.spine = spine[i];
  return r;
}

}  // namespace

int findBoneByRoleName(const Skeleton& skeleton, const std::string& role, int side) {
  std::vector<std::string> sides =
      side == 0 ? std::vector<std::string>{"l", "left"} : std::vector<std::string>{"r", "right"};
  for (const auto& [name, patterns] : aliases()) {
    if (name != role) continue;
    for (const std::string& pattern : patterns) {
      std::vector<std::string> candidates;
      size_t pct = pattern.find('%');
      if (pct == std::string::npos)
        candidates.push_back(pattern);
      else
        for (const std::string& s : sides) candidates.push_back(pattern.substr(0, pct) + s + pattern.substr(pct + 1));
      for (const std::string& candidate : candidates)
        for (int b = 0; b < skeleton.boneCount(); ++b)
          if (canonical(skeleton.bone(b).name) == candidate) return b;
    }
  }
  return -1;
}

HumanoidBones findHumanoidBones(const Skeleton& skeleton, const std::vector<glm::mat4>& restWorld) {
  HumanoidBones named;
  named.pelvis = findBoneByRoleName(skeleton, "pelvis", 0);
  named.spine = findBoneByRoleName(skeleton, "spine", 0);
  named.chest = findBoneByRoleName(skeleton, "chest", 0);
  named.neck = findBoneByRoleName(skeleton, "neck", 0);
  named.head = findBoneByRoleName(skeleton, "head", 0);
  for (int s = 0; s < 2; ++s) {
    named.clavicle[s] = findBoneByRoleName(skeleton, "clavicle", s);
    named.upperArm[s] = findBoneByRoleName(skeleton, "upperarm", s);
    named.forearm[s] = findBoneByRoleName(skeleton, "forearm", s);
    named.hand[s] = findBoneByRoleName(skeleton, "hand", s);
    named.thigh[s] = findBoneByRoleName(skeleton, "thigh", s);
    named.shin[s] = findBoneByRoleName(skeleton, "shin", s);
    named.foot[s] = findBoneByRoleName(skeleton, "foot", s);
  }
  std::vector<int*> required = {&named.pelvis, &named.spine, &named.chest, &named.neck};
  for (int s = 0; s < 2; ++s)
    for (int* b :
         {&named.upperArm[s], &named.forearm[s], &named.hand[s], &named.thigh[s], &named.shin[s], &named.foot[s]})
      required.push_back(b);
  const bool allNamed = std::all_of(required.begin(), required.end(), [](const int* b) { return *b >= 0; });

  const Rig rig(skeleton, restWorld);
  HumanoidBones structural;
  try {
    structural = structuralRoles(rig);
  } catch (const Error&) {
    if (!allNamed) throw;
    named.facing = facingOf(rig, named.foot);
    return named;  // every role named: the structure is not needed
  }
  const auto fill = [](int& name, int structure) {
    if (name < 0) name = structure;
  };
  fill(named.pelvis, structural.pelvis), fill(named.spine, structural.spine), fill(named.chest, structural.chest);
  fill(named.neck, structural.neck), fill(named.head, structural.head);
  for (int s = 0; s < 2; ++s) {
    fill(named.clavicle[s], structural.clavicle[s]), fill(named.upperArm[s], structural.upperArm[s]);
    fill(named.forearm[s], structural.forearm[s]), fill(named.hand[s], structural.hand[s]);
    fill(named.thigh[s], structural.thigh[s]), fill(named.shin[s], structural.shin[s]);
    fill(named.foot[s], structural.foot[s]);
  }
  named.facing = facingOf(rig, named.foot);
  return named;
}

}  // namespace mq
