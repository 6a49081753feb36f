#include "core/skinning/skin_report.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include <glm/gtc/quaternion.hpp>

#include "core/character/implicit_body.h"
#include "core/mesh/mesh_checks.h"
#include "core/skeleton/humanoid_roles.h"
#include "core/skinning/skin_metrics.h"
#include "core/util/error.h"

namespace mq {

void rotateBoneAboutWorldAxis(const Skeleton& skeleton, Pose& pose, int bone, const glm::vec3& worldAxis,
                              float degrees) {
  const std::vector<glm::mat4> world = skeleton.worldTransforms(pose);
  const glm::quat w = glm::normalize(glm::quat_cast(glm::mat3(world[bone])));
  const glm::quat q = glm::angleAxis(glm::radians(degrees), glm::normalize(worldAxis));
  pose[bone].rotation = glm::normalize(pose[bone].rotation * (glm::inverse(w) * q * w));
}

namespace {

// The test poses scale their measuring radii with the body: the brief's
// radii are for a 1.75 m mannequin.
constexpr double kReferenceHeight = 1.75;

glm::dvec3 headOf(const std::vector<glm::mat4>& world, int bone) { return glm::dvec3(world[bone][3]); }

// Where the character faces: the roles' facing when the feet give one, +Z
// (the glTF convention) otherwise.
glm::vec3 frontOf(const HumanoidBones& roles) {
  return glm::length(roles.facing) > 0.5f ? roles.facing : glm::vec3(0, 0, 1);
}

glm::dvec3 direction(const std::vector<glm::mat4>& world, int from, int to) {
  return glm::normalize(headOf(world, to) - headOf(world, from));
}

class Measurer {
 public:
  Measurer(const Character& character, const SkinReportOptions& options, ThreadPool* pool)
      : character_(character), options_(options), pool_(pool), body_(character) {
    posed_.evaluate(character, character.skeleton.restPose(), {}, pool);
    rest_ = body_.weld(posed_.meshes());
    restWorld_ = posed_.worldFromBone();
    restVolume_ = signedVolume(rest_, body_.triangles());
  }

  const MetricBody& body() const { return body_; }
  const std::vector<float>& rest() const { return rest_; }
  const std::vector<glm::mat4>& restWorld() const { return restWorld_; }

  std::vector<float> posedBy(const Pose& pose, std::vector<glm::mat4>* world = nullptr) {
    posed_.evaluate(character_, pose, {}, pool_);
    if (world) *world = posed_.worldFromBone();
    return body_.weld(posed_.meshes());
  }
  std::vector<float> posedAt(int clip, float time, const PoseEdits* edits = nullptr) {
    posed_.evaluate(character_, clip, time, edits, pool_);
    return body_.weld(posed_.meshes());
  }
  // M6 over the meshes built from an implicit body, from the last
  // evaluation; nothing when the character has no such mesh.
  std::optional<BodyDeviation> implicitDeviation(const glm::dvec3& jointRest, double radius) const {
    BodyDeviation all;
    double sum = 0.0, squares = 0.0, beyond = 0.0;
    const std::vector<glm::mat4> worldFromBind = worldFromBindOf(posed_.worldFromBone());
    for (size_t i = 0; i < character_.meshes.size(); ++i) {
      const Mesh& mesh = character_.meshes[i];
      if (!mesh.implicitBody) continue;
      const BodyDeviation d = implicitBodyDeviation(mesh.implicitBody->posed(worldFromBind), mesh.positions,
                                                    posed_.meshes()[i].positions, jointRest, radius);
      const double n = double(d.vertices);
      all.vertices += d.vertices;
      sum += d.mean * n;
      squares += d.rms * d.rms * n;
      beyond += d.beyond2mm * n;
      all.largest = std::max(all.largest, d.largest);
    }
    if (all.vertices == 0) return std::nullopt;
    const double n = double(all.vertices);
    all.mean = sum / n;
    all.rms = std::sqrt(squares / n);
    all.beyond2mm = beyond / n;
    return all;
  }
  long intersections(const std::vector<float>& positions) const {
    return options_.intersections ? long(intersectingPairs(positions, body_.triangles())) : -1;
  }
  // Each bone's transform from the rest (bind) pose to `world`.
  std::vector<glm::mat4> worldFromBindOf(const std::vector<glm::mat4>& world) const {
    std::vector<glm::mat4> out(world.size());
    for (size_t b = 0; b < world.size() && b < restWorld_.size(); ++b) out[b] = world[b] * glm::inverse(restWorld_[b]);
    return out;
  }
  double volumeRatio(const std::vector<float>& positions) const {
    return restVolume_ != 0.0 ? signedVolume(positions, body_.triangles()) / restVolume_ : 1.0;
  }

 private:
  const Character& character_;
  const SkinReportOptions& options_;
  ThreadPool* pool_;
  MetricBody body_;
  PosedCharacter posed_;
  std::vector<float> rest_;
  std::vector<glm::mat4> restWorld_;
  double restVolume_ = 0.0;
};

// The rest pose against LBS at the rest pose (where every skinning matrix is
// the bind matrix), relative to the body's size.
double restErrorOf(const Character& character, ThreadPool* pool) {
  PosedCharacter posed, reference;
  posed.evaluate(character, character.skeleton.restPose(), {}, pool);
  Character asLbs = character;
  asLbs.skinning = SkinningMethod::Lbs;
  reference.evaluate(asLbs, asLbs.skeleton.restPose(), {}, pool);
  double worst = 0.0;
  Aabb box;
  for (size_t m = 0; m < character.meshes.size(); ++m) {
    const std::vector<float>& a = posed.meshes()[m].positions;
    const std::vector<float>& b = reference.meshes()[m].positions;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, double(std::abs(a[i] - b[i])));
    for (size_t i = 0; i + 2 < b.size(); i += 3) box.extend({b[i], b[i + 1], b[i + 2]});
  }
  return box.valid() && box.diagonal() > 0.0f ? worst / box.diagonal() : 0.0;
}

struct Hinge {
  const char* name;
  int parent, bone, child;  // the bent bone's parent, the bone, and the bone its direction points to
  double sign;              // +1 bends forward about cross(d_bone, front), -1 backward
  double radius;            // M3 radius at the reference height
  std::vector<float> angles;
  bool outerSection;  // M1 applies (a hinge between two long bones)
};

void measureHingePoses(Measurer& m, const Character& character, const HumanoidBones& roles, double scale,
                       std::vector<PoseMeasure>& out) {
  const glm::vec3 front = frontOf(roles);
  const std::vector<Hinge> hinges = {
      {"elbow", roles.upperArm[0], roles.forearm[0], roles.hand[0], 1.0, 0.08, {90, 120, 150}, true},
      {"knee", roles.thigh[0], roles.shin[0], roles.foot[0], -1.0, 0.10, {90, 120, 150}, true},
      {"hip", roles.pelvis, roles.thigh[0], roles.shin[0], 1.0, 0.12, {45, 90, 120}, false},
      {"wrist", roles.forearm[0], roles.hand[0], -1, 1.0, 0.05, {45, 90}, false},
  };
  const auto& restWorld = m.restWorld();
  for (const Hinge& h : hinges) {
    // The wrist turns about the forearm's hinge axis (the hand may have no child).
    const glm::dvec3 dBone =
        h.child >= 0 ? direction(restWorld, h.bone, h.child) : direction(restWorld, h.parent, h.bone);
    const glm::dvec3 axis = glm::normalize(glm::cross(dBone, glm::dvec3(front)));
    for (float angle : h.angles) {
      PoseMeasure pm;
      pm.name = std::string(h.name) + " " + std::to_string(int(angle));
      Pose pose = character.skeleton.restPose();
      rotateBoneAboutWorldAxis(character.skeleton, pose, h.bone, glm::vec3(axis), float(h.sign * angle));
      std::vector<glm::mat4> world;
      const std::vector<float> posed = m.posedBy(pose, &world);
      const glm::dvec3 joint = headOf(restWorld, h.bone);
      if (h.outerSection) {
        BendFrame bend;
        bend.jointRest = joint;
        bend.jointPosed = headOf(world, h.bone);
        bend.parentRest = direction(restWorld, h.parent, h.bone);
        bend.childRest = dBone;
        bend.parentPosed = direction(world, h.parent, h.bone);
        bend.childPosed = direction(world, h.bone, h.child);
        bend.inward = h.sign * glm::normalize(glm::cross(axis, dBone));
        const OuterSection section = outerSection(m.rest(), posed, m.body().triangles(), bend);
        pm.thickness = section.thickness;
        pm.halfArea = section.halfArea;
      }
      pm.localVolume =
          localVolumeRatio(m.rest(), posed, m.body().triangles(), joint, headOf(world, h.bone), h.radius * scale);
      if (const std::optional<BodyDeviation> deviation = m.implicitDeviation(joint, h.radius * scale)) {
        pm.deviationRms = deviation->rms;
        pm.deviationMean = deviation->mean;
      }
      pm.intersections = m.intersections(posed);
      out.push_back(pm);
    }
  }
}

void measureTwists(Measurer& m, const Character& character, const HumanoidBones& roles, double scale,
                   std::vector<PoseMeasure>& out) {
  struct Twist {
    const char* name;
    int parent, bone;
    double from, to;  // the M2 band along the parent's axis, metres at the reference height
  };
  const Twist twists[] = {{"wrist twist", roles.forearm[0], roles.hand[0], -0.12, 0.03},
                          {"forearm twist", roles.upperArm[0], roles.forearm[0], -0.06, 0.06}};
  const auto& restWorld = m.restWorld();
  for (const Twist& t : twists) {
    const glm::dvec3 axis = direction(restWorld, t.parent, t.bone);
    for (float angle : {90.0f, 180.0f}) {
      PoseMeasure pm;
      pm.name = std::string(t.name) + " " + std::to_string(int(angle));
      Pose pose = character.skeleton.restPose();
      rotateBoneAboutWorldAxis(character.skeleton, pose, t.bone, glm::vec3(axis), angle);
      const std::vector<float> posed = m.posedBy(pose);
      pm.twistSection = minimumSectionRatio(m.rest(), posed, m.body().triangles(), headOf(restWorld, t.bone), axis,
                                            t.from * scale, t.to * scale, 0.01 * scale);
      pm.intersections = m.intersections(posed);
      out.push_back(pm);
    }
  }
}

void measureShoulder(Measurer& m, const Character& character, const HumanoidBones& roles, double scale,
                     std::vector<PoseMeasure>& out) {
  const glm::vec3 front = frontOf(roles);
  const auto& restWorld = m.restWorld();
  for (float angle : {60.0f, 95.0f, 120.0f}) {
    PoseMeasure pm;
    pm.name = "shoulder " + std::to_string(int(angle));
    Pose pose = character.skeleton.restPose();
    rotateBoneAboutWorldAxis(character.skeleton, pose, roles.upperArm[0], front, angle);
    std::vector<glm::mat4> world;
    const std::vector<float> posed = m.posedBy(pose, &world);
    pm.localVolume = localVolumeRatio(m.rest(), posed, m.body().triangles(), headOf(restWorld, roles.upperArm[0]),
                                      headOf(world, roles.upperArm[0]), 0.12 * scale);
    pm.intersections = m.intersections(posed);
    out.push_back(pm);
  }
}

// clip -1: the rest pose with `edits`, as one frame.
ClipMeasure measureClip(Measurer& m, const Character& character, int clip, float fps, const PoseEdits* edits) {
  ClipMeasure cm;
  int frames = 1;
  float start = 0.0f;
  if (clip >= 0) {
    const Clip& c = character.clips[clip];
    cm.name = c.name.empty() ? std::to_string(clip) : c.name;
    frames = std::max(1, int(std::floor(c.duration() * fps + 1e-4f)) + 1);
    start = c.startTime();
    edits = nullptr;
  } else {
    cm.name = "rest";
  }
  long total = 0;
  cm.worstIntersections = -1;
  for (int f = 0; f < frames; ++f) {
    const float time = start + f / fps;
    const std::vector<float> posed = m.posedAt(clip, time, edits);
    const long pairs = m.intersections(posed);
    total += std::max(0L, pairs);
    if (pairs > cm.worstIntersections) cm.worstIntersections = pairs, cm.worstTime = time;
    const double v = m.volumeRatio(posed);
    cm.minVolume = std::min(cm.minVolume, v);
    cm.maxVolume = std::max(cm.maxVolume, v);
  }
  cm.frames = frames;
  cm.meanIntersections = double(total) / frames;
  return cm;
}

}  // namespace

SkinReport measureSkinning(const Character& character, const SkinReportOptions& options, ThreadPool* pool) {
  SkinReport report;
  report.method =
      std::string(skinningMethodName(character.skinning)) + (character.helperBones.empty() ? "" : " + helper bones");
  Measurer m(character, options, pool);
  report.vertices = m.body().vertexCount();
  report.triangles = m.body().triangles().size() / 3;
  report.restError = restErrorOf(character, pool);
  if (options.poses) {
    try {
      const HumanoidBones roles = findHumanoidBones(character.skeleton, m.restWorld());
      Aabb box;
      for (size_t i = 0; i + 2 < m.rest().size(); i += 3) box.extend({m.rest()[i], m.rest()[i + 1], m.rest()[i + 2]});
      const double scale = box.valid() ? (box.max.y - box.min.y) / kReferenceHeight : 1.0;
      measureHingePoses(m, character, roles, scale, report.poses);
      measureTwists(m, character, roles, scale, report.poses);
      measureShoulder(m, character, roles, scale, report.poses);
    } catch (const Error& e) {
      report.notes.push_back(std::string("no test poses: ") + e.what());
    }
  }
  if (options.clips && options.clip != SkinReportOptions::kEveryClip)
    report.clips.push_back(measureClip(m, character, options.clip, options.clipFps, options.edits));
  else if (options.clips)
    for (int c = 0; c < int(character.clips.size()); ++c)
      report.clips.push_back(measureClip(m, character, c, options.clipFps, nullptr));
  return report;
}

}  // namespace mq
