// glTF 2.0 features the sample characters do not exercise, on small
// hand-made files: strips, interleaved (byteStride) and sparse accessors,
// normalised integer weights, zero-weight joints, unskinned meshes under
// animated nodes (STEP), node matrices, morph targets with CUBICSPLINE
// weights.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include <unistd.h>
#include <nlohmann/json.hpp>

#include "core/character/posed_character.h"
#include "core/io/character_import.h"
#include "gltf_test_util.h"

namespace mq {
namespace {

using nlohmann::json;
using test::Buffer;
using test::writeGltf;

glm::vec3 vertex(const PosedCharacter& p, int mesh, int v) {
  const auto& pos = p.meshes()[mesh].positions;
  return {pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]};
}

void expectNear(const glm::vec3& a, const glm::vec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-5f);
  EXPECT_NEAR(a.y, b.y, 1e-5f);
  EXPECT_NEAR(a.z, b.z, 1e-5f);
}

// A strip of 4 vertices interleaved with a padding float (byteStride 16),
// on a node under an animated node under a matrix node.
TEST(GltfFeatures, StripUnderAnimatedNodeWithStepKeys) {
  Buffer b;
  const size_t interleaved = b.add(std::vector<float>{0, 0, 0, 9, 1, 0, 0, 9, 0, 1, 0, 9, 1, 1, 0, 9});
  const size_t times = b.add(std::vector<float>{0, 1});
  const size_t moves = b.add(std::vector<float>{0, 1, 0, 0, 2, 0});
  json g;
  g["bufferViews"] = {{{"buffer", 0}, {"byteOffset", interleaved}, {"byteLength", 64}, {"byteStride", 16}},
                      {{"buffer", 0}, {"byteOffset", times}, {"byteLength", 8}},
                      {{"buffer", 0}, {"byteOffset", moves}, {"byteLength", 24}}};
  g["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                    {{"bufferView", 1}, {"componentType", 5126}, {"count", 2}, {"type", "SCALAR"}},
                    {{"bufferView", 2}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}}};
  g["meshes"] = {{{"name", "strip"}, {"primitives", {{{"attributes", {{"POSITION", 0}}}, {"mode", 5}}}}}};
  g["nodes"] = {{{"name", "root"}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 1}}, {"children", {1}}},
                {{"name", "mover"}, {"translation", {0, 1, 0}}, {"children", {2}}},
                {{"name", "shape"}, {"mesh", 0}, {"translation", {0, 0, 1}}, {"scale", {2, 2, 2}}}};
  g["scenes"] = {{{"nodes", {0}}}};
  g["animations"] = {{{"samplers", {{{"input", 1}, {"output", 2}, {"interpolation", "STEP"}}}},
                      {"channels", {{{"sampler", 0}, {"target", {{"node", 1}, {"path", "translation"}}}}}}}};
  const Character c = importCharacter(writeGltf("strip.gltf", g, b));

  ASSERT_EQ(c.skeleton.boneCount(), 1);  // only the animated node
  EXPECT_EQ(c.skeleton.bone(0).name, "mover");
  ASSERT_EQ(c.meshes.size(), 1u);
  EXPECT_EQ(c.meshes[0].triangles, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));  // spec strip order
  EXPECT_EQ(c.meshes[0].attachBone, 0);

  PosedCharacter p;
  p.evaluate(c, 0, 0.99f, nullptr, nullptr);  // STEP holds the first key
  expectNear(vertex(p, 0, 3), {1 + 2, 1 + 2, 1});
  p.evaluate(c, 0, 1.0f, nullptr, nullptr);
  expectNear(vertex(p, 0, 3), {1 + 2, 2 + 2, 1});
}

// Sparse positions on a zero accessor, one morph target animated with
// CUBICSPLINE weights, default weight from mesh.weights.
TEST(GltfFeatures, SparseMorphTargetWithCubicWeights) {
  Buffer b;
  const size_t sparseIndices = b.add(std::vector<uint8_t>{1, 2});
  const size_t sparseValues = b.add(std::vector<float>{1, 0, 0, 0, 1, 0});
  const size_t deltas = b.add(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1});
  const size_t times = b.add(std::vector<float>{0, 2});
  // per key: in-tangent, value, out-tangent
  const size_t weights = b.add(std::vector<float>{0, 0, 1, 0, 1, 0});
  json g;
  g["bufferViews"] = {{{"buffer", 0}, {"byteOffset", sparseIndices}, {"byteLength", 2}},
                      {{"buffer", 0}, {"byteOffset", sparseValues}, {"byteLength", 24}},
                      {{"buffer", 0}, {"byteOffset", deltas}, {"byteLength", 36}},
                      {{"buffer", 0}, {"byteOffset", times}, {"byteLength", 8}},
                      {{"buffer", 0}, {"byteOffset", weights}, {"byteLength", 24}}};
  g["accessors"] = {
      {{"componentType", 5126},
       {"count", 3},
       {"type", "VEC3"},
       {"sparse",
        {{"count", 2}, {"indices", {{"bufferView", 0}, {"componentType", 5121}}}, {"values", {{"bufferView", 1}}}}}},
      {{"bufferView", 2}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
      {{"bufferView", 3}, {"componentType", 5126}, {"count", 2}, {"type", "SCALAR"}},
      {{"bufferView", 4}, {"componentType", 5126}, {"count", 6}, {"type", "SCALAR"}}};
  g["meshes"] = {
      {{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"targets", {{{"POSITION", 1}}}}}}}, {"weights", {0.25}}}};
  g["nodes"] = {{{"mesh", 0}}};
  g["scenes"] = {{{"nodes", {0}}}};
  g["animations"] = {{{"samplers", {{{"input", 2}, {"output", 3}, {"interpolation", "CUBICSPLINE"}}}},
                      {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}}}}}};
  const Character c = importCharacter(writeGltf("morph.gltf", g, b));
  ASSERT_EQ(c.meshes.size(), 1u);
  ASSERT_EQ(c.meshes[0].morphTargets.size(), 1u);
  EXPECT_EQ(c.skeleton.boneCount(), 0);

  PosedCharacter p;
  p.evaluate(c, -1, 0.0f, nullptr, nullptr);
  expectNear(vertex(p, 0, 1), {1, 0, 0.25f});  // sparse value + default weight
  p.evaluate(c, 0, 1.0f, nullptr, nullptr);
  // Hermite at s = 0.5, dt = 2: h10 * dt * out0 + h01 * v1 = 0.125 * 2 * 1 + 0.5
  expectNear(vertex(p, 0, 2), {0, 1, 0.75f});
}

// Normalised unsigned-byte weights that do not quite sum to 1, and a joint
// index beyond the skin paired with weight 0.
TEST(GltfFeatures, NormalisedByteWeightsAndZeroWeightJoints) {
  Buffer b;
  const size_t positions = b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  const size_t joints = b.add(std::vector<uint8_t>{0, 1, 0, 9, 1, 0, 0, 0, 0, 0, 0, 0});
  const size_t weights = b.add(std::vector<uint8_t>{100, 100, 0, 0, 255, 0, 0, 0, 200, 0, 0, 0});
  json g;
  g["bufferViews"] = {{{"buffer", 0}, {"byteOffset", positions}, {"byteLength", 36}},
                      {{"buffer", 0}, {"byteOffset", joints}, {"byteLength", 12}},
                      {{"buffer", 0}, {"byteOffset", weights}, {"byteLength", 12}}};
  g["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                    {{"bufferView", 1}, {"componentType", 5121}, {"count", 3}, {"type", "VEC4"}},
                    {{"bufferView", 2}, {"componentType", 5121}, {"normalized", true}, {"count", 3}, {"type", "VEC4"}}};
  g["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"JOINTS_0", 1}, {"WEIGHTS_0", 2}}}}}}}};
  g["skins"] = {{{"joints", {1, 2}}}};
  g["nodes"] = {{{"mesh", 0}, {"skin", 0}, {"translation", {5, 5, 5}}},  // ignored: skinned node
                {{"name", "a"}, {"children", {2}}},
                {{"name", "b"}, {"translation", {0, 1, 0}}}};
  g["scenes"] = {{{"nodes", {0, 1}}}};
  const Character c = importCharacter(writeGltf("weights.gltf", g, b));
  const SkinBinding& s = c.meshes[0].skin;
  ASSERT_EQ(s.influencesPerVertex, 4);
  EXPECT_NEAR(s.weights[0] + s.weights[1], 1.0f, 1e-6f);
  EXPECT_NEAR(s.weights[8], 1.0f, 1e-6f);  // 200/255 alone, normalised
  EXPECT_EQ(s.joints[3], 0);               // the out-of-range joint with weight 0
  EXPECT_EQ(c.maxInfluences(), 2);

  // No inverseBindMatrices: identity, so the rest pose moves vertices by
  // the joints' world transforms; the skinned node's own translation is ignored.
  PosedCharacter p;
  p.evaluate(c, -1, 0.0f, nullptr, nullptr);
  expectNear(vertex(p, 0, 0), {0, 0.5f, 0});  // half on a (0), half on b (+1 y)
  expectNear(vertex(p, 0, 1), {1, 1, 0});     // all on b
}

}  // namespace
}  // namespace mq
