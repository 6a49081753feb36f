#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/character/posed_character.h"
#include "core/skin_test_util.h"
#include "core/skinning/skin_deformer.h"
#include "core/util/thread_pool.h"

namespace mq {
namespace {

TEST(Skeleton, WorldIsParentWorldTimesLocal) {
  Skeleton s = twoBoneChain();
  Pose pose = s.restPose();
  pose[0].rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
  pose[0].translation = {1, 0, 0};
  const auto world = s.worldTransforms(pose);
  // child origin: root rotated 90 deg about Z maps (0,1,0) to (-1,0,0), plus (1,0,0)
  const glm::vec3 childOrigin(world[1][3]);
  EXPECT_NEAR(childOrigin.x, 0.0f, 1e-6f);
  EXPECT_NEAR(childOrigin.y, 0.0f, 1e-6f);
  const auto inverseBind = s.inverseBindMatrices();
  EXPECT_NEAR(inverseBind[1][3][1], -1.0f, 1e-6f);
}

TEST(Skeleton, ParentFromOffsetAppliesAboveBone) {
  Skeleton s;
  Bone root;
  root.name = "root";
  root.parentFromOffset = glm::mat4(2.0f);
  root.parentFromOffset[3][3] = 1.0f;
  s.addBone(root);
  const auto world = s.worldTransforms(s.restPose());
  EXPECT_FLOAT_EQ(world[0][0][0], 2.0f);
}

TEST(Skinning, BindPoseReproducesRestMesh) {
  const Character c = tubeCharacter(40, 24, false);
  PosedCharacter posed;
  posed.evaluate(c, -1, 0.0f, nullptr, nullptr);
  const auto& p = posed.meshes()[0].positions;
  for (size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p[i], c.meshes[0].positions[i], 1e-5f);
}

TEST(Skinning, RigidSkinningEqualsBoneTransform) {
  const Character c = tubeCharacter(20, 12, true);
  PoseEdits edits;
  edits.rotations[1] = glm::angleAxis(glm::radians(70.0f), glm::normalize(glm::vec3(1, 0, 1)));
  PosedCharacter posed;
  posed.evaluate(c, -1, 0.0f, &edits, nullptr);
  const glm::mat4 worldFromBind = posed.worldFromBone()[1] * c.meshes[0].skin.inverseBind[1];
  const Mesh& m = c.meshes[0];
  for (size_t v = 0; v < m.vertexCount(); ++v) {
    const int joint = m.skin.joints[v];
    const glm::vec3 expected = joint == 1 ? glm::vec3(worldFromBind * glm::vec4(m.position(v), 1)) : m.position(v);
    const auto& p = posed.meshes()[0].positions;
    EXPECT_NEAR(glm::length(glm::vec3(p[3 * v], p[3 * v + 1], p[3 * v + 2]) - expected), 0.0f, 1e-5f);
  }
}

TEST(Skinning, NormalsStayUnitAndAgreeWithRecomputedNormals) {
  const Character c = tubeCharacter(80, 48, false);
  PoseEdits edits;
  edits.rotations[1] = glm::angleAxis(glm::radians(30.0f), glm::vec3(1, 0, 0));
  PosedCharacter posed;
  posed.evaluate(c, -1, 0.0f, &edits, nullptr);
  const PosedMesh& out = posed.meshes()[0];
  std::vector<float> recomputed;
  computeVertexNormals(out.positions, c.meshes[0].triangles, recomputed);
  const size_t around = 48;
  double sumCos = 0;
  size_t count = 0;
  for (size_t v = around; v + around < c.meshes[0].vertexCount(); ++v) {  // skip open ends
    const glm::vec3 n(out.normals[3 * v], out.normals[3 * v + 1], out.normals[3 * v + 2]);
    const glm::vec3 r(recomputed[3 * v], recomputed[3 * v + 1], recomputed[3 * v + 2]);
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    EXPECT_GT(glm::dot(n, r), 0.9f) << "vertex " << v;
    sumCos += glm::dot(n, r);
    ++count;
  }
  EXPECT_GT(sumCos / count, 0.995);
}

TEST(Skinning, ThreadedEqualsSingleThreaded) {
  const Character c = tubeCharacter(200, 64, false);
  PoseEdits edits;
  edits.rotations[1] = glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 0, 1));
  PosedCharacter single, threaded;
  ThreadPool pool(2);
  single.evaluate(c, -1, 0.0f, &edits, nullptr);
  threaded.evaluate(c, -1, 0.0f, &edits, &pool);
  EXPECT_EQ(single.meshes()[0].positions, threaded.meshes()[0].positions);
  EXPECT_EQ(single.meshes()[0].normals, threaded.meshes()[0].normals);
}

TEST(SkinBinding, NormaliseAndLimitInfluences) {
  SkinBinding s;
  s.influencesPerVertex = 6;
  s.joints = {0, 1, 2, 3, 4, 5};
  s.weights = {0.1f, 0.5f, 0.05f, 0.3f, 0.2f, 0.23f};
  s.limitInfluences(4);
  ASSERT_EQ(s.influencesPerVertex, 4);
  float sum = 0;
  for (float w : s.weights) sum += w;
  EXPECT_NEAR(sum, 1.0f, 1e-6f);
  EXPECT_EQ(s.joints[0], 1);
  EXPECT_EQ(s.joints[1], 3);
  EXPECT_EQ(s.maxInfluences(), 4);
}

}  // namespace
}  // namespace mq
