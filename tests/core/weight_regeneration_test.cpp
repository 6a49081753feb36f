#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>

#include "core/character/default_mannequin.h"
#include "core/io/character_import.h"
#include "core/scene/scene_document.h"
#include "core/skin_test_util.h"
#include "core/skinning/helper_bones.h"
#include "core/skinning/section_cones.h"
#include "core/skinning/weight_regeneration.h"
#include "core/util/error.h"
#include "core/util/thread_pool.h"

namespace mq {
namespace {

float weightOf(const SkinBinding& skin, size_t v, int joint) {
  float w = 0.0f;
  for (int i = 0; i < skin.influencesPerVertex; ++i)
    if (skin.joints[v * skin.influencesPerVertex + i] == joint) w += skin.weights[v * skin.influencesPerVertex + i];
  return w;
}

void expectPartitionOfUnity(const SkinBinding& skin, size_t vertices) {
  ASSERT_LE(skin.influencesPerVertex, 4);
  for (size_t v = 0; v < vertices; ++v) {
    float sum = 0.0f;
    for (int i = 0; i < skin.influencesPerVertex; ++i) {
      const float w = skin.weights[v * skin.influencesPerVertex + i];
      ASSERT_GE(w, 0.0f);
      ASSERT_LE(w, 1.0f + 1e-6f);
      sum += w;
    }
    ASSERT_NEAR(sum, 1.0f, 1e-5f) << "vertex " << v;
  }
}

// A tube whose file weights are wrong: its rings on the root and the child
// in turn.
Character tubeWithScrambledWeights() {
  Character c = tubeCharacter(41, 32, false);
  SkinBinding& skin = c.meshes[0].skin;
  for (size_t v = 0; v < c.meshes[0].vertexCount(); ++v) {
    const bool child = (v / 32) % 2 == 1;
    skin.weights[2 * v] = child ? 0.0f : 1.0f;
    skin.weights[2 * v + 1] = child ? 1.0f : 0.0f;
  }
  return c;
}

TEST(WeightRegeneration, TubeSplitsAtTheJointAndBlendsOverItsSection) {
  Character c = tubeWithScrambledWeights();
  WeightSettings settings;
  settings.regenerate = true;
  const WeightReport report = regenerateWeights(c, settings, nullptr);
  const Mesh& m = c.meshes[0];
  expectPartitionOfUnity(m.skin, m.vertexCount());
  // Blended over `transition` (2) section radii (0.2) on each side of y = 1.
  const double reach = settings.transition * 0.2;
  float previous = -1.0f;
  for (size_t v = 0; v < m.vertexCount(); v += 32) {  // one vertex per ring, bottom to top
    const double y = m.position(v).y;
    const float child = weightOf(m.skin, v, 1);
    EXPECT_GE(child, previous) << "the child's weight grows along the tube (y = " << y << ")";
    previous = child;
    if (y < 1.0 - reach - 0.05) {
      EXPECT_EQ(child, 0.0f) << "y = " << y;
    }
    if (y > 1.0 + reach + 0.05) {
      EXPECT_EQ(child, 1.0f) << "y = " << y;
    }
  }
  EXPECT_NEAR(weightOf(m.skin, 20 * 32, 1), 0.5f, 0.2f);  // the ring at y = 1
  EXPECT_EQ(report.blendedBefore, 0u);
  EXPECT_GT(report.blendedAfter, 0u);
  EXPECT_LT(report.blendedAfter, m.vertexCount() / 2);
  // The same around each ring: the tube is round.
  for (size_t ring = 0; ring < 41; ++ring)
    for (size_t a = 1; a < 32; ++a)
      EXPECT_NEAR(weightOf(m.skin, ring * 32 + a, 1), weightOf(m.skin, ring * 32, 1), 1e-5f);
}

TEST(WeightRegeneration, SmoothingBoundsTheWeightsSlope) {
  Character c = tubeCharacter(41, 32, true);  // rigid: a step at y = 1
  WeightSettings settings;
  settings.smooth = true;
  settings.passes = 2000;
  const WeightReport report = regenerateWeights(c, settings, nullptr);
  EXPECT_GT(report.passes, 1);
  EXPECT_EQ(report.largestExcess, 0.0) << report.summary();
  const Mesh& m = c.meshes[0];
  expectPartitionOfUnity(m.skin, m.vertexCount());
  const double length = settings.transition * 0.2 * 0.999;  // the 32-gon's area-equivalent radius is a hair smaller
  for (size_t ring = 0; ring + 1 < 41; ++ring) {
    const double dy = m.position((ring + 1) * 32).y - m.position(ring * 32).y;
    const float step = std::abs(weightOf(m.skin, (ring + 1) * 32, 1) - weightOf(m.skin, ring * 32, 1));
    EXPECT_LE(step, dy / length + 2e-3) << "ring " << ring;
  }
}

TEST(WeightRegeneration, RestPoseAndThreadsAreUnchanged) {
  Character c = tubeWithScrambledWeights();
  WeightSettings settings;
  settings.regenerate = settings.smooth = true;
  Character threaded = c;
  regenerateWeights(c, settings, nullptr);
  ThreadPool pool(2);
  regenerateWeights(threaded, settings, &pool);
  EXPECT_EQ(c.meshes[0].skin.weights, threaded.meshes[0].skin.weights);
  EXPECT_EQ(c.meshes[0].skin.joints, threaded.meshes[0].skin.joints);
  PosedCharacter posed;
  posed.evaluate(c, -1, 0.0f, nullptr, nullptr);
  const std::vector<float>& rest = c.meshes[0].positions;
  for (size_t i = 0; i < rest.size(); ++i) ASSERT_NEAR(posed.meshes()[0].positions[i], rest[i], 1e-6f);
}

TEST(WeightRegeneration, ConesBoundOnTheOldWeightsAreDropped) {
  // The cones' creases are bound from each vertex's dominant bone: cones
  // bound on the file's weights must not outlive them.
  Character c = makeDefaultMannequin();
  c.skinning = SkinningMethod::Cones;
  prepareSkinning(c);
  ASSERT_TRUE(c.meshes[0].sectionCones);
  WeightSettings settings;
  settings.regenerate = true;
  regenerateWeights(c, settings, &ThreadPool::shared());
  EXPECT_FALSE(c.meshes[0].sectionCones);
  prepareSkinning(c);
  ASSERT_TRUE(c.meshes[0].sectionCones);
  const std::shared_ptr<const SectionCones> fresh = bindSectionCones(c.meshes[0], c.skeleton);
  EXPECT_EQ(c.meshes[0].sectionCones->creaseJoint, fresh->creaseJoint);
  EXPECT_EQ(c.meshes[0].sectionCones->creaseBound, fresh->creaseBound);
}

TEST(WeightRegeneration, ProgressCountsUpAndACancelChangesNothing) {
  Character c = makeDefaultMannequin();
  ASSERT_GT(addHelperBones(c), 0);
  const Character before = c;
  WeightSettings settings;
  settings.regenerate = settings.smooth = true;

  int calls = 0, last = 0, total = 0;
  WeightCallbacks callbacks;
  callbacks.progress = [&](int done, int all) {
    EXPECT_GE(done, last);
    last = done, total = all, ++calls;
  };
  callbacks.cancelled = [&] { return calls == 2; };  // during the rigid assignment
  const WeightReport stopped = regenerateWeights(c, settings, &ThreadPool::shared(), &callbacks);
  EXPECT_TRUE(stopped.cancelled);
  EXPECT_EQ(c.skeleton.boneCount(), before.skeleton.boneCount());
  EXPECT_EQ(c.helperBones.size(), before.helperBones.size());
  EXPECT_EQ(c.meshes[0].skin.weights, before.meshes[0].skin.weights);
  EXPECT_EQ(c.meshes[0].skin.joints, before.meshes[0].skin.joints);
  EXPECT_EQ(c.skinsBeforeHelpers[0].weights, before.skinsBeforeHelpers[0].weights);

  calls = last = 0;
  callbacks.cancelled = [] { return false; };
  const WeightReport done = regenerateWeights(c, settings, &ThreadPool::shared(), &callbacks);
  EXPECT_FALSE(done.cancelled);
  EXPECT_EQ(last, total);
  EXPECT_GT(calls, 3);
  EXPECT_NE(c.meshes[0].skin.weights, before.meshes[0].skin.weights);
  EXPECT_EQ(c.helperBones.size(), before.helperBones.size());
}

TEST(WeightRegeneration, MannequinHandStaysOnItsChainAndHelpersComeBack) {
  Character c = makeDefaultMannequin();
  ASSERT_GT(addHelperBones(c), 0);
  const size_t helpers = c.helperBones.size();
  WeightSettings settings;
  settings.regenerate = true;
  const WeightReport report = regenerateWeights(c, settings, &ThreadPool::shared());
  EXPECT_EQ(c.helperBones.size(), helpers);
  const Mesh& m = c.meshes[0];
  expectPartitionOfUnity(m.skin, m.vertexCount());
  EXPECT_EQ(report.vertices, m.vertexCount());
  // A hand's vertices stay on the hand's chain, not on the other arm or the torso.
  const int hand = c.skeleton.findBone("hand_l");
  ASSERT_GE(hand, 0);
  int handJoint = -1;
  for (size_t j = 0; j < m.skin.jointBones.size(); ++j)
    if (m.skin.jointBones[j] == hand) handJoint = int(j);
  ASSERT_GE(handJoint, 0);
  size_t onHand = 0;
  for (size_t v = 0; v < m.vertexCount(); ++v) onHand += weightOf(m.skin, v, handJoint) > 0.5f;
  EXPECT_GT(onHand, 200u);
}

TEST(WeightRegeneration, SeamVerticesOfAnImportedSkinKeepOneWeight) {
  Character c =
      importCharacter(std::string(MANNEQUIN_SHARED_DIR) + "/assets/characters/CesiumMan/glTF-Binary/CesiumMan.glb");
  WeightSettings settings;
  settings.regenerate = settings.smooth = true;
  regenerateWeights(c, settings, nullptr);
  size_t shared = 0;
  for (const Mesh& m : c.meshes) {
    expectPartitionOfUnity(m.skin, m.vertexCount());
    std::map<std::array<float, 3>, size_t> first;
    for (size_t v = 0; v < m.vertexCount(); ++v) {
      const glm::vec3 p = m.position(v);
      auto [it, inserted] = first.try_emplace({p.x, p.y, p.z}, v);
      if (inserted) continue;
      ++shared;
      for (size_t j = 0; j < m.skin.jointBones.size(); ++j)
        ASSERT_EQ(weightOf(m.skin, v, int(j)), weightOf(m.skin, it->second, int(j)));
    }
  }
  EXPECT_GT(shared, 0u);
}

TEST(WeightRegeneration, SettingsReadAndWriteJson) {
  WeightSettings s;
  s.regenerate = true;
  s.transition = 3.0;
  s.passes = 12;
  const WeightSettings back = weightSettingsFromJson(toJson(s), "skinning.weights");
  EXPECT_TRUE(back == s);
  auto expectError = [](const char* text, const std::string& message) {
    try {
      weightSettingsFromJson(nlohmann::json::parse(text), "skinning.weights");
      ADD_FAILURE() << "accepted " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  expectError(R"({"passes": 0})", "skinning.weights.passes");
  expectError(R"({"transition": -1})", "skinning.weights.transition");
  expectError(R"({"regenerate": "yes"})", "skinning.weights.regenerate");
  expectError(R"({"regnerate": true})", "regnerate");
}

TEST(WeightRegeneration, SceneDocumentKeepsTheSettings) {
  SceneDocument doc;
  doc.weights.regenerate = true;
  doc.weights.axialWeight = 1.0;
  const SceneDocument back = parseSceneDocument(toJson(doc).dump(), "mem.mqscene");
  EXPECT_TRUE(back.weights == doc.weights);
  EXPECT_FALSE(parseSceneDocument(toJson(SceneDocument()).dump(), "mem.mqscene").weights.active());
  EXPECT_THROW(parseSceneDocument(R"({"format":"mannequin-scene","version":1,"skinning":{"weights":{"passes":-3}}})",
                                  "bad.mqscene"),
               FileError);
}

}  // namespace
}  // namespace mq
