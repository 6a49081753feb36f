#include "core/character/default_mannequin.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numeric>
#include <string>

#include "core/character/implicit_body.h"
#include "core/mesh/marching_cubes.h"
#include "core/util/thread_pool.h"

namespace mq {
namespace {

// ---- Skeleton ---------------------------------------------------------------
// Joint positions from standard anthropometry for a 1.75 m adult (segment
// lengths as fractions of stature after Drillis & Contini): shoulders at
// 0.82 H, hip joints at 0.53 H, knees at 0.285 H, ankles at 0.04 H; upper arm
// 0.17 H, forearm 0.145 H, hand 0.105 H, thigh and shin 0.245 H.

struct BoneSpec {
  std::string name;
  std::string parent;
  glm::vec3 head, tail;  // rest joint and child joint, world space
};

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

// World rest orientation: +Y along the bone, +X = Y x forward (forward is +Z,
// or +Y for bones that point forward), +Z completes the frame.
glm::mat3 restFrame(const BoneSpec& s) {
  const glm::vec3 y = glm::normalize(s.tail - s.head);
  const glm::vec3 forward = std::abs(y.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  const glm::vec3 x = glm::normalize(glm::cross(y, forward));
  return glm::mat3(x, y, glm::cross(x, y));
}

Skeleton buildSkeleton(const std::vector<BoneSpec>& specs) {
  Skeleton skeleton;
  std::vector<glm::mat3> frames;
  for (const BoneSpec& s : specs) {
    Bone bone;
    bone.name = s.name;
    bone.parent = skeleton.findBone(s.parent);
    const glm::mat3 frame = restFrame(s);
    glm::mat3 parentFrame(1.0f);
    glm::vec3 parentHead(0.0f);
    if (bone.parent >= 0) parentFrame = frames[bone.parent], parentHead = specs[bone.parent].head;
    const glm::mat3 parentFromWorld = glm::transpose(parentFrame);
    bone.rest.translation = parentFromWorld * (s.head - parentHead);
    bone.rest.rotation = glm::normalize(glm::quat_cast(parentFromWorld * frame));
    skeleton.addBone(bone);
    frames.push_back(frame);
  }
  return skeleton;
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

// ---- Mesh, weights, tags ----------------------------------------------------

constexpr float kCellSize = 0.009f;

Mesh polygonise(const ImplicitBody& body) {
  ThreadPool& pool = ThreadPool::shared();
  const ScalarGrid grid = body.sample(kCellSize, &pool);
  IsoSurface surface = extractIsoSurface(grid, 0.0f);
  Mesh mesh;
  mesh.name = "mannequin";
  mesh.positions = std::move(surface.positions);
  mesh.triangles = std::move(surface.triangles);
  mesh.normals.resize(mesh.positions.size());
  pool.parallelFor(0, mesh.vertexCount(), 512, [&](size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v) {
      const glm::vec3 n = body.normal(mesh.position(v), 0.25f * kCellSize);
      for (int d = 0; d < 3; ++d) mesh.normals[3 * v + d] = n[d];
    }
  });
  mesh.baseColor = {0.82f, 0.7f, 0.56f};
  return mesh;
}

// Bones a vertex may follow: the bone of the nearest primitive and its
// neighbours in the hierarchy, so a thigh never pulls the other thigh's skin.
std::vector<std::vector<int>> skinNeighbourhoods(const Skeleton& skeleton) {
  std::vector<std::vector<int>> allowed(skeleton.boneCount());
  for (int b = 0; b < skeleton.boneCount(); ++b) {
    allowed[b].push_back(b);
    const int parent = skeleton.bone(b).parent;
    if (parent >= 0) {
      allowed[b].push_back(parent);
      if (skeleton.bone(parent).parent >= 0) allowed[b].push_back(skeleton.bone(parent).parent);
    }
    for (int c : skeleton.children(b)) allowed[b].push_back(c);
  }
  return allowed;
}

// Dense per-vertex bone weights (vertices x bones) from primitive potentials.
std::vector<float> potentialWeights(const Mesh& mesh, const ImplicitBody& body, const Skeleton& skeleton) {
  constexpr float kFalloff = 0.02f;
  // The pelvis reaches further down the thighs, so the crotch and the
  // buttocks blend between the hip and both legs instead of being torn
  // between the two thighs.
  const int pelvis = skeleton.findBone("pelvis");
  auto falloff = [&](int bone) { return bone == pelvis ? 2.0f * kFalloff : kFalloff; };
  const int bones = skeleton.boneCount();
  const auto allowed = skinNeighbourhoods(skeleton);
  const auto& prims = body.primitives();
  std::vector<float> dense(mesh.vertexCount() * bones, 0.0f);
  ThreadPool::shared().parallelFor(0, mesh.vertexCount(), 512, [&](size_t begin, size_t end) {
    std::vector<float> distance(prims.size());
    std::vector<float> perBone(bones);
    for (size_t v = begin; v < end; ++v) {
      const glm::vec3 p = mesh.position(v);
      size_t nearest = 0;
      for (size_t i = 0; i < prims.size(); ++i) {
        distance[i] = prims[i].distance(p);
        if (distance[i] < distance[nearest]) nearest = i;
      }
      std::fill(perBone.begin(), perBone.end(), 0.0f);
      for (size_t i = 0; i < prims.size(); ++i)
        perBone[prims[i].bone] += std::exp(-std::max(distance[i], 0.0f) / falloff(prims[i].bone));
      for (int b : allowed[prims[nearest].bone]) dense[v * bones + b] = perBone[b];
    }
  });
  return dense;
}

// Averages each vertex's weights with its mesh neighbours' (uniform
// Laplacian), which removes the seams where the nearest primitive changes.
void smoothOverSurface(const Mesh& mesh, int bones, int iterations, std::vector<float>& dense) {
  const size_t n = mesh.vertexCount();
  std::vector<std::vector<uint32_t>> neighbours(n);
  for (size_t t = 0; t < mesh.triangleCount(); ++t)
    for (int e = 0; e < 3; ++e) neighbours[mesh.triangles[3 * t + e]].push_back(mesh.triangles[3 * t + (e + 1) % 3]);
  std::vector<float> next(dense.size());
  for (int it = 0; it < iterations; ++it) {
    ThreadPool::shared().parallelFor(0, n, 1024, [&](size_t begin, size_t end) {
      for (size_t v = begin; v < end; ++v) {
        float* out = &next[v * bones];
        for (int b = 0; b < bones; ++b) out[b] = 0.5f * dense[v * bones + b];
        const float share = 0.5f / float(neighbours[v].size());
        for (uint32_t u : neighbours[v])
          for (int b = 0; b < bones; ++b) out[b] += share * dense[u * bones + b];
      }
    });
    dense.swap(next);
  }
}

void bindSkin(Mesh& mesh, const ImplicitBody& body, const Skeleton& skeleton) {
  const int bones = skeleton.boneCount();
  std::vector<float> dense = potentialWeights(mesh, body, skeleton);
  smoothOverSurface(mesh, bones, 12, dense);
  SkinBinding& skin = mesh.skin;
  skin.influencesPerVertex = bones;
  skin.jointBones.resize(bones);
  std::iota(skin.jointBones.begin(), skin.jointBones.end(), 0);
  skin.inverseBind = skeleton.inverseBindMatrices();
  // Traces that smoothing carried far from a bone are dropped.
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    float* w = &dense[v * bones];
    const float sum = std::accumulate(w, w + bones, 0.0f);
    for (int b = 0; b < bones; ++b)
      if (w[b] < 0.01f * sum) w[b] = 0.0f;
  }
  skin.weights = std::move(dense);
  skin.joints.resize(skin.weights.size());
  for (size_t i = 0; i < skin.joints.size(); ++i) skin.joints[i] = uint16_t(i % bones);
  skin.normalise();
  skin.limitInfluences(4);
}

// The hair region: the skull above a line from the forehead over the ears
// down to the nape.
void tagScalp(Mesh& mesh, const Skeleton& skeleton) {
  const int headBone = skeleton.findBone("head");
  const glm::vec3 skull(0.0f, 1.655f, -0.008f);
  mesh.vertexTags.assign(mesh.vertexCount(), TagNone);
  const SkinBinding& skin = mesh.skin;
  const int k = skin.influencesPerVertex;
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    float headWeight = 0.0f;
    for (int i = 0; i < k; ++i)
      if (skin.jointBones[skin.joints[v * k + i]] == headBone) headWeight += skin.weights[v * k + i];
    const glm::vec3 r = mesh.position(v) - skull;
    const float frontness = std::clamp((r.z + 0.06f) / 0.11f, 0.0f, 1.0f);
    const float hairline = -0.05f + 0.09f * frontness;
    if (headWeight > 0.5f && r.y > hairline) mesh.vertexTags[v] = TagScalp;
  }
}

// ---- Clips ------------------------------------------------------------------

// A rotation by `angle` about a world axis, as the bone would turn in its rest
// orientation, applied on top of the bone's rest rotation.
struct Motion {
  const Skeleton& skeleton;
  std::vector<glm::mat3> worldRest;

  explicit Motion(const Skeleton& s) : skeleton(s) {
    const auto world = s.worldTransforms(s.restPose());
    for (const glm::mat4& m : world) worldRest.push_back(glm::mat3(m));
  }
  glm::quat local(int bone, glm::quat worldDelta) const {
    const glm::quat rest = glm::quat_cast(worldRest[bone]);
    return glm::normalize(skeleton.bone(bone).rest.rotation * (glm::inverse(rest) * worldDelta * rest));
  }
  glm::vec3 restDirection(int bone) const { return glm::normalize(worldRest[bone][1]); }
};

glm::quat about(const glm::vec3& axis, float degrees) {
  return glm::angleAxis(glm::radians(degrees), glm::normalize(axis));
}

// Samples f(phase) at evenly spaced keys over [0, duration]; the last key
// repeats the first when the motion loops.
Track rotationTrack(int keys, float duration, bool loops, const std::function<glm::quat(float)>& at) {
  Track track;
  track.components = 4;
  track.isRotation = true;
  for (int i = 0; i <= keys; ++i) {
    const float u = (loops && i == keys) ? 0.0f : float(i) / keys;
    const glm::quat q = at(u);
    track.times.push_back(duration * float(i) / keys);
    track.values.insert(track.values.end(), {q.x, q.y, q.z, q.w});
  }
  return track;
}

Track translationTrack(int keys, float duration, bool loops, const std::function<glm::vec3(float)>& at) {
  Track track;
  track.components = 3;
  for (int i = 0; i <= keys; ++i) {
    const float u = (loops && i == keys) ? 0.0f : float(i) / keys;
    const glm::vec3 p = at(u);
    track.times.push_back(duration * float(i) / keys);
    track.values.insert(track.values.end(), {p.x, p.y, p.z});
  }
  return track;
}

void addRotation(Clip& clip, int bone, Track track) {
  BoneChannel channel;
  channel.bone = bone;
  channel.rotation = std::move(track);
  clip.boneChannels.push_back(std::move(channel));
}

// A walk in place, one stride of each leg per second. Angles in degrees;
// the left leg swings forward for phase in (-1/4, 1/4).
Clip makeWalk(const Skeleton& s) {
  constexpr int kKeys = 24;
  constexpr float kDuration = 1.0f;
  const Motion m(s);
  const glm::vec3 xAxis(1, 0, 0), yAxis(0, 1, 0);
  Clip clip;
  clip.name = "walk";
  clip.wrap = WrapMode::Loop;
  auto wave = [](float u, float shift = 0.0f) { return std::sin(2.0f * float(M_PI) * (u + shift)); };

  const int pelvis = s.findBone("pelvis");
  BoneChannel root;
  root.bone = pelvis;
  const glm::vec3 rest = s.bone(pelvis).rest.translation;
  root.translation = translationTrack(kKeys, kDuration, true, [&](float u) {
    return rest + glm::vec3(-0.015f * wave(u, 0.25f), 0.012f * wave(2 * u, 0.25f), 0.0f);
  });
  root.rotation = rotationTrack(kKeys, kDuration, true, [&](float u) {
    return m.local(pelvis, about(yAxis, 5.0f * wave(u)) * about({0, 0, 1}, 3.0f * wave(u, 0.25f)));
  });
  clip.boneChannels.push_back(std::move(root));
  addRotation(clip, s.findBone("chest"), rotationTrack(kKeys, kDuration, true, [&](float u) {
                return m.local(s.findBone("chest"), about(yAxis, -9.0f * wave(u)));
              }));
  for (bool left : {true, false}) {
    const std::string suffix = left ? "_l" : "_r";
    const float shift = left ? 0.0f : 0.5f;
    const int thigh = s.findBone("thigh" + suffix), shin = s.findBone("shin" + suffix);
    const int foot = s.findBone("foot" + suffix), upper = s.findBone("upperarm" + suffix);
    const int fore = s.findBone("forearm" + suffix);
    addRotation(clip, thigh, rotationTrack(kKeys, kDuration, true, [&](float u) {
                  return m.local(thigh, about(xAxis, -25.0f * wave(u, shift)));
                }));
    addRotation(clip, shin, rotationTrack(kKeys, kDuration, true, [&](float u) {
                  const float swing =
                      std::max(0.0f, wave(u, shift + 0.25f));  // knee folds while the leg swings forward
                  return m.local(shin, about(xAxis, 8.0f + 50.0f * swing * swing));
                }));
    addRotation(clip, foot, rotationTrack(kKeys, kDuration, true, [&](float u) {
                  return m.local(foot, about(xAxis, 10.0f * wave(u, shift + 0.1f)));
                }));
    const float toBody = left ? -1.0f : 1.0f;  // brings the A-pose arm down beside the body
    addRotation(clip, upper, rotationTrack(kKeys, kDuration, true, [&](float u) {
                  return m.local(upper, about(xAxis, 18.0f * wave(u, shift)) * about({0, 0, 1}, toBody * 32.0f));
                }));
    addRotation(clip, fore, rotationTrack(kKeys, kDuration, true, [&](float u) {
                  const glm::vec3 hinge = glm::cross(m.restDirection(fore), glm::vec3(0, 0, 1));
                  return m.local(fore, about(hinge, 20.0f - 12.0f * wave(u, shift)));
                }));
  }
  return clip;
}

// Both arms rise sideways to above the shoulders and come back down.
Clip makeArmRaise(const Skeleton& s) {
  constexpr int kKeys = 32;
  constexpr float kDuration = 2.0f;
  const Motion m(s);
  Clip clip;
  clip.name = "arm_raise";
  clip.wrap = WrapMode::Clamp;
  auto lift = [](float u) {
    const float x = std::sin(float(M_PI) * u);
    return x * x;
  };  // 0 -> 1 -> 0, eased
  for (bool left : {true, false}) {
    const std::string suffix = left ? "_l" : "_r";
    const float sign = left ? 1.0f : -1.0f;
    const int clavicle = s.findBone("clavicle" + suffix), upper = s.findBone("upperarm" + suffix);
    addRotation(clip, clavicle, rotationTrack(kKeys, kDuration, false, [&](float u) {
                  return m.local(clavicle, about({0, 0, 1}, sign * 15.0f * lift(u)));
                }));
    addRotation(clip, upper, rotationTrack(kKeys, kDuration, false, [&](float u) {
                  return m.local(upper, about({0, 0, 1}, sign * 95.0f * lift(u)));
                }));
  }
  return clip;
}

}  // namespace

Character makeDefaultMannequin() {
  const std::vector<BoneSpec> specs = allBoneSpecs();
  Character character;
  character.name = "Mannequin";
  character.sourcePath = "default";
  character.skeleton = buildSkeleton(specs);
  auto body = std::make_shared<const ImplicitBody>(BodyBuilder(character.skeleton, specs).build());
  Mesh mesh = polygonise(*body);
  bindSkin(mesh, *body, character.skeleton);
  tagScalp(mesh, character.skeleton);
  mesh.implicitBody = body;
  character.meshes.push_back(std::move(mesh));
  character.clips.push_back(makeWalk(character.skeleton));
  character.clips.push_back(makeArmRaise(character.skeleton));
  return character;
}

}  // namespace mq
