#include "render/test_figure.h"

#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace mq::test {
namespace {

struct Part {
  int bone;
  glm::vec3 centre;
  glm::mat3 axes;   // columns: the ellipsoid's axes
  glm::vec3 radii;  // along the axes
};

// An ellipsoid spanning a..b (a little past both ends) with radius r across.
Part limb(int bone, glm::vec3 a, glm::vec3 b, float r) {
  const glm::vec3 axis = b - a;
  const float length = glm::length(axis);
  const glm::vec3 y = axis / length;
  const glm::vec3 ref = std::abs(y.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
  const glm::vec3 x = glm::normalize(glm::cross(y, ref));
  const glm::vec3 z = glm::cross(x, y);
  return {bone, 0.5f * (a + b), glm::mat3(x, y, z), {r, 0.5f * length + 0.5f * r, r}};
}

Part blob(int bone, glm::vec3 centre, glm::vec3 radii) { return {bone, centre, glm::mat3(1.0f), radii}; }

void addEllipsoid(const Part& part, Mesh& mesh, std::vector<uint16_t>& joints) {
  constexpr int kRings = 14, kSegments = 20;
  const uint32_t base = static_cast<uint32_t>(mesh.vertexCount());
  for (int i = 0; i <= kRings; ++i) {
    const float theta = static_cast<float>(M_PI) * i / kRings;
    for (int j = 0; j < kSegments; ++j) {
      const float phi = 2.0f * static_cast<float>(M_PI) * j / kSegments;
      const glm::vec3 unit(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      const glm::vec3 p = part.centre + part.axes * (unit * part.radii);
      mesh.positions.insert(mesh.positions.end(), {p.x, p.y, p.z});
      joints.push_back(static_cast<uint16_t>(part.bone));
    }
  }
  for (int i = 0; i < kRings; ++i)
    for (int j = 0; j < kSegments; ++j) {
      const uint32_t a = base + i * kSegments + j, b = base + i * kSegments + (j + 1) % kSegments;
      const uint32_t c = a + kSegments, d = b + kSegments;
      mesh.triangles.insert(mesh.triangles.end(), {a, b, c, b, d, c});
    }
}

Track rotationTrack(const glm::vec3& axis, float degrees) {
  Track track;
  track.components = 4;
  track.isRotation = true;
  track.times = {0.0f, 1.0f};
  const glm::quat end = glm::angleAxis(glm::radians(degrees), axis);
  track.values = {0.0f, 0.0f, 0.0f, 1.0f, end.x, end.y, end.z, end.w};
  return track;
}

}  // namespace

Character makeTestFigure() {
  Character c;
  c.name = "test figure";
  c.sourcePath = "test";
  std::vector<glm::vec3> world;  // rest joint positions
  auto add = [&](const std::string& name, int parent, glm::vec3 position) {
    Bone bone;
    bone.name = name;
    bone.parent = parent;
    bone.rest.translation = parent >= 0 ? position - world[parent] : position;
    world.push_back(position);
    return c.skeleton.addBone(bone);
  };
  const int pelvis = add("pelvis", -1, {0, 0.95f, 0});
  const int spine = add("spine", pelvis, {0, 1.07f, 0});
  const int chest = add("chest", spine, {0, 1.25f, 0});
  const int neck = add("neck", chest, {0, 1.47f, 0});
  const int head = add("head", neck, {0, 1.57f, 0});
  std::vector<Part> parts = {
      blob(pelvis, {0, 0.96f, 0}, {0.16f, 0.1f, 0.1f}), blob(spine, {0, 1.12f, 0}, {0.13f, 0.12f, 0.09f}),
      blob(chest, {0, 1.32f, 0}, {0.17f, 0.16f, 0.1f}), limb(neck, {0, 1.44f, 0}, {0, 1.56f, 0}, 0.045f),
      blob(head, {0, 1.65f, 0.01f}, {0.085f, 0.11f, 0.1f})};
  for (const float side : {1.0f, -1.0f}) {
    const std::string s = side > 0 ? "_l" : "_r";  // the figure's left is +x (it faces +z)
    const int clavicle = add("clavicle" + s, chest, {side * 0.04f, 1.42f, 0});
    const int upperarm = add("upperarm" + s, clavicle, {side * 0.18f, 1.42f, 0});
    const int forearm = add("forearm" + s, upperarm, {side * 0.22f, 1.14f, 0});
    const int hand = add("hand" + s, forearm, {side * 0.25f, 0.89f, 0});
    const int thigh = add("thigh" + s, pelvis, {side * 0.1f, 0.9f, 0});
    const int shin = add("shin" + s, thigh, {side * 0.1f, 0.48f, 0});
    const int foot = add("foot" + s, shin, {side * 0.1f, 0.08f, 0});
    parts.push_back(limb(clavicle, world[clavicle], world[upperarm], 0.04f));
    parts.push_back(limb(upperarm, world[upperarm], world[forearm], 0.045f));
    parts.push_back(limb(forearm, world[forearm], world[hand], 0.038f));
    parts.push_back(limb(hand, world[hand], world[hand] + glm::vec3(side * 0.01f, -0.16f, 0), 0.035f));
    parts.push_back(limb(thigh, world[thigh], world[shin], 0.075f));
    parts.push_back(limb(shin, world[shin], world[foot], 0.055f));
    parts.push_back(limb(foot, {side * 0.1f, 0.04f, -0.04f}, {side * 0.1f, 0.035f, 0.16f}, 0.04f));
  }

  Mesh body;
  body.name = "body";
  std::vector<uint16_t> joints;
  for (const Part& part : parts) addEllipsoid(part, body, joints);
  computeVertexNormals(body.positions, body.triangles, body.normals);
  body.skin.influencesPerVertex = 1;
  body.skin.joints = joints;
  body.skin.weights.assign(joints.size(), 1.0f);
  for (int b = 0; b < c.skeleton.boneCount(); ++b) body.skin.jointBones.push_back(b);
  body.skin.inverseBind = c.skeleton.inverseBindMatrices();
  c.meshes.push_back(std::move(body));

  Clip raise;
  raise.name = "arm_raise";
  raise.boneChannels.push_back({c.skeleton.findBone("upperarm_l"), {}, rotationTrack({0, 0, 1}, 150.0f), {}});
  raise.boneChannels.push_back({c.skeleton.findBone("upperarm_r"), {}, rotationTrack({0, 0, 1}, -150.0f), {}});
  c.clips.push_back(std::move(raise));
  c.validate();
  return c;
}

}  // namespace mq::test
