#include "core/character/mannequin_body.h"

#include <cmath>
#include <string>
#include <vector>

#include "core/skeleton/skeleton_from_joints.h"

namespace mq {
namespace {

// ---- Skeleton ---------------------------------------------------------------
// Joint positions from standard anthropometry for a 1.75 m adult (segment
// lengths as fractions of stature after Drillis & Contini): shoulders at
// 0.82 H, hip joints at 0.53 H, knees at 0.285 H, ankles at 0.04 H; upper arm
// 0.17 H, forearm 0.145 H, hand 0.105 H, thigh and shin 0.245 H.

using BoneSpec = JointSpec;  // rest joint and child joint, world space

constexpr float kArmAngle = glm::radians(45.0f);  // A-pose: arms 45 deg below horizontal

glm::vec3 armDirection(float forward) {
  return glm::normalize(glm::vec3(std::sin(kArmAngle), -std::cos(kArmAngle), forward));
}

// The left half (+X) and the midline; the right half is mirrored.
std::vector<BoneSpec> leftAndMidline() {
  const glm::vec3 shoulder(0.175f, 1.425f, -0.02f);
  const glm::vec3 elbow = shoulder + 0.29f * armDirection(0.0f);
  const glm::vec3 wrist = elbow + 0.25f * armDirection(0.1f);
  const glm::vec3 handTip = wrist + 0.18f * armDirection(0.1f);
  const glm::vec3 hip(0.09f, 0.93f, 0.0f), knee(0.09f, 0.5f, 0.01f), ankle(0.09f, 0.085f, -0.02f);
  const glm::vec3 ball(0.095f, 0.025f, 0.115f), toeTip(0.1f, 0.02f, 0.185f);
  return {
      {"pelvis", "", {0, 0.97f, 0}, {0, 1.07f, -0.005f}},
      {"spine", "pelvis", {0, 1.07f, -0.005f}, {0, 1.22f, -0.015f}},
      {"chest", "spine", {0, 1.22f, -0.015f}, {0, 1.45f, -0.025f}},
      {"neck", "chest", {0, 1.45f, -0.025f}, {0, 1.565f, -0.005f}},
      {"head", "neck", {0, 1.565f, -0.005f}, {0, 1.72f, 0.0f}},
      {"clavicle_l", "chest", {0.02f, 1.425f, 0.01f}, shoulder},
      {"upperarm_l", "clavicle_l", shoulder, elbow},
      {"forearm_l", "upperarm_l", elbow, wrist},
      {"hand_l", "forearm_l", wrist, handTip},
      {"thigh_l", "pelvis", hip, knee},
      {"shin_l", "thigh_l", knee, ankle},
      {"foot_l", "shin_l", ankle, ball},
      {"toes_l", "foot_l", ball, toeTip},
  };
}

std::string mirroredName(const std::string& name) {
  if (name.size() > 2 && name.compare(name.size() - 2, 2, "_l") == 0) return name.substr(0, name.size() - 2) + "_r";
  return name;
}

glm::vec3 mirrored(const glm::vec3& p) { return {-p.x, p.y, p.z}; }

std::vector<BoneSpec> allBoneSpecs() {
  std::vector<BoneSpec> specs = leftAndMidline();
  const size_t left = specs.size();
  for (size_t i = 0; i < left; ++i) {
    const BoneSpec s = specs[i];
    if (mirroredName(s.name) != s.name)
      specs.push_back({mirroredName(s.name), mirroredName(s.parent), mirrored(s.head), mirrored(s.tail)});
  }
  return specs;
}

// ---- Body -------------------------------------------------------------------

class BodyBuilder {
 public:
  BodyBuilder(const Skeleton& skeleton, const std::vector<BoneSpec>& specs) : skeleton_(skeleton), specs_(specs) {}

  ImplicitBody build() {
    addTorso();
    addHead();
    for (bool left : {true, false}) {
      addArm(left);
      addLeg(left);
    }
    body_.setReferenceBlend(0.01f);
    body_.setGround(0.0f, 0.006f);
    return body_;
  }

 private:
  int bone(const std::string& name) const { return skeleton_.findBone(name); }
  int side(const std::string& name, bool left) const { return bone(name + (left ? "_l" : "_r")); }
  glm::vec3 head(int b) const { return specs_[b].head; }
  glm::vec3 tail(int b) const { return specs_[b].tail; }
  static glm::vec3 onSide(glm::vec3 p, bool left) { return left ? p : mirrored(p); }

  void cone(glm::vec3 a, glm::vec3 b, float r0, float r1, int boneIndex, float blend, glm::vec3 wide = {},
            float wideScale = 1.0f, float thickScale = 1.0f, int group = -1) {
    ImplicitPrimitive p = ImplicitPrimitive::roundCone(a, b, r0, r1, boneIndex, blend, wide, wideScale, thickScale);
    p.group = group;
    body_.add(p);
  }
  void ellipsoid(glm::vec3 c, glm::vec3 r, int boneIndex, float blend) {
    body_.add(ImplicitPrimitive::ellipsoid(c, r, boneIndex, blend));
  }

  // The trunk is a chain of round cones with elliptic sections (wide along
  // X, deep along Z) whose end radii match, so the skin runs smoothly from
  // the hips through the waist to the chest.
  void addTorso() {
    const int pelvis = bone("pelvis"), spine = bone("spine"), chest = bone("chest"), neck = bone("neck");
    const glm::vec3 wide(1, 0, 0);
    constexpr int kTrunk = 0;
    constexpr float kWide = 1.8f, kDeep = 1.2f;  // section: half-width 1.8 r, half-depth 1.2 r
    const glm::vec3 spinePath[] = {
        {0, 0.87f, -0.01f}, {0, 1.0f, -0.005f}, {0, 1.12f, 0.0f}, {0, 1.28f, -0.01f}, {0, 1.37f, -0.02f}};
    const float radius[] = {0.09f, 0.08f, 0.076f, 0.089f, 0.072f};
    const int segmentBone[] = {pelvis, spine, chest, chest};
    for (int i = 0; i < 4; ++i)
      cone(spinePath[i], spinePath[i + 1], radius[i], radius[i + 1], segmentBone[i], 0.014f, wide, kWide, kDeep,
           kTrunk);
    for (bool left : {true, false})
      ellipsoid(onSide({0.068f, 0.885f, -0.05f}, left), {0.075f, 0.085f, 0.065f}, pelvis, 0.012f);
    cone({0, 1.42f, -0.025f}, {0, 1.6f, -0.005f}, 0.06f, 0.054f, neck, 0.012f);
  }

  void addHead() {
    const int h = bone("head");
    ellipsoid({0, 1.655f, -0.008f}, {0.078f, 0.095f, 0.098f}, h, 0.01f);
    ellipsoid({0, 1.6f, 0.03f}, {0.058f, 0.06f, 0.065f}, h, 0.012f);
    ellipsoid({0, 1.622f, 0.092f}, {0.012f, 0.022f, 0.014f}, h, 0.005f);  // a nose shows where it faces
  }

  void addArm(bool left) {
    const int clavicle = side("clavicle", left), upper = side("upperarm", left);
    const int fore = side("forearm", left), hand = side("hand", left);
    cone(onSide({0.04f, 1.43f, -0.035f}, left), onSide({0.16f, 1.415f, -0.025f}, left), 0.045f, 0.042f, clavicle,
         0.012f);
    const glm::vec3 shoulder = head(upper), elbow = head(fore), wrist = head(hand), tip = tail(hand);
    const glm::vec3 upperDir = glm::normalize(elbow - shoulder), foreDir = glm::normalize(wrist - elbow);
    ellipsoid(shoulder + 0.01f * upperDir, {0.055f, 0.058f, 0.055f}, upper, 0.01f);
    cone(shoulder, elbow, 0.048f, 0.037f, upper, 0.01f);
    cone(elbow, wrist, 0.038f, 0.025f, fore, 0.01f, {0, 0, 1}, 1.15f);
    cone(elbow + 0.03f * foreDir, elbow + 0.12f * foreDir, 0.042f, 0.034f, fore, 0.01f);
    // A mitten hand, palm facing the thigh, thumb forward.
    const glm::vec3 handDir = glm::normalize(tip - wrist);
    const glm::vec3 knuckles = wrist + 0.1f * handDir;
    cone(wrist, knuckles, 0.017f, 0.017f, hand, 0.007f, {0, 0, 1}, 2.5f);
    cone(knuckles, tip, 0.014f, 0.011f, hand, 0.007f, {0, 0, 1}, 2.7f);
    const glm::vec3 thumbBase = wrist + 0.035f * handDir + glm::vec3(0, 0, 0.03f);
    cone(thumbBase, thumbBase + 0.055f * glm::normalize(handDir + glm::vec3(0, 0, 0.8f)), 0.012f, 0.01f, hand, 0.007f);
  }

  void addLeg(bool left) {
    const int thigh = side("thigh", left), shin = side("shin", left);
    const int foot = side("foot", left), toes = side("toes", left);
    const glm::vec3 hip = head(thigh), knee = head(shin), ankle = head(foot), ball = head(toes), toeTip = tail(toes);
    cone(hip, knee, 0.087f, 0.055f, thigh, 0.012f);
    cone(knee, ankle, 0.052f, 0.033f, shin, 0.01f);
    ellipsoid(onSide({0.09f, 0.36f, -0.03f}, left), {0.05f, 0.1f, 0.05f}, shin, 0.012f);
    const glm::vec3 heel = onSide({0.09f, 0.036f, -0.04f}, left);
    cone(ankle, heel, 0.034f, 0.034f, foot, 0.008f);
    cone(heel, ball, 0.03f, 0.026f, foot, 0.008f, {1, 0, 0}, 1.6f);
    cone(ball, toeTip, 0.024f, 0.018f, toes, 0.008f, {1, 0, 0}, 1.85f);
  }

  const Skeleton& skeleton_;
  const std::vector<BoneSpec>& specs_;
  ImplicitBody body_;
};

}  // namespace

Skeleton makeMannequinSkeleton() { return skeletonFromJoints(allBoneSpecs()); }

ImplicitBody makeMannequinBody(const Skeleton& skeleton) {
  const std::vector<BoneSpec> specs = allBoneSpecs();
  return BodyBuilder(skeleton, specs).build();
}

}  // namespace mq
