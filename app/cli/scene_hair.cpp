#include "app/cli/scene_hair.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/hair/character_groom.h"
#include "core/mesh/closest_point.h"
#include "core/util/error.h"
#include "core/util/thread_pool.h"
#include "sim/hair/child_follow.h"

namespace mq::cli {
namespace {

glm::vec3 vertexOf(const std::vector<float>& positions, uint32_t v) {
  return {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]};
}

// Orthonormal frame of a triangle: first edge, in-plane perpendicular, normal.
glm::mat3 triangleFrame(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 e = glm::normalize(b - a);
  const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
  return glm::mat3(e, glm::cross(n, e), n);
}

bool degenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  return glm::length(glm::cross(b - a, c - a)) < 1e-12f;
}

}  // namespace

bool sceneHasHair(const LoadedScene& scene) { return !scene.document.hair.is_null(); }

HairSection sceneHairSection(const LoadedScene& scene) {
  try {
    return hairSectionFromJson(scene.document.hair);
  } catch (const FileError&) {
    throw;
  } catch (const Error& e) {
    throw FileError(scene.documentPath, e.what());
  }
}

SceneHair::SceneHair(const LoadedScene& scene, const HairSection& section)
    : scene_(scene), clip_(scene.clipIndex), section_(section) {
  const auto start = std::chrono::steady_clock::now();
  try {
    groom_ = makeSectionGroom(scene.character, section_);
  } catch (const FileError&) {
    throw;
  } catch (const Error& e) {
    throw FileError(scene.documentPath, std::string("hair: ") + e.what());
  }
  groom_->grow(section_.style, section_.strands);
  groomSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rig_ = HairRig::fromProxy(scene.character, groom_->proxy());
  const int head = scene.character.skeleton.findBone(section_.scalp.bone);
  if (head >= 0 && head != rig_.headBone) {
    // The groom's head bone (e.g. found by height on an imported character).
    rig_.headBone = head;
    rig_.restWorldFromHead = scene.character.skeleton.worldTransforms(scene.character.skeleton.restPose())[head];
    rig_.body = HairColliders::attachToSkeleton(groom_->proxy(), scene.character.skeleton, head);
  }
  simulator_.setParams(characterHairParams(section_.style.dynamics));
  simulator_.setRest(leadingStrands(groom_->strands(), groom_->guideCount()));
  anchorRoots();
}

// Each guide root to the nearest triangle of the rest-pose meshes. Only
// triangles near the roots' bounding box are searched.
void SceneHair::anchorRoots() {
  PosedCharacter rest;
  rest.evaluate(scene_.character, -1, 0.0f, nullptr, nullptr);
  const Strands& guides = simulator_.rest();
  const size_t count = simulator_.strandCount();
  const int points = guides.pointsPerStrand;
  auto rootOf = [&](size_t s) { return vertexOf(guides.points, uint32_t(s * points)); };
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (size_t s = 0; s < count; ++s) {
    lo = glm::min(lo, rootOf(s));
    hi = glm::max(hi, rootOf(s));
  }
  lo -= glm::vec3(0.02f);
  hi += glm::vec3(0.02f);
  struct Candidate {
    int mesh;
    uint32_t t;
  };
  std::vector<Candidate> candidates;
  for (size_t m = 0; m < scene_.character.meshes.size(); ++m) {
    const auto& tris = scene_.character.meshes[m].triangles;
    const auto& pos = rest.meshes()[m].positions;
    for (uint32_t t = 0; t < tris.size() / 3; ++t) {
      const glm::vec3 a = vertexOf(pos, tris[3 * t]), b = vertexOf(pos, tris[3 * t + 1]),
                      c = vertexOf(pos, tris[3 * t + 2]);
      const glm::vec3 tlo = glm::min(a, glm::min(b, c)), thi = glm::max(a, glm::max(b, c));
      if (glm::all(glm::lessThanEqual(tlo, hi)) && glm::all(glm::greaterThanEqual(thi, lo)) && !degenerate(a, b, c))
        candidates.push_back({int(m), t});
    }
  }
  anchors_.assign(count, RootAnchor{});
  ThreadPool::shared().parallelFor(0, count, 16, [&](size_t begin, size_t end) {
    for (size_t s = begin; s < end; ++s) {
      const glm::vec3 p = rootOf(s);
      float best = std::numeric_limits<float>::max();
      RootAnchor& anchor = anchors_[s];
      for (const Candidate& c : candidates) {
        const auto& tris = scene_.character.meshes[c.mesh].triangles;
        const auto& pos = rest.meshes()[c.mesh].positions;
        const uint32_t i0 = tris[3 * c.t], i1 = tris[3 * c.t + 1], i2 = tris[3 * c.t + 2];
        const glm::vec3 a = vertexOf(pos, i0), b = vertexOf(pos, i1), v2 = vertexOf(pos, i2);
        const glm::vec3 w = closestTriangleWeights(p, a, b, v2);
        const glm::vec3 q = w.x * a + w.y * b + w.z * v2;
        const float d = glm::dot(p - q, p - q);
        if (d < best) {
          best = d;
          anchor.mesh = c.mesh;
          anchor.corner[0] = i0;
          anchor.corner[1] = i1;
          anchor.corner[2] = i2;
          anchor.barycentric = w;
          anchor.restFrame = triangleFrame(a, b, v2);
          anchor.localOffset = glm::transpose(anchor.restFrame) * (p - q);
        }
      }
    }
  });
  rootPositions_.resize(count);
  rootRotations_.resize(count);
}

void SceneHair::poseAt(float time) {
  posed_.evaluate(scene_.character, clip_, time, &scene_.edits, &ThreadPool::shared());
  body_ = rig_.body.posed(posed_.worldFromBone(), simulator_.params().collisionMargin);
  updateRootTargets();
}

// Root targets on the posed mesh; a root without a triangle (no mesh near
// it) rides on the head bone.
void SceneHair::updateRootTargets() {
  const glm::mat4 headMotion = rig_.posedFromRest(posed_.worldFromBone());
  const glm::quat headRotation = glm::quat_cast(glm::mat3(headMotion));
  const Strands& guides = simulator_.rest();
  for (size_t s = 0; s < anchors_.size(); ++s) {
    const RootAnchor& anchor = anchors_[s];
    if (anchor.mesh < 0) {
      rootPositions_[s] =
          glm::vec3(headMotion * glm::vec4(vertexOf(guides.points, uint32_t(s * guides.pointsPerStrand)), 1.0f));
      rootRotations_[s] = headRotation;
      continue;
    }
    const auto& pos = posed_.meshes()[anchor.mesh].positions;
    const glm::vec3 a = vertexOf(pos, anchor.corner[0]), b = vertexOf(pos, anchor.corner[1]),
                    c = vertexOf(pos, anchor.corner[2]);
    if (degenerate(a, b, c)) {
      rootRotations_[s] = headRotation;
      rootPositions_[s] = anchor.barycentric.x * a + anchor.barycentric.y * b + anchor.barycentric.z * c;
      continue;
    }
    const glm::mat3 frame = triangleFrame(a, b, c);
    rootPositions_[s] =
        anchor.barycentric.x * a + anchor.barycentric.y * b + anchor.barycentric.z * c + frame * anchor.localOffset;
    rootRotations_[s] = glm::normalize(glm::quat_cast(frame * glm::transpose(anchor.restFrame)));
  }
}

void SceneHair::step(float time, float dt) {
  poseAt(time);
  simulator_.step(dt, rootPositions_, rootRotations_, &body_);
}

void SceneHair::settle(float time, float seconds, float fps) {
  const int steps = int(std::ceil(std::max(0.0f, seconds) * fps));
  for (int i = 0; i < steps; ++i) step(time, 1.0f / fps);
}

const std::vector<float>& SceneHair::updateAllStrands() {
  poseGroomedStrands(groom_->strands(), simulator_, all_, &body_);
  return all_;
}

const std::vector<float>& SceneHair::rigidStrands(float time) {
  poseAt(time);
  const glm::mat4 motion = rig_.posedFromRest(posed_.worldFromBone());
  const std::vector<float>& rest = groom_->strands().points;
  all_.resize(rest.size());
  for (size_t k = 0; k < rest.size(); k += 3) {
    const glm::vec3 p = glm::vec3(motion * glm::vec4(rest[k], rest[k + 1], rest[k + 2], 1.0f));
    all_[k] = p.x;
    all_[k + 1] = p.y;
    all_[k + 2] = p.z;
  }
  return all_;
}

SceneHair::InsideCount SceneHair::pointsInsideBody() const {
  const PosedHairColliders exact = rig_.body.posed(posed_.worldFromBone(), 0.0f);
  const size_t perStrand = size_t(std::max(1, groom_->strands().pointsPerStrand));
  InsideCount count;
  for (size_t k = 0; k + 2 < all_.size(); k += 3) {
    if (!exact.contains({all_[k], all_[k + 1], all_[k + 2]})) continue;
    if ((k / 3) % perStrand == 0)
      ++count.roots;
    else
      ++count.points;
  }
  return count;
}

float SceneHair::maxGuideLengthError() const {
  const std::vector<float>& now = simulator_.positions();
  const std::vector<float>& rest = simulator_.rest().points;
  const int points = simulator_.pointsPerStrand();
  float worst = 0.0f;
  for (size_t s = 0; s < simulator_.strandCount(); ++s)
    for (int i = 1; i < points; ++i) {
      const uint32_t k = uint32_t(s * points + i);
      const float restLength = glm::length(vertexOf(rest, k) - vertexOf(rest, k - 1));
      if (restLength <= 0.0f) continue;
      const float length = glm::length(vertexOf(now, k) - vertexOf(now, k - 1));
      worst = std::max(worst, std::abs(length - restLength) / restLength);
    }
  return worst;
}

}  // namespace mq::cli
