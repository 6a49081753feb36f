#include "sim/hair/hair_bake.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/character/character.h"
#include "core/hair/body_proxy.h"
#include "core/hair/head_fit.h"
#include "core/hair/scalp.h"
#include "core/util/error.h"

namespace mq {

HairRig HairRig::fromProxy(const Character& character, const BodyProxy& restProxy) {
  HairRig rig;
  rig.headBone = findHeadBone(character);
  if (rig.headBone >= 0)
    rig.restWorldFromHead = character.skeleton.worldTransforms(character.skeleton.restPose())[rig.headBone];
  rig.body = HairColliders::attachToSkeleton(restProxy, character.skeleton, rig.headBone);
  return rig;
}

HairRig HairRig::fromCharacter(const Character& character) {
  const int head = findHeadBone(character);
  if (head < 0) return HairRig{};
  std::vector<glm::vec3> scalpPoints;
  try {
    const ScalpSurface scalp = extractScalp(character, ScalpRegion{});
    for (size_t v = 0; v < scalp.positions.size() / 3; ++v) scalpPoints.push_back(scalp.position(v));
  } catch (const Error&) {
    // No tagged scalp: fit the head to its vertices alone.
  }
  try {
    return fromProxy(character, fitBodyProxy(character, character.skeleton.bone(head).name, scalpPoints));
  } catch (const Error&) {
    return fromProxy(character, BodyProxy{});  // the head drives no vertex: no colliders
  }
}

HairSimParams characterHairParams(const HairDynamicsParams& dynamics) {
  HairSimParams params;
  params.globalRange = 1.0f;
  params.interaction.volume = dynamics.volume;
  params.interaction.friction = dynamics.friction;
  params.adaptiveWisps = dynamics.adaptiveWisps;
  return params;
}

glm::mat4 HairRig::posedFromRest(const std::vector<glm::mat4>& worldFromBone) const {
  if (headBone < 0 || headBone >= int(worldFromBone.size())) return glm::mat4(1.0f);
  return worldFromBone[headBone] * glm::inverse(restWorldFromHead);
}

const std::vector<float>* HairBake::frameAt(float t) const {
  if (frames.empty()) return nullptr;
  const int i = int(std::lround((t - startTime) * fps));
  return &frames[std::clamp(i, 0, frameCount() - 1)];
}

HairBake bakeHair(const Character& character, int clipIndex, const Strands& restGuides, const HairSimParams& params,
                  const HairBakeSettings& settings, const HairBakeCallbacks& callbacks, const HairRig* givenRig) {
  HairBake bake;
  bake.fps = settings.fps > 0.0f ? settings.fps : 60.0f;
  bake.pointsPerStrand = restGuides.pointsPerStrand;
  const bool hasClip = clipIndex >= 0 && clipIndex < int(character.clips.size());
  const float start = hasClip ? character.clips[clipIndex].startTime() : 0.0f;
  const float duration = hasClip ? std::max(0.0f, character.clips[clipIndex].duration()) : 1.0f;
  bake.startTime = start;
  const int frameCount = int(std::floor(duration * bake.fps + 1e-3f)) + 1;
  const float dt = 1.0f / bake.fps;

  const HairRig rig = givenRig ? *givenRig : HairRig::fromCharacter(character);
  HairSimulator simulator(params);
  simulator.setRest(restGuides);
  std::vector<glm::mat4> worldFromBone;
  auto poseAt = [&](float t) {
    character.skeleton.worldTransforms(samplePose(character, hasClip ? clipIndex : -1, t), worldFromBone);
  };
  auto stepAt = [&](float t) {
    poseAt(t);
    const PosedHairColliders body = rig.body.posed(worldFromBone, params.collisionMargin);
    simulator.step(dt, rig.posedFromRest(worldFromBone), &body);
  };

  const int settleSteps = int(std::ceil(std::max(0.0f, settings.settleSeconds) * bake.fps));
  for (int i = 0; i < settleSteps; ++i) stepAt(start);
  bake.frames.reserve(frameCount);
  for (int f = 0; f < frameCount; ++f) {
    if (callbacks.cancelled && callbacks.cancelled()) {
      bake.cancelled = true;
      break;
    }
    if (f > 0 || settleSteps == 0) stepAt(start + float(f) * dt);
    bake.frames.push_back(simulator.positions());
    if (callbacks.progress) callbacks.progress(f + 1, frameCount);
  }
  return bake;
}

}  // namespace mq
