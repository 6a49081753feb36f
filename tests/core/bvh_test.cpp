// BVH motion: the files in ../shared/assets/motion read with the joint and
// frame counts of MANIFEST.md; motion applied to a skeleton with matching
// names (or through a name map, or with other local axes) moves each bone by
// the same world rotation as the BVH joint; malformed files fail clearly.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include <unistd.h>

#include "core/io/bvh_import.h"
#include "core/io/character_import.h"
#include "core/io/file_bytes.h"
#include "core/util/error.h"
#include "import_test_util.h"

namespace mq {
namespace {

const std::string kMotion = std::string(MANNEQUIN_SHARED_DIR) + "/assets/motion/";

std::string tempPath(const std::string& name) {
  const auto dir = test::scratchDir("mq_bvh_test");
  return (dir / name).string();
}

std::string writeTemp(const std::string& name, const std::string& content) {
  const std::string path = tempPath(name);
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

int frameCount(const Clip& clip) {
  int frames = 0;
  for (const BoneChannel& c : clip.boneChannels) frames = std::max(frames, c.rotation.keyCount());
  return frames;
}

TEST(Bvh, CountsMatchManifest) {
  struct Expected {
    const char* file;
    int joints;
    int frames;
    float frameTime;
  };
  for (const Expected& e :
       {Expected{"cmu_01_01.bvh", 31, 2752, 0.0083333f}, Expected{"makehuman_tpose.bvh", 173, 1, 0.041667f},
        Expected{"makehuman_walk1.bvh", 75, 14, 0.041667f}}) {
    SCOPED_TRACE(e.file);
    const Character c = importCharacter(kMotion + e.file);
    EXPECT_EQ(c.skeleton.boneCount(), e.joints);
    EXPECT_TRUE(c.meshes.empty());
    ASSERT_EQ(c.clips.size(), 1u);
    EXPECT_EQ(frameCount(c.clips[0]), e.frames);
    EXPECT_NEAR(c.clips[0].duration(), (e.frames - 1) * e.frameTime, 1e-3);
  }
}

TEST(Bvh, CmuRootIsHipsWithZyxChannels) {
  const Character c = loadBvhCharacter(kMotion + "cmu_01_01.bvh");
  EXPECT_EQ(c.skeleton.bone(0).name, "Hips");
  EXPECT_EQ(c.skeleton.bone(0).parent, -1);
  // The root travels: its translation track is not constant.
  const Track& t = c.clips[0].boneChannels[0].translation;
  ASSERT_EQ(t.keyCount(), 2752);
  float travel = 0.0f;
  for (int k = 0; k < t.keyCount(); ++k)
    travel = std::max(travel, std::hypot(t.values[3 * k] - t.values[0], t.values[3 * k + 2] - t.values[2]));
  EXPECT_GT(travel, 5.0f);
}

// World rotation change from the rest pose, per bone.
std::vector<glm::quat> worldRotationChange(const Character& c, int clip, float time) {
  const auto rest = c.skeleton.worldTransforms(c.skeleton.restPose());
  const auto posed = c.skeleton.worldTransforms(samplePose(c, clip, time));
  std::vector<glm::quat> change;
  for (size_t b = 0; b < rest.size(); ++b)
    change.push_back(Trs::fromMatrix(posed[b]).rotation * glm::inverse(Trs::fromMatrix(rest[b]).rotation));
  return change;
}

void expectSameRotations(const std::vector<glm::quat>& a, const std::vector<glm::quat>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_GT(std::abs(glm::dot(a[i], b[i])), 1.0f - 1e-5f) << "bone " << i;
}

TEST(Bvh, AppliedToItsOwnSkeletonReproducesTheMotion) {
  Character c = loadBvhCharacter(kMotion + "cmu_01_01.bvh");
  c.clips.push_back(importBvhMotion(kMotion + "cmu_01_01.bvh", c));
  for (float t : {0.0f, 1.0f, 7.3f, 22.0f}) {
    SCOPED_TRACE(t);
    expectSameRotations(worldRotationChange(c, 0, t), worldRotationChange(c, 1, t));
    // Positions agree up to one constant shift (the root's first-frame offset).
    const auto own = c.skeleton.worldTransforms(samplePose(c, 0, t));
    const auto applied = c.skeleton.worldTransforms(samplePose(c, 1, t));
    const auto own0 = c.skeleton.worldTransforms(samplePose(c, 0, 0.0f));
    const auto applied0 = c.skeleton.worldTransforms(samplePose(c, 1, 0.0f));
    for (size_t b = 0; b < own.size(); ++b) {
      const glm::vec3 d =
          (glm::vec3(own[b][3]) - glm::vec3(own0[0][3])) - (glm::vec3(applied[b][3]) - glm::vec3(applied0[0][3]));
      EXPECT_LT(glm::length(d), 1e-3f) << "bone " << b;
    }
  }
}

TEST(Bvh, NameMapDrivesRenamedBones) {
  const Character source = loadBvhCharacter(kMotion + "makehuman_walk1.bvh");
  Character renamed = source;
  std::string map = "# bvh joint -> target bone\n\n";
  for (int b = 0; b < renamed.skeleton.boneCount(); ++b) {
    map += renamed.skeleton.bone(b).name + "   mq_" + renamed.skeleton.bone(b).name + "  # renamed\n";
    renamed.skeleton.bone(b).name = "mq_" + renamed.skeleton.bone(b).name;
  }
  renamed.clips = {importBvhMotion(kMotion + "makehuman_walk1.bvh", renamed, writeTemp("walk.map", map))};
  for (float t : {0.0f, 0.2f, 0.5f})
    expectSameRotations(worldRotationChange(source, 0, t), worldRotationChange(renamed, 0, t));
}

TEST(Bvh, RetargetsOntoBonesWithOtherLocalAxes) {
  const Character source = loadBvhCharacter(kMotion + "cmu_01_01.bvh");
  Character target = source;
  target.clips.clear();
  std::mt19937 rng(12111);
  std::normal_distribution<float> n(0.0f, 1.0f);
  for (int b = 0; b < target.skeleton.boneCount(); ++b)
    target.skeleton.bone(b).rest.rotation = glm::normalize(glm::quat(n(rng), n(rng), n(rng), n(rng)));
  target.skeleton.bone(0).parentFromOffset = glm::mat4_cast(glm::angleAxis(-1.5707963f, glm::vec3(1, 0, 0)));
  target.clips.push_back(importBvhMotion(kMotion + "cmu_01_01.bvh", target));
  // Scrambled rest orientations put the bones in another rest pose; driven,
  // every single-child bone must point where its BVH joint points.
  int checked = 0;
  for (float t : {0.5f, 10.0f}) {
    const auto want = source.skeleton.worldTransforms(samplePose(source, 0, t));
    const auto got = target.skeleton.worldTransforms(samplePose(target, 0, t));
    for (int b = 0; b < target.skeleton.boneCount(); ++b) {
      const auto children = target.skeleton.children(b);
      if (children.size() != 1) continue;
      const glm::vec3 dw = glm::normalize(glm::vec3(want[children[0]][3]) - glm::vec3(want[b][3]));
      const glm::vec3 dg = glm::normalize(glm::vec3(got[children[0]][3]) - glm::vec3(got[b][3]));
      EXPECT_GT(glm::dot(dw, dg), 1.0f - 1e-4f) << target.skeleton.bone(b).name << " at t " << t;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

TEST(Bvh, UnrelatedSkeletonIsRefused) {
  const Character skin =
      importCharacter(std::string(MANNEQUIN_SHARED_DIR) + "/assets/characters/SimpleSkin/SimpleSkin.gltf");
  try {
    importBvhMotion(kMotion + "cmu_01_01.bvh", skin);
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), kMotion + "cmu_01_01.bvh");
    EXPECT_NE(std::string(e.what()).find("no BVH joint matches"), std::string::npos);
  }
}

void expectFileError(const std::string& path, const std::string& fragment) {
  try {
    loadBvhCharacter(path);
    FAIL() << "expected FileError for " << path;
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), path);
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Bvh, MalformedFilesNameTheLine) {
  expectFileError(writeTemp("garbage.bvh", "\x7f\x45\x4c\x46 binary junk \x01\x02"), "line 1");
  expectFileError(writeTemp("bad_offset.bvh", "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 x\n"), "line 4");
  expectFileError(writeTemp("bad_channel.bvh", "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 1 Wrotation\n}\n"),
                  "unknown channel");
  expectFileError(writeTemp("short_row.bvh",
                            "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 3 Zrotation Xrotation Yrotation\n}\n"
                            "MOTION\nFrames: 2\nFrame Time: 0.1\n1 2 3\n4 5\n"),
                  "line 11: frame 1 has 2 values, expected 3");
  expectFileError(writeTemp("huge_frames.bvh",
                            "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 3 Zrotation Xrotation Yrotation\n}\n"
                            "MOTION\nFrames: 4000000000\nFrame Time: 0.1\n1 2 3\n"),
                  "line 8: implausible frame count");
  expectFileError(writeTemp("few_frames.bvh",
                            "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 3 Zrotation Xrotation Yrotation\n}\n"
                            "MOTION\nFrames: 40000\nFrame Time: 0.1\n1 2 3\n"),
                  "file ends after 1 of 40000 frames");
  const std::string cmu = loadFileText(kMotion + "cmu_01_01.bvh");
  expectFileError(writeTemp("truncated.bvh", cmu.substr(0, cmu.size() / 2)), "frame");
  expectFileError(tempPath("missing.bvh"), "no such file");
}

TEST(Bvh, MalformedNameMapNamesTheLine) {
  const Character c = loadBvhCharacter(kMotion + "makehuman_walk1.bvh");
  const std::string map = writeTemp("bad.map", "Root Root\nSpine1 Spine1 extra\n");
  try {
    importBvhMotion(kMotion + "makehuman_walk1.bvh", c, map);
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), map);
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
  const std::string unknown = writeTemp("unknown.map", "Root no_such_bone\n");
  EXPECT_THROW(importBvhMotion(kMotion + "makehuman_walk1.bvh", c, unknown), FileError);
}

}  // namespace
}  // namespace mq
