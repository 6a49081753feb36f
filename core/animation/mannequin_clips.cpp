#include "core/animation/mannequin_clips.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace mq {
namespace {

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
}  // namespace

Clip makeMannequinWalk(const Skeleton& s) {
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
Clip makeMannequinArmRaise(const Skeleton& s) {
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

// The head turns quickly over one shoulder, across to the other and back, with
// a tilt into the turn: long hair swings across itself.
Clip makeMannequinHeadTurn(const Skeleton& s) {
  constexpr int kKeys = 60;
  constexpr float kDuration = 2.0f;
  const Motion m(s);
  Clip clip;
  clip.name = "head_turn";
  clip.wrap = WrapMode::Clamp;
  auto ease = [](float x) { return 0.5f - 0.5f * std::cos(float(M_PI) * std::clamp(x, 0.0f, 1.0f)); };
  // Turn in degrees: 0 -> 70 (0 .. 0.2), 70 -> -70 (0.3 .. 0.6), -70 -> 0 (0.75 .. 1).
  auto turn = [&](float u) {
    return 70.0f * (ease(u / 0.2f) - 2.0f * ease((u - 0.3f) / 0.3f) + ease((u - 0.75f) / 0.25f));
  };
  for (const auto& [name, part] : {std::pair{"neck", 0.4f}, std::pair{"head", 0.6f}}) {
    const int bone = s.findBone(name);
    const float share = part;  // (a structured binding cannot be captured before C++20's last revisions)
    if (bone < 0) continue;
    addRotation(clip, bone, rotationTrack(kKeys, kDuration, false, [&](float u) {
                  const float yaw = share * turn(u);
                  return m.local(bone, about({0, 1, 0}, yaw) * about({0, 0, 1}, -0.25f * yaw));
                }));
  }
  return clip;
}

}  // namespace mq
