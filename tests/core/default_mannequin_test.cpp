#include <gtest/gtest.h>

#include <cmath>

#include "core/character/default_mannequin.h"
#include "core/character/posed_character.h"
#include "core/mesh/mesh_checks.h"

namespace mq {
namespace {

// Built once: every test reads the same character.
const Character& mannequin() {
  static const Character character = makeDefaultMannequin();
  return character;
}

const Mesh& body() { return mannequin().meshes.at(0); }

glm::vec3 restJoint(const std::string& name) {
  const Skeleton& s = mannequin().skeleton;
  const int bone = s.findBone(name);
  EXPECT_GE(bone, 0) << name;
  return glm::vec3(s.worldTransforms(s.restPose())[bone][3]);
}

std::vector<float> posedPositions(const Pose& pose) {
  PosedCharacter posed;
  posed.evaluate(mannequin(), pose, {}, nullptr);
  return posed.meshes().at(0).positions;
}

TEST(DefaultMannequin, SkeletonHasTheNamedHumanoidBones) {
  const Skeleton& s = mannequin().skeleton;
  EXPECT_GE(s.boneCount(), 20);
  for (const char* name : {"pelvis", "spine", "chest", "neck", "head"}) EXPECT_GE(s.findBone(name), 0) << name;
  for (const char* base : {"clavicle", "upperarm", "forearm", "hand", "thigh", "shin", "foot", "toes"})
    for (const char* side : {"_l", "_r"}) EXPECT_GE(s.findBone(std::string(base) + side), 0) << base << side;
  EXPECT_EQ(s.bone(s.findBone("pelvis")).parent, -1);
  EXPECT_EQ(s.bone(s.findBone("forearm_l")).parent, s.findBone("upperarm_l"));
  EXPECT_EQ(s.bone(s.findBone("toes_r")).parent, s.findBone("foot_r"));
}

TEST(DefaultMannequin, StandsOnTheGroundFacingPlusZWithLeftOnPlusX) {
  const Aabb box = boundsOf(body().positions);
  EXPECT_NEAR(box.min.y, 0.0f, 0.005f);
  EXPECT_NEAR(box.max.y, 1.75f, 0.03f);
  EXPECT_GT(restJoint("hand_l").x, 0.3f);
  EXPECT_LT(restJoint("hand_r").x, -0.3f);
  EXPECT_GT(restJoint("toes_l").z, restJoint("foot_l").z);  // toes point forward
  EXPECT_GT(restJoint("head").y, restJoint("chest").y);
  EXPECT_NEAR(restJoint("thigh_l").y, 0.93f, 0.05f);  // hip joints at ~0.53 of stature
  EXPECT_NEAR(restJoint("shin_l").y, 0.5f, 0.04f);    // knees at ~0.285
  // Symmetric: the right half mirrors the left.
  EXPECT_NEAR(box.min.x, -box.max.x, 0.01f);
}

TEST(DefaultMannequin, VertexCountIsInRange) {
  EXPECT_GE(body().vertexCount(), 20000u);
  EXPECT_LE(body().vertexCount(), 60000u);
  EXPECT_EQ(body().normals.size(), body().positions.size());
}

TEST(DefaultMannequin, MeshIsOneClosedManifold) {
  const MeshTopologyReport report = checkTopology(body().vertexCount(), body().triangles);
  EXPECT_EQ(report.boundaryEdges, 0u);
  EXPECT_EQ(report.overSharedEdges, 0u);
  EXPECT_EQ(report.misorientedEdges, 0u);
  EXPECT_EQ(report.nonManifoldVertices, 0u);
  EXPECT_EQ(report.isolatedVertices, 0u);
  EXPECT_EQ(report.degenerateTriangles, 0u);
  EXPECT_EQ(report.components, 1u);
  // Euler characteristic of a sphere: V - E + F = 2.
  EXPECT_EQ(long(body().vertexCount()) - long(report.edges) + long(body().triangleCount()), 2);
}

TEST(DefaultMannequin, FacesOutwardWithAHumanVolume) {
  const double volume = signedVolume(body().positions, body().triangles);
  // A 70-80 kg adult displaces about 0.07 m^3; a slim mannequin a little less.
  EXPECT_GT(volume, 0.045);
  EXPECT_LT(volume, 0.09);
  // Field normals agree with the triangles' orientation.
  std::vector<float> faceNormals;
  computeVertexNormals(body().positions, body().triangles, faceNormals);
  size_t agreeing = 0;
  for (size_t i = 0; i < faceNormals.size(); i += 3)
    agreeing += faceNormals[i] * body().normals[i] + faceNormals[i + 1] * body().normals[i + 1] +
                    faceNormals[i + 2] * body().normals[i + 2] >
                0.5f;
  EXPECT_GT(agreeing, body().vertexCount() * 99 / 100);
  for (size_t i = 0; i < body().normals.size(); i += 3)
    ASSERT_NEAR(std::hypot(body().normals[i], body().normals[i + 1], body().normals[i + 2]), 1.0f, 1e-4f);
}

TEST(DefaultMannequin, HasNoSelfIntersectionsInBindPose) {
  const auto pairs = selfIntersections(body().positions, body().triangles);
  EXPECT_TRUE(pairs.empty()) << pairs.size() << " intersecting triangle pairs";
}

TEST(DefaultMannequin, WeightsArePartitionsOfUnityWithFourInfluences) {
  const SkinBinding& skin = body().skin;
  const Skeleton& s = mannequin().skeleton;
  ASSERT_FALSE(skin.empty());
  EXPECT_LE(skin.maxInfluences(), 4);
  EXPECT_EQ(skin.jointBones.size(), size_t(s.boneCount()));
  const auto inverseBind = s.inverseBindMatrices();
  ASSERT_EQ(skin.inverseBind.size(), inverseBind.size());
  for (size_t j = 0; j < inverseBind.size(); ++j) {
    EXPECT_EQ(skin.jointBones[j], int(j));
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) EXPECT_FLOAT_EQ(skin.inverseBind[j][c][r], inverseBind[j][c][r]);
  }
  const int k = skin.influencesPerVertex;
  for (size_t v = 0; v < body().vertexCount(); ++v) {
    float sum = 0.0f;
    for (int i = 0; i < k; ++i) {
      ASSERT_GE(skin.weights[v * k + i], 0.0f);
      ASSERT_LT(skin.joints[v * k + i], skin.jointBones.size());
      sum += skin.weights[v * k + i];
    }
    ASSERT_NEAR(sum, 1.0f, 1e-5f) << "vertex " << v;
  }
}

float weightOf(const Mesh& mesh, size_t v, int bone) {
  const SkinBinding& skin = mesh.skin;
  const int k = skin.influencesPerVertex;
  float w = 0.0f;
  for (int i = 0; i < k; ++i)
    if (skin.jointBones[skin.joints[v * k + i]] == bone) w += skin.weights[v * k + i];
  return w;
}

TEST(DefaultMannequin, WeightsFollowTheNearestLimb) {
  const Skeleton& s = mannequin().skeleton;
  const glm::vec3 midForearm = 0.5f * (restJoint("forearm_l") + restJoint("hand_l"));
  const glm::vec3 midShin = 0.5f * (restJoint("shin_r") + restJoint("foot_r"));
  size_t forearmVertices = 0, shinVertices = 0;
  for (size_t v = 0; v < body().vertexCount(); ++v) {
    const glm::vec3 p = body().position(v);
    if (glm::distance(p, midForearm) < 0.05f) {
      ++forearmVertices;
      EXPECT_GT(weightOf(body(), v, s.findBone("forearm_l")), 0.9f);
    }
    if (glm::distance(p, midShin) < 0.06f) {
      ++shinVertices;
      EXPECT_GT(weightOf(body(), v, s.findBone("shin_r")), 0.9f);
    }
    // No skin of the left leg below the crotch follows the right leg.
    if (p.x > 0.03f && p.y < 0.75f) {
      ASSERT_EQ(weightOf(body(), v, s.findBone("thigh_r")), 0.0f) << v;
    }
  }
  EXPECT_GT(forearmVertices, 50u);
  EXPECT_GT(shinVertices, 50u);
}

TEST(DefaultMannequin, ScalpCoversTheTopAndBackOfTheHead) {
  const Mesh& mesh = body();
  ASSERT_EQ(mesh.vertexTags.size(), mesh.vertexCount());
  const int headBone = mannequin().skeleton.findBone("head");
  size_t scalp = 0;
  glm::vec3 top(0.0f);
  float highest = 0.0f;
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    const glm::vec3 p = mesh.position(v);
    if (p.y > highest) highest = p.y, top = p;
    if (mesh.vertexTags[v] != TagScalp) continue;
    ++scalp;
    EXPECT_GT(p.y, 1.55f);
    EXPECT_GT(weightOf(mesh, v, headBone), 0.5f);
    if (p.z > 0.07f) {
      EXPECT_GT(p.y, 1.67f) << "scalp on the face";
    }
  }
  EXPECT_GT(scalp, 300u);
  EXPECT_LT(scalp, mesh.vertexCount() / 10);
  // The crown is scalp.
  size_t crown = 0;
  for (size_t v = 0; v < mesh.vertexCount(); ++v) crown += glm::distance(mesh.position(v), top) < 0.02f;
  size_t crownScalp = 0;
  for (size_t v = 0; v < mesh.vertexCount(); ++v)
    crownScalp += glm::distance(mesh.position(v), top) < 0.02f && mesh.vertexTags[v] == TagScalp;
  EXPECT_EQ(crownScalp, crown);
}

TEST(DefaultMannequin, BindPoseReproducesTheRestMesh) {
  const std::vector<float> posed = posedPositions(mannequin().skeleton.restPose());
  ASSERT_EQ(posed.size(), body().positions.size());
  for (size_t i = 0; i < posed.size(); ++i) ASSERT_NEAR(posed[i], body().positions[i], 1e-5f) << i;
}

TEST(DefaultMannequin, ClipsStayFiniteAndPlausible) {
  const Character& c = mannequin();
  ASSERT_GE(c.findClip("walk"), 0);
  ASSERT_GE(c.findClip("arm_raise"), 0);
  EXPECT_EQ(c.clips[c.findClip("walk")].wrap, WrapMode::Loop);
  EXPECT_NEAR(c.clips[c.findClip("walk")].duration(), 1.0f, 0.2f);
  EXPECT_NEAR(c.clips[c.findClip("arm_raise")].duration(), 2.0f, 0.3f);
  EXPECT_NO_THROW(c.validate());
  PosedCharacter posed;
  for (size_t clip = 0; clip < c.clips.size(); ++clip) {
    const float start = c.clips[clip].startTime(), duration = c.clips[clip].duration();
    for (int frame = 0; frame <= int(duration * 30.0f); ++frame) {
      posed.evaluate(c, int(clip), start + frame / 30.0f, nullptr, nullptr);
      const std::vector<float>& p = posed.meshes()[0].positions;
      for (float x : p) ASSERT_TRUE(std::isfinite(x)) << c.clips[clip].name << " frame " << frame;
      const Aabb box = boundsOf(p);
      const glm::vec3 size = box.max - box.min;
      EXPECT_GT(box.min.y, -0.1f);
      EXPECT_GT(size.y, 1.5f);
      EXPECT_LT(size.y, 2.3f);
      EXPECT_LT(size.x, 1.9f);
      EXPECT_LT(size.z, 1.0f);
    }
  }
}

TEST(DefaultMannequin, WalkLoopsSeamlessly) {
  const Character& c = mannequin();
  const Clip& walk = c.clips[c.findClip("walk")];
  Pose first = c.skeleton.restPose(), last = c.skeleton.restPose();
  walk.applyToPose(walk.startTime(), first);
  walk.applyToPose(walk.endTime(), last);
  for (size_t b = 0; b < first.size(); ++b) {
    EXPECT_NEAR(glm::distance(first[b].translation, last[b].translation), 0.0f, 1e-5f);
    EXPECT_NEAR(std::abs(glm::dot(first[b].rotation, last[b].rotation)), 1.0f, 1e-5f);
  }
  // It moves: the feet leave the rest pose.
  Pose quarter = c.skeleton.restPose();
  walk.applyToPose(walk.startTime() + 0.25f * walk.duration(), quarter);
  const int thigh = c.skeleton.findBone("thigh_l");
  EXPECT_LT(std::abs(glm::dot(quarter[thigh].rotation, c.skeleton.bone(thigh).rest.rotation)), 0.99f);
}

TEST(DefaultMannequin, ArmRaiseLiftsTheHandsAboveTheShoulders) {
  const Character& c = mannequin();
  const int clip = c.findClip("arm_raise");
  const Pose top = samplePose(c, clip, c.clips[clip].startTime() + 0.5f * c.clips[clip].duration());
  const auto world = c.skeleton.worldTransforms(top);
  for (const char* side : {"_l", "_r"}) {
    const int hand = c.skeleton.findBone(std::string("hand") + side);
    EXPECT_GT(world[hand][3].y, restJoint(std::string("upperarm") + side).y + 0.1f) << side;
  }
}

float triangleArea(const std::vector<float>& p, const std::vector<uint32_t>& tris, size_t t) {
  auto at = [&](uint32_t v) { return glm::vec3(p[3 * v], p[3 * v + 1], p[3 * v + 2]); };
  const glm::vec3 a = at(tris[t]), b = at(tris[t + 1]), c = at(tris[t + 2]);
  return 0.5f * glm::length(glm::cross(b - a, c - a));
}

// Bends a joint and checks that the skin neither collapses nor tears: the
// volume barely changes, no edge stretches beyond 4 cm (rest edges are under
// 1.3 cm) and hardly any triangle is crushed.
void expectJointBendKeepsShape(const std::string& boneName, float degrees) {
  const Character& c = mannequin();
  const std::vector<uint32_t>& tris = body().triangles;
  const int bone = c.skeleton.findBone(boneName);
  Pose pose = c.skeleton.restPose();
  pose[bone].rotation = pose[bone].rotation * glm::angleAxis(glm::radians(degrees), glm::vec3(1, 0, 0));
  const std::vector<float> bent = posedPositions(pose);
  const double restVolume = signedVolume(body().positions, tris);
  EXPECT_NEAR(signedVolume(bent, tris) / restVolume, 1.0, 0.03) << boneName;
  float longest = 0.0f;
  for (size_t t = 0; t < tris.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = tris[t + e], b = tris[t + (e + 1) % 3];
      longest = std::max(longest, glm::distance(glm::vec3(bent[3 * a], bent[3 * a + 1], bent[3 * a + 2]),
                                                glm::vec3(bent[3 * b], bent[3 * b + 1], bent[3 * b + 2])));
    }
  EXPECT_LT(longest, 0.04f) << boneName;
  size_t crushed = 0, counted = 0;
  for (size_t t = 0; t < tris.size(); t += 3) {
    const float rest = triangleArea(body().positions, tris, t);
    if (rest < 1e-5f) continue;  // skip slivers, whose ratios mean little
    ++counted;
    crushed += triangleArea(bent, tris, t) < 0.1f * rest;
  }
  EXPECT_LT(crushed, counted / 200) << boneName << ": " << crushed << " of " << counted << " triangles crushed";
}

TEST(DefaultMannequin, ElbowAndKneeBendNinetyDegreesWithoutCollapse) {
  expectJointBendKeepsShape("forearm_l", 90.0f);  // elbow flexion (forward)
  expectJointBendKeepsShape("forearm_r", 90.0f);
  expectJointBendKeepsShape("shin_l", -90.0f);     // knee flexion (backward)
  expectJointBendKeepsShape("thigh_r", 80.0f);     // hip flexion (a high step)
  expectJointBendKeepsShape("upperarm_l", 60.0f);  // shoulder flexion
}

TEST(DefaultMannequin, IsDeterministic) {
  const Character again = makeDefaultMannequin();
  EXPECT_EQ(again.meshes[0].positions, body().positions);
  EXPECT_EQ(again.meshes[0].triangles, body().triangles);
  EXPECT_EQ(again.meshes[0].skin.weights, body().skin.weights);
}

}  // namespace
}  // namespace mq
