// Every character in ../shared/assets/characters imports with the counts its
// MANIFEST.md lists; the two CesiumMan layouts give identical data; FBX and
// Collada skins reproduce the mesh in the bind pose and stay plausible over
// their clips.
#include <gtest/gtest.h>

#include <cmath>

#include "core/character/posed_character.h"
#include "core/io/character_import.h"

namespace mq {
namespace {

const std::string kCharacters = std::string(MANNEQUIN_SHARED_DIR) + "/assets/characters/";

struct Expected {
  std::string file;
  size_t vertices;
  int bones;
  int maxInfluences;
  std::vector<std::pair<float, float>> clips;  // start, end (seconds)
};

// From ../shared/assets/MANIFEST.md.
const std::vector<Expected> kManifest = {
    {"CesiumMan/glTF/CesiumMan.gltf", 3273, 19, 4, {{0.0417f, 2.0f}}},
    {"CesiumMan/glTF-Binary/CesiumMan.glb", 3273, 19, 4, {{0.0417f, 2.0f}}},
    {"RiggedSimple/RiggedSimple.gltf", 96, 2, 2, {{0.0416f, 2.083f}}},
    {"SimpleSkin/SimpleSkin.gltf", 10, 2, 2, {{0.0f, 5.5f}}},
    {"assimp_fbx_animation_with_skeleton/animation_with_skeleton.fbx", 4224, 14, 6, {{0.0f, 0.8333f}}},
    {"assimp_collada_library_animation_clips/library_animation_clips.dae",
     72,
     5,
     2,
     {{0.04167f, 0.625f}, {0.0f, 0.8333f}}},
};

TEST(Import, CountsMatchManifest) {
  for (const Expected& e : kManifest) {
    SCOPED_TRACE(e.file);
    const Character c = importCharacter(kCharacters + e.file);
    EXPECT_EQ(c.vertexCount(), e.vertices);
    EXPECT_EQ(c.skeleton.boneCount(), e.bones);
    EXPECT_EQ(c.maxInfluences(), e.maxInfluences);
    ASSERT_EQ(c.clips.size(), e.clips.size());
    for (size_t i = 0; i < e.clips.size(); ++i) {
      EXPECT_NEAR(c.clips[i].startTime(), e.clips[i].first, 1e-3);
      EXPECT_NEAR(c.clips[i].endTime(), e.clips[i].second, 1e-3);
    }
    EXPECT_NO_THROW(c.validate());
  }
}

TEST(Import, ColladaClipsAreNamed) {
  const Character c =
      importCharacter(kCharacters + "assimp_collada_library_animation_clips/library_animation_clips.dae");
  ASSERT_EQ(c.clips.size(), 2u);
  EXPECT_EQ(c.findClip("bend"), 0);
  EXPECT_EQ(c.findClip("turn"), 1);
}

TEST(Import, SkinWeightsSumToOne) {
  for (const Expected& e : kManifest) {
    SCOPED_TRACE(e.file);
    const Character c = importCharacter(kCharacters + e.file);
    for (const Mesh& m : c.meshes) {
      const int k = m.skin.influencesPerVertex;
      for (size_t v = 0; k > 0 && v < m.vertexCount(); ++v) {
        float sum = 0.0f;
        for (int i = 0; i < k; ++i) sum += m.skin.weights[v * k + i];
        ASSERT_NEAR(sum, 1.0f, 1e-5f) << "vertex " << v << " of " << m.name;
      }
    }
  }
}

TEST(Import, CesiumManGltfAndGlbAreIdentical) {
  const Character a = importCharacter(kCharacters + "CesiumMan/glTF/CesiumMan.gltf");
  const Character b = importCharacter(kCharacters + "CesiumMan/glTF-Binary/CesiumMan.glb");
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (size_t i = 0; i < a.meshes.size(); ++i) {
    const Mesh &ma = a.meshes[i], &mb = b.meshes[i];
    EXPECT_EQ(ma.name, mb.name);
    EXPECT_EQ(ma.positions, mb.positions);
    EXPECT_EQ(ma.normals, mb.normals);
    EXPECT_EQ(ma.uvs, mb.uvs);
    EXPECT_EQ(ma.triangles, mb.triangles);
    EXPECT_EQ(ma.skin.joints, mb.skin.joints);
    EXPECT_EQ(ma.skin.weights, mb.skin.weights);
    EXPECT_EQ(ma.skin.jointBones, mb.skin.jointBones);
    EXPECT_EQ(ma.skin.inverseBind, mb.skin.inverseBind);
  }
  ASSERT_EQ(a.skeleton.boneCount(), b.skeleton.boneCount());
  for (int i = 0; i < a.skeleton.boneCount(); ++i) {
    EXPECT_EQ(a.skeleton.bone(i).name, b.skeleton.bone(i).name);
    EXPECT_EQ(a.skeleton.bone(i).parent, b.skeleton.bone(i).parent);
    EXPECT_EQ(a.skeleton.bone(i).parentFromOffset, b.skeleton.bone(i).parentFromOffset);
  }
  ASSERT_EQ(a.clips.size(), b.clips.size());
  for (size_t c = 0; c < a.clips.size(); ++c) {
    ASSERT_EQ(a.clips[c].boneChannels.size(), b.clips[c].boneChannels.size());
    for (size_t k = 0; k < a.clips[c].boneChannels.size(); ++k) {
      EXPECT_EQ(a.clips[c].boneChannels[k].rotation.values, b.clips[c].boneChannels[k].rotation.values);
      EXPECT_EQ(a.clips[c].boneChannels[k].translation.times, b.clips[c].boneChannels[k].translation.times);
    }
  }
}

TEST(Import, GltfSkeletonParentsAreNearestJointAncestors) {
  const Character c = importCharacter(kCharacters + "CesiumMan/glTF/CesiumMan.gltf");
  EXPECT_EQ(c.skeleton.bone(0).name, "Skeleton_torso_joint_1");
  EXPECT_EQ(c.skeleton.bone(0).parent, -1);
  // The root joint carries the Z_UP and Armature node transforms above it.
  EXPECT_NE(c.skeleton.bone(0).parentFromOffset, glm::mat4(1.0f));
  for (int b = 1; b < c.skeleton.boneCount(); ++b) EXPECT_GE(c.skeleton.bone(b).parent, 0);
}

// In the rest pose every joint's worldFromBone * boneFromMesh must be the same
// matrix (the mesh's own placement), or the bind pose would tear the mesh.
void expectBindPoseIsRigid(const Character& c) {
  const std::vector<glm::mat4> world = c.skeleton.worldTransforms(c.skeleton.restPose());
  for (const Mesh& m : c.meshes) {
    if (m.skin.empty()) continue;
    const glm::mat4 first = world[m.skin.jointBones[0]] * m.skin.inverseBind[0];
    float scale = 1.0f;  // float round-off grows with the size of the numbers
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row) scale = std::max(scale, std::abs(first[col][row]));
    for (size_t j = 1; j < m.skin.jointBones.size(); ++j) {
      const glm::mat4 other = world[m.skin.jointBones[j]] * m.skin.inverseBind[j];
      for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row)
          EXPECT_NEAR(other[col][row], first[col][row], 1e-5f * scale) << m.name << " joint " << j;
    }
  }
}

// Longest ratio of a posed triangle edge to its rest length, over all meshes
// (skinning with wrong bind matrices tears the mesh apart).
float worstEdgeStretch(const Character& c, const PosedCharacter& rest, const PosedCharacter& posed) {
  float worst = 1.0f;
  for (size_t m = 0; m < c.meshes.size(); ++m) {
    const auto& r = rest.meshes()[m].positions;
    const auto& p = posed.meshes()[m].positions;
    const auto& tri = c.meshes[m].triangles;
    for (size_t t = 0; t < tri.size(); t += 3)
      for (int e = 0; e < 3; ++e) {
        const uint32_t a = tri[t + e], b = tri[t + (e + 1) % 3];
        const float restLength = glm::distance(glm::vec3(r[3 * a], r[3 * a + 1], r[3 * a + 2]),
                                               glm::vec3(r[3 * b], r[3 * b + 1], r[3 * b + 2]));
        const float posedLength = glm::distance(glm::vec3(p[3 * a], p[3 * a + 1], p[3 * a + 2]),
                                                glm::vec3(p[3 * b], p[3 * b + 1], p[3 * b + 2]));
        if (restLength > 1e-6f)
          worst = std::max(worst, std::max(posedLength / restLength, restLength / std::max(posedLength, 1e-12f)));
      }
  }
  return worst;
}

// Posed vertices stay finite, the bbox keeps a similar size, no edge
// stretches or shrinks more than 3x, and no vertex jumps between frames 1/60 s
// apart.
void expectPlausibleOverClips(const Character& c) {
  PosedCharacter posed, posedRest;
  posedRest.evaluate(c, -1, 0.0f, nullptr, nullptr);
  posed.evaluate(c, -1, 0.0f, nullptr, nullptr);
  std::vector<float> rest;
  for (const PosedMesh& m : posed.meshes()) rest.insert(rest.end(), m.positions.begin(), m.positions.end());
  const float restDiagonal = boundsOf(rest).diagonal();
  ASSERT_GT(restDiagonal, 0.0f);
  for (size_t clip = 0; clip < c.clips.size(); ++clip) {
    std::vector<float> previous;
    for (float t = c.clips[clip].startTime(); t <= c.clips[clip].endTime(); t += 1.0f / 60.0f) {
      posed.evaluate(c, static_cast<int>(clip), t, nullptr, nullptr);
      std::vector<float> all;
      for (const PosedMesh& m : posed.meshes()) all.insert(all.end(), m.positions.begin(), m.positions.end());
      for (float x : all) ASSERT_TRUE(std::isfinite(x)) << "clip " << clip << " t " << t;
      const float diagonal = boundsOf(all).diagonal();
      EXPECT_GT(diagonal, 0.5f * restDiagonal) << "clip " << clip << " t " << t;
      EXPECT_LT(diagonal, 1.5f * restDiagonal) << "clip " << clip << " t " << t;
      EXPECT_LT(worstEdgeStretch(c, posedRest, posed), 3.0f) << "clip " << clip << " t " << t;
      for (size_t i = 0; i < previous.size(); ++i)
        ASSERT_LT(std::abs(all[i] - previous[i]), 0.2f * restDiagonal) << "clip " << clip << " t " << t;
      previous = all;
    }
  }
}

TEST(Import, FbxSkinBindPoseAndClip) {
  const Character c = importCharacter(kCharacters + "assimp_fbx_animation_with_skeleton/animation_with_skeleton.fbx");
  expectBindPoseIsRigid(c);
  expectPlausibleOverClips(c);
}

TEST(Import, ColladaSkinBindPoseAndClips) {
  const Character c =
      importCharacter(kCharacters + "assimp_collada_library_animation_clips/library_animation_clips.dae");
  expectBindPoseIsRigid(c);
  expectPlausibleOverClips(c);
}

TEST(Import, GltfSkinBindPoseIsRigid) {
  for (const char* f :
       {"CesiumMan/glTF/CesiumMan.gltf", "RiggedSimple/RiggedSimple.gltf", "SimpleSkin/SimpleSkin.gltf"})
    expectBindPoseIsRigid(importCharacter(kCharacters + f));
}

// The clip really moves the mesh (a bad skin or clip mapping would not).
TEST(Import, FbxClipMovesVertices) {
  const Character c = importCharacter(kCharacters + "assimp_fbx_animation_with_skeleton/animation_with_skeleton.fbx");
  PosedCharacter a, b;
  a.evaluate(c, 0, c.clips[0].startTime(), nullptr, nullptr);
  b.evaluate(c, 0, 0.5f * (c.clips[0].startTime() + c.clips[0].endTime()), nullptr, nullptr);
  float moved = 0.0f;
  for (size_t m = 0; m < c.meshes.size(); ++m)
    for (size_t i = 0; i < a.meshes()[m].positions.size(); ++i)
      moved = std::max(moved, std::abs(a.meshes()[m].positions[i] - b.meshes()[m].positions[i]));
  EXPECT_GT(moved, 1e-3f);
}

}  // namespace
}  // namespace mq
