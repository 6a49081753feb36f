#include "core/skinning/section_cones.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "core/character/character.h"
#include "core/mesh/plane_section.h"
#include "core/mesh/position_weld.h"
#include "core/skeleton/skeleton.h"
#include "core/util/thread_pool.h"

namespace mq {

namespace {
constexpr size_t kMinChunk = 2048;
// A cone wider than this fraction of its bone is not a limb (the pelvis,
// the chest, a clavicle cut across the torso): it gets no crease.
constexpr double kLimbWidth = 0.6;
// A vertex keeps to a joint's plane within this many limb radii of it.
constexpr double kCreaseReach = 3.0;
// The gap left between the two sides of a crease, per metre of the child
// bone (so touching skins do not lie in one plane).
constexpr double kCreaseGap = 0.005;

glm::dvec2 lerp2(const glm::dvec2& a, const glm::dvec2& b, double t) { return a + t * (b - a); }

double baseParameter(double s) {
  return std::clamp((s - SectionCone::kBaseNear) / (SectionCone::kBaseFar - SectionCone::kBaseNear), 0.0, 1.0);
}

}  // namespace

SectionCone::Point SectionCone::locate(const glm::dvec3& p) const {
  Point out;
  const glm::dvec3 d = p - head;
  out.s = glm::dot(d, axis) / length;
  const double t = baseParameter(out.s);
  const glm::dvec2 across(glm::dot(d, side), glm::dot(d, front));
  const glm::dvec2 fromMinimum = across - lerp2(minimum[0].center, minimum[1].center, t);
  const double r = glm::length(fromMinimum);
  out.radial = fromMinimum.x * side + fromMinimum.y * front;
  if (r <= 0.0) return out;
  const glm::dvec2 dir = fromMinimum / r;
  out.rho = r / ((1.0 - t) * minimum[0].radius(dir) + t * minimum[1].radius(dir));
  const glm::dvec2 fromEnclosing = across - lerp2(enclosing[0].center, enclosing[1].center, t);
  const double re = glm::length(fromEnclosing);
  out.rhoEnclosing =
      re > 0.0
          ? re / ((1.0 - t) * enclosing[0].radius(fromEnclosing / re) + t * enclosing[1].radius(fromEnclosing / re))
          : 0.0;
  return out;
}

namespace {

// The mesh with bit-equal positions merged, so its sections close.
struct WeldedSkin {
  std::vector<float> positions;
  std::vector<uint32_t> triangles;
};

WeldedSkin weld(const Mesh& mesh) {
  PositionWeld weld = weldByPosition(mesh.positions, mesh.triangles);
  return {weld.gather(mesh.positions), std::move(weld.triangles)};
}

int dominantSlot(const SkinBinding& skin, size_t v) {
  const int k = skin.influencesPerVertex;
  int best = 0;
  for (int i = 1; i < k; ++i)
    if (skin.weights[v * k + i] > skin.weights[v * k + best]) best = i;
  return best;
}

// Skin joint per bone (-1 when the bone is not a joint of this skin).
std::vector<int> jointOfBone(const SkinBinding& skin, int bones) {
  std::vector<int> out(bones, -1);
  for (size_t j = 0; j < skin.jointBones.size(); ++j)
    if (skin.jointBones[j] >= 0 && skin.jointBones[j] < bones) out[skin.jointBones[j]] = int(j);
  return out;
}

// The nearest skin-joint ancestor of a bone, or -1.
int parentJoint(const Skeleton& skeleton, const std::vector<int>& jointOf, int bone) {
  for (int b = skeleton.bone(bone).parent; b >= 0; b = skeleton.bone(b).parent)
    if (jointOf[b] >= 0) return jointOf[b];
  return -1;
}

// Fits one base: the section loop around the axis at s, in the cone's chart.
bool fitBase(const WeldedSkin& skin, SectionCone& cone, double s, Ellipse2& minimum, Ellipse2& enclosing) {
  const PlaneChart chart(cone.head + s * cone.length * cone.axis, cone.axis);
  const std::vector<Polygon2> loops = sectionLoops(skin.positions, skin.triangles, chart);
  const Polygon2* loop = loopAround(loops, glm::dvec2(0.0));
  if (!loop) return false;
  std::vector<glm::dvec2> points;
  points.reserve(loop->size());
  for (const glm::dvec2& q : *loop) {
    const glm::dvec3 offset = q.x * chart.u + q.y * chart.v;
    points.emplace_back(glm::dot(offset, cone.side), glm::dot(offset, cone.front));
  }
  minimum = momentEllipse(points);
  enclosing = enclosingEllipse(points);
  return minimum.valid() && enclosing.valid();
}

SectionCone fitCone(const Mesh& mesh, const WeldedSkin& welded, const Skeleton& skeleton,
                    const std::vector<int>& jointOf, int joint) {
  const SkinBinding& skin = mesh.skin;
  SectionCone cone;
  const glm::dmat4 meshFromBone = glm::inverse(glm::dmat4(skin.inverseBind[joint]));
  cone.head = glm::dvec3(meshFromBone[3]);
  const glm::dvec3 boneY = glm::normalize(glm::dvec3(meshFromBone[1]));
  // The tail: the child joint the bone's Y axis points at best, either way
  // (a mirrored rig's right side points its bones back at their parents),
  // else (a leaf) the farthest of the bone's own vertices along its Y axis,
  // on the side where they reach farther.
  glm::dvec3 tail = cone.head;
  double best = 0.0;
  const int bone = skin.jointBones[joint];
  for (int child : skeleton.children(bone)) {
    if (jointOf[child] < 0) continue;
    const glm::dvec3 head(glm::inverse(glm::dmat4(skin.inverseBind[jointOf[child]]))[3]);
    const glm::dvec3 d = head - cone.head;
    const double len = glm::length(d);
    if (len <= 0.0) continue;
    const double alignment = std::abs(glm::dot(d / len, boneY));
    if (alignment > best) best = alignment, tail = head;
  }
  if (best <= 0.0) {
    double up = 0.0, down = 0.0;
    for (size_t v = 0; v < mesh.vertexCount(); ++v)
      if (skin.joints[v * skin.influencesPerVertex + dominantSlot(skin, v)] == joint) {
        const double along = glm::dot(glm::dvec3(mesh.position(v)) - cone.head, boneY);
        up = std::max(up, along), down = std::max(down, -along);
      }
    tail = cone.head + (up >= down ? up : -down) * boneY;
  }
  cone.length = glm::length(tail - cone.head);
  if (cone.length <= 1e-6) return cone;
  cone.axis = (tail - cone.head) / cone.length;
  glm::dvec3 x = glm::dvec3(meshFromBone[0]);
  x -= glm::dot(x, cone.axis) * cone.axis;
  if (glm::length(x) < 1e-6)
    x = std::abs(cone.axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0),
    x -= glm::dot(x, cone.axis) * cone.axis;
  cone.side = glm::normalize(x);
  cone.front = glm::cross(cone.side, cone.axis);
  cone.valid = fitBase(welded, cone, SectionCone::kBaseNear, cone.minimum[0], cone.enclosing[0]) &&
               fitBase(welded, cone, SectionCone::kBaseFar, cone.minimum[1], cone.enclosing[1]);
  cone.limb = cone.valid && std::max(cone.enclosing[0].a, cone.enclosing[1].a) <= kLimbWidth * cone.length;
  return cone;
}

void buildAdjacency(const Mesh& mesh, SectionCones& out) {
  const size_t n = mesh.vertexCount();
  out.triangleStart.assign(n + 1, 0);
  for (uint32_t index : mesh.triangles) ++out.triangleStart[index + 1];
  for (size_t v = 0; v < n; ++v) out.triangleStart[v + 1] += out.triangleStart[v];
  out.triangleList.resize(mesh.triangles.size());
  std::vector<uint32_t> fill(out.triangleStart.begin(), out.triangleStart.end() - 1);
  for (size_t i = 0; i < mesh.triangles.size(); ++i) out.triangleList[fill[mesh.triangles[i]]++] = uint32_t(i / 3);
}

}  // namespace

std::vector<SectionCone> fitSectionCones(const Mesh& mesh, const Skeleton& skeleton) {
  const SkinBinding& skin = mesh.skin;
  std::vector<SectionCone> cones(skin.jointBones.size());
  if (skin.empty()) return cones;
  const WeldedSkin welded = weld(mesh);
  const std::vector<int> jointOf = jointOfBone(skin, skeleton.boneCount());
  for (size_t j = 0; j < cones.size(); ++j)
    if (skin.jointBones[j] >= 0 && skin.jointBones[j] < skeleton.boneCount())
      cones[j] = fitCone(mesh, welded, skeleton, jointOf, int(j));
  return cones;
}

std::vector<int> skinJointParents(const SkinBinding& skin, const Skeleton& skeleton) {
  const std::vector<int> jointOf = jointOfBone(skin, skeleton.boneCount());
  std::vector<int> parentOf(skin.jointBones.size(), -1);
  for (size_t j = 0; j < parentOf.size(); ++j) {
    const int bone = skin.jointBones[j];
    if (bone >= 0 && bone < skeleton.boneCount()) parentOf[j] = parentJoint(skeleton, jointOf, bone);
  }
  return parentOf;
}

std::shared_ptr<const SectionCones> bindSectionCones(const Mesh& mesh, const Skeleton& skeleton) {
  auto out = std::make_shared<SectionCones>();
  const SkinBinding& skin = mesh.skin;
  if (skin.empty()) return out;
  const int joints = int(skin.jointBones.size());
  const std::vector<int> parentOf = skinJointParents(skin, skeleton);
  out->cones = fitSectionCones(mesh, skeleton);

  const size_t n = mesh.vertexCount();
  out->creaseJoint.assign(n, -1);
  out->creaseBound.assign(n, 0.0f);
  out->creaseSide.assign(n, 0);
  out->parentJoint.assign(parentOf.begin(), parentOf.end());
  std::vector<std::vector<int>> childrenOf(joints);
  for (int j = 0; j < joints; ++j)
    if (parentOf[j] >= 0) childrenOf[parentOf[j]].push_back(j);
  for (size_t v = 0; v < n; ++v) {
    // The nearest joint between the dominant bone and its parent or one of
    // its children, when the vertex lies within its reach and both bones are
    // limbs. (Creases at the shoulder and hip, where the parent is the
    // torso, lowered the DQS bulge there but added folds on the walk.)
    const glm::dvec3 p(mesh.position(v));
    const int dominant = skin.joints[v * skin.influencesPerVertex + dominantSlot(skin, v)];
    int nearest = -1;
    double nearestDistance = 0.0;
    auto consider = [&](int child) {
      const SectionCone& cone = out->cones[child];
      if (parentOf[child] < 0 || !cone.limb || !out->cones[parentOf[child]].limb) return;
      const double reach = kCreaseReach * std::max(cone.enclosing[0].a, cone.enclosing[1].a);
      const double distance = glm::length(p - cone.head);
      if (distance < reach && (nearest < 0 || distance < nearestDistance)) nearest = child, nearestDistance = distance;
    };
    consider(dominant);
    for (int child : childrenOf[dominant]) consider(child);
    if (nearest < 0) continue;
    // The rest side, and how near the plane the vertex may come: the gap,
    // or its rest distance when it starts closer (so the rest pose holds).
    const SectionCone& cone = out->cones[nearest];
    const double restHeight = glm::dot(p - cone.head, cone.axis);
    const double gap = kCreaseGap * cone.length;
    out->creaseJoint[v] = int16_t(nearest);
    out->creaseSide[v] = restHeight < 0.0 ? -1 : 1;
    out->creaseBound[v] = float(restHeight < 0.0 ? std::max(restHeight, -gap) : std::min(restHeight, gap));
    out->visited.push_back(uint32_t(v));
  }
  buildAdjacency(mesh, *out);
  return out;
}

namespace {

glm::dvec3 transformPoint(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

struct JointFrames {
  std::vector<glm::dmat4> worldFromMesh, meshFromWorld;
  std::vector<glm::dvec3> creasePoint, creaseNormal;  // per child joint: its posed joint plane
};

JointFrames framesOf(const SkinBinding& skin, const std::vector<glm::mat4>& worldFromBone) {
  JointFrames f;
  f.worldFromMesh.resize(skin.jointBones.size());
  f.meshFromWorld.resize(skin.jointBones.size());
  for (size_t j = 0; j < skin.jointBones.size(); ++j) {
    const int bone = skin.jointBones[j];
    const glm::mat4 world = bone >= 0 && bone < int(worldFromBone.size()) ? worldFromBone[bone] : glm::mat4(1.0f);
    f.worldFromMesh[j] = glm::dmat4(world) * glm::dmat4(skin.inverseBind[j]);
    f.meshFromWorld[j] = glm::inverse(f.worldFromMesh[j]);
  }
  return f;
}

// The joint plane of each child joint: through its posed head, normal to its
// rest axis turned half way between the parent's and its own rotation.
void creasePlanes(const SectionCones& cones, JointFrames& f) {
  const size_t joints = cones.cones.size();
  f.creasePoint.assign(joints, glm::dvec3(0.0));
  f.creaseNormal.assign(joints, glm::dvec3(0.0));
  for (size_t j = 0; j < joints; ++j) {
    const int parent = cones.parentJoint[j];
    if (parent < 0 || !cones.cones[j].limb) continue;
    const glm::dquat qa = glm::normalize(glm::quat_cast(glm::dmat3(f.worldFromMesh[parent])));
    const glm::dquat qb = glm::normalize(glm::quat_cast(glm::dmat3(f.worldFromMesh[j])));
    const glm::dquat half = glm::slerp(qa, glm::dot(qa, qb) < 0.0 ? -qb : qb, 0.5);
    f.creasePoint[j] = transformPoint(f.worldFromMesh[j], cones.cones[j].head);
    f.creaseNormal[j] = glm::normalize(half * cones.cones[j].axis);
  }
}

// Keeps the vertex on its side of its joint's plane (a crease where the two
// limbs meet instead of skin crossing skin).
glm::dvec3 creaseCorrection(const SectionCones& cones, const JointFrames& frames, size_t v, const glm::dvec3& p) {
  const int joint = cones.creaseJoint[v];
  if (joint < 0 || frames.creaseNormal[joint] == glm::dvec3(0.0)) return glm::dvec3(0.0);
  const double h = glm::dot(p - frames.creasePoint[joint], frames.creaseNormal[joint]);
  const double bound = cones.creaseBound[v];
  if (cones.creaseSide[v] < 0 ? h <= bound : h >= bound) return glm::dvec3(0.0);
  return (bound - h) * frames.creaseNormal[joint];
}

void recomputeNormal(const Mesh& mesh, const SectionCones& cones, const float* positions, size_t v, float* normals) {
  glm::dvec3 sum(0.0);
  for (uint32_t i = cones.triangleStart[v]; i < cones.triangleStart[v + 1]; ++i) {
    const uint32_t t = cones.triangleList[i];
    const uint32_t* tri = &mesh.triangles[3 * size_t(t)];
    auto at = [&](uint32_t q) { return glm::dvec3(positions[3 * q], positions[3 * q + 1], positions[3 * q + 2]); };
    sum += glm::cross(at(tri[1]) - at(tri[0]), at(tri[2]) - at(tri[0]));
  }
  const double len = glm::length(sum);
  if (len <= 0.0) return;
  for (int d = 0; d < 3; ++d) normals[3 * v + d] = float(sum[d] / len);
}

}  // namespace

void correctWithSectionCones(const Mesh& mesh, const SectionCones& cones, const std::vector<glm::mat4>& worldFromBone,
                             float* positions, float* normals, ThreadPool* pool) {
  JointFrames frames = framesOf(mesh.skin, worldFromBone);
  creasePlanes(cones, frames);

  std::vector<uint8_t> moved(cones.visited.size(), 0);
  auto correct = [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const size_t v = cones.visited[i];
      glm::dvec3 p(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
      const glm::dvec3 push = creaseCorrection(cones, frames, v, p);
      if (push == glm::dvec3(0.0)) continue;
      p += push;
      moved[i] = 1;
      for (int d = 0; d < 3; ++d) positions[3 * v + d] = float(p[d]);
    }
  };
  if (pool)
    pool->parallelFor(0, cones.visited.size(), kMinChunk, correct);
  else
    correct(0, cones.visited.size());
  if (!normals) return;
  auto renormal = [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i)
      if (moved[i]) recomputeNormal(mesh, cones, positions, cones.visited[i], normals);
  };
  if (pool)
    pool->parallelFor(0, cones.visited.size(), kMinChunk, renormal);
  else
    renormal(0, cones.visited.size());
}

}  // namespace mq
