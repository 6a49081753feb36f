#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/scene/open_scene.h"
#include "core/scene/scene_document.h"
#include "core/util/error.h"

namespace mq {
namespace {

namespace fs = std::filesystem;

fs::path scratchDir() {
  const fs::path dir = fs::temp_directory_path() / ("mq_doc_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

void writeText(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

TEST(SceneDocument, RoundTripKeepsEverything) {
  SceneDocument doc;
  doc.character = "chars/hero.glb";
  doc.motionFile = "walk.bvh";
  doc.motionInPlace = true;
  doc.clip = "walk";
  doc.time = 0.75f;
  doc.poseRotations["upperarm_l"] = glm::normalize(glm::quat(0.9f, 0.1f, 0.2f, 0.3f));
  doc.view.showSkeleton = true;
  doc.view.hasCamera = true;
  doc.view.cameraPosition = {1, 2, 3};
  doc.hair = {{"style", "bob"}};
  doc.helperBones = true;
  doc.autoRig = true;
  const fs::path path = scratchDir() / "round.mqscene";
  saveSceneDocument(doc, path.string());
  const SceneDocument back = loadSceneDocument(path.string());
  EXPECT_EQ(back.character, doc.character);
  EXPECT_EQ(back.motionFile, doc.motionFile);
  EXPECT_TRUE(back.motionInPlace);
  EXPECT_EQ(back.clip, "walk");
  EXPECT_FLOAT_EQ(back.time, 0.75f);
  ASSERT_EQ(back.poseRotations.count("upperarm_l"), 1u);
  EXPECT_NEAR(glm::dot(back.poseRotations.at("upperarm_l"), doc.poseRotations.at("upperarm_l")), 1.0f, 1e-6f);
  EXPECT_TRUE(back.view.showSkeleton);
  EXPECT_FLOAT_EQ(back.view.cameraPosition.z, 3.0f);
  EXPECT_EQ(back.hair["style"], "bob");
  EXPECT_TRUE(back.garments.is_null());
  EXPECT_TRUE(back.helperBones);
  EXPECT_TRUE(back.autoRig);
}

TEST(SceneDocument, NullCharacterMeansNone) {
  const SceneDocument doc =
      parseSceneDocument(R"({"format":"mannequin-scene","version":1,"character":null})", "x.mqscene");
  EXPECT_FALSE(doc.hasCharacter());
}

void expectFileError(const std::string& text, const std::string& fragment) {
  try {
    parseSceneDocument(text, "scene.mqscene");
    FAIL() << "no error for: " << text;
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), "scene.mqscene");
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(SceneDocument, NoClipIsTheRestPoseButABareCharacterPlaysItsFirstClip) {
  SceneDocument doc;  // the built-in mannequin, with its walk and arm raise
  EXPECT_EQ(resolveSceneDocument(doc, "").clipIndex, -1);
  doc.clip = "arm_raise";
  EXPECT_EQ(resolveSceneDocument(doc, "").clipIndex, 1);
  EXPECT_EQ(openScene("default").clipIndex, 0);
}

TEST(SceneDocument, BadDocumentsFailClearly) {
  expectFileError(R"({"format":"mannequin-scene","vers)", "not valid JSON");
  expectFileError("\x01\x02garbage", "not valid JSON");
  expectFileError(R"([1,2,3])", "not a Mannequin scene document");
  expectFileError(R"({"format":"other","version":1})", "not a Mannequin scene document");
  expectFileError(R"({"format":"mannequin-scene","version":7})", "newer version");
  expectFileError(R"({"format":"mannequin-scene","version":1,"pose":{"head":[0,0,0]}})", "quaternion");
  expectFileError(R"({"format":"mannequin-scene","version":1,"animation":{"time":"soon"}})", "number");
  expectFileError(R"({"format":"mannequin-scene","version":1,"skinning":{"helper_bones":"yes"}})",
                  "skinning.helper_bones must be true or false");
  expectFileError(R"({"format":"mannequin-scene","version":1,"auto_rig":1})", "\"auto_rig\" must be true or false");
  expectFileError(R"({"format":"mannequin-scene","version":1,"motion":{"file":"a.bvh","inPlace":"yes"}})",
                  "\"motion\".\"inPlace\" must be true or false");
}

TEST(SceneDocument, MissingFileNamesTheFile) {
  try {
    loadSceneDocument("/nonexistent/dir/scene.mqscene");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/scene.mqscene"), std::string::npos);
  }
}

TEST(SceneDocument, FailedSaveLeavesPreviousFileIntact) {
  const fs::path dir = scratchDir();
  const fs::path path = dir / "keep.mqscene";
  writeText(path, "previous");
  SceneDocument doc;
  doc.time = std::numeric_limits<float>::quiet_NaN();  // serialises as null; still a valid save
  // A save into a missing directory fails and must not touch anything else.
  EXPECT_THROW(saveSceneDocument(doc, (dir / "missing" / "x.mqscene").string()), FileError);
  std::ifstream in(path);
  std::string content;
  std::getline(in, content);
  EXPECT_EQ(content, "previous");
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << "temporary file left behind";
}

TEST(SceneDocument, ResolvesPathsRelativeToTheDocument) {
  EXPECT_EQ(resolveDocumentPath("/a/b/scene.mqscene", "chars/x.glb"), "/a/b/chars/x.glb");
  EXPECT_EQ(resolveDocumentPath("/a/b/scene.mqscene", "/abs/x.glb"), "/abs/x.glb");
}

}  // namespace
}  // namespace mq
