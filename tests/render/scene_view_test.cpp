// Offscreen images of SceneView: the character is there, framed, lit, posed,
// and matches its baseline. Needs X: a private Xvfb starts when none answers.
#include <gtest/gtest.h>

#include <cmath>

#include <vtkActor.h>
#include <vtkRenderer.h>

#include "core/character/posed_character.h"
#include "core/scene/open_scene.h"
#include "render/image_checks.h"
#include "render/offscreen.h"
#include "render/scene_view.h"
#include "render/test_figure.h"

namespace mq {
namespace {

constexpr int kWidth = 320, kHeight = 240;

class SceneViewTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { test::useSoftwareRendering(); }

  // The view framed for the test size, in the rest pose or clip/time.
  void show(const Character& character, int clip = -1, float time = 0.0f) {
    view.setCharacter(character);
    pose(character, clip, time);
    view.frameAll(double(kWidth) / kHeight);
  }
  void pose(const Character& character, int clip, float time) {
    posed.evaluate(character, clip, time, nullptr, nullptr);
    view.updatePose(posed);
  }
  // The same scene without the character's meshes.
  render::RgbImage background(render::OffscreenRenderer& r, size_t meshCount) {
    for (size_t i = 0; i < meshCount; ++i) view.meshActor(int(i))->VisibilityOff();
    render::RgbImage image = r.capture();
    for (size_t i = 0; i < meshCount; ++i) view.meshActor(int(i))->VisibilityOn();
    return image;
  }

  render::SceneView view;
  PosedCharacter posed;
};

// Pixels whose blue clearly exceeds red: the skeleton's sticks (the figure,
// the floor and the backdrop are warm or grey).
size_t bluePixels(const render::RgbImage& image) {
  size_t n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.at(x, y)[2] > image.at(x, y)[0] + 60) ++n;
  return n;
}

// Pixels that are strongly orange: the highlighted bone.
size_t orangePixels(const render::RgbImage& image) {
  size_t n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.at(x, y);
      if (p[0] > 150 && p[0] > p[1] + 50 && p[0] > p[2] + 110) ++n;
    }
  return n;
}

TEST_F(SceneViewTest, DefaultMannequinIsVisibleAndCentred) {
  const LoadedScene scene = openScene("default");
  ASSERT_FALSE(scene.character.meshes.empty());
  show(scene.character);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage image = renderer.capture();
  const test::Foreground f = test::foregroundOf(image, background(renderer, scene.character.meshes.size()));
  // A standing figure framed to the height of the image covers a tall thin strip.
  EXPECT_GT(f.fraction, 0.04);
  EXPECT_LT(f.fraction, 0.40);
  EXPECT_NEAR(f.centre.x, 0.5, 0.08);
  EXPECT_NEAR(f.centre.y, 0.5, 0.12);
  // Framed: head and feet inside the image, using most of its height.
  EXPECT_GT(f.min.y, 0.02);
  EXPECT_LT(f.max.y, 0.98);
  EXPECT_GT(f.max.y - f.min.y, 0.6);
}

TEST_F(SceneViewTest, WeightHeatColoursTheSelectedBonesSkin) {
  const LoadedScene scene = openScene("default");
  show(scene.character);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage shaded = renderer.capture();
  const int forearm = scene.character.skeleton.findBone("forearm_l");
  ASSERT_GE(forearm, 0);
  view.setVertexHeat(boneWeights(scene.character, forearm));
  const render::RgbImage heat = renderer.capture();
  // Red where the forearm has all the weight, blue on the rest of the body.
  size_t red = 0, blue = 0;
  for (int y = 0; y < heat.height; ++y)
    for (int x = 0; x < heat.width; ++x) {
      const uint8_t* p = heat.at(x, y);
      red += p[0] > 120 && p[0] > 2 * p[1] && p[0] > 2 * p[2];
      blue += p[2] > 90 && p[2] > 2 * p[0] && p[2] > p[1] + 30;
    }
  EXPECT_GT(red, 40u);
  EXPECT_GT(blue, 10 * red);
  // Cleared: the shaded surface again.
  view.setVertexHeat({});
  EXPECT_LT(test::compareImages(renderer.capture(), shaded).rms, 0.5);
  unsigned char rgb[3];
  render::heatColor(0.0f, rgb);
  EXPECT_GT(rgb[2], rgb[0]);
  render::heatColor(1.0f, rgb);
  EXPECT_GT(rgb[0], rgb[2]);
  render::heatColor(std::nanf(""), rgb);  // no value: as 0
  EXPECT_GT(rgb[2], rgb[0]);
}

TEST_F(SceneViewTest, SectionConesAreDrawnAroundTheLimbsAndFollowThePose) {
  const LoadedScene scene = openScene("default");
  show(scene.character);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage plain = renderer.capture();
  view.showSectionCones(scene.character);
  EXPECT_EQ(view.sectionConeCount(), 15);  // the head and each arm, hand, leg, foot and toes: the limbs
  const render::RgbImage cones = renderer.capture();
  EXPECT_GT(test::compareImages(plain, cones).changedFraction, 0.01);
  // Raising the arms moves the arms' cones with them.
  pose(scene.character, scene.character.findClip("arm_raise"), 1.0f);
  const render::RgbImage raised = renderer.capture();
  view.hideSectionCones();
  EXPECT_EQ(view.sectionConeCount(), 0);
  const render::RgbImage raisedPlain = renderer.capture();
  EXPECT_GT(test::compareImages(raised, raisedPlain).changedFraction, 0.01);
}

TEST_F(SceneViewTest, TestFigureMatchesBaseline) {
  show(test::makeTestFigure());
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const std::string problem = test::checkAgainstBaseline(renderer.capture(), "test_figure_rest");
  EXPECT_TRUE(problem.empty()) << problem;
}

TEST_F(SceneViewTest, SameSceneGivesSameImage) {
  show(test::makeTestFigure());
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage first = renderer.capture();
  const render::RgbImage second = renderer.capture();
  EXPECT_EQ(first.pixels, second.pixels);
}

TEST_F(SceneViewTest, UpdatePoseMovesTheImageWithoutRebuilding) {
  const Character figure = test::makeTestFigure();
  show(figure);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage rest = renderer.capture();
  const render::RgbImage empty = background(renderer, 1);
  vtkActor* actorBefore = view.meshActor(0);

  pose(figure, figure.findClip("arm_raise"), 1.0f);
  const render::RgbImage raised = renderer.capture();
  EXPECT_EQ(view.meshActor(0), actorBefore);

  const test::ImageDifference d = test::compareImages(rest, raised);
  EXPECT_GT(d.changedFraction, 0.01);
  // The raised hands reach above the head: the figure's top moves up.
  const test::Foreground before = test::foregroundOf(rest, empty);
  const test::Foreground after = test::foregroundOf(raised, empty);
  EXPECT_LT(after.min.y, before.min.y - 0.05);
  const std::string problem = test::checkAgainstBaseline(raised, "test_figure_arm_raise");
  EXPECT_TRUE(problem.empty()) << problem;
}

TEST_F(SceneViewTest, DefaultMannequinArmRaiseChangesTheImage) {
  const Character mannequin = openScene("default").character;
  const int clip = mannequin.findClip("arm_raise");
  ASSERT_GE(clip, 0);
  show(mannequin);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage rest = renderer.capture();
  const Clip& raise = mannequin.clips[clip];
  pose(mannequin, clip, raise.startTime() + 0.5f * raise.duration());  // arms up at mid-clip
  EXPECT_GT(test::compareImages(rest, renderer.capture()).changedFraction, 0.01);
}

// Mean brightness of the outermost `depth` pixels on each row's right-hand
// silhouette (the main rim light is behind the figure, to the viewer's right),
// and of the pixels 6..8 further in.
std::pair<double, double> rightEdgeBrightness(const render::RgbImage& image, const render::RgbImage& empty) {
  double edge = 0.0, inside = 0.0;
  int rows = 0;
  auto brightness = [&](int x, int y) { return (image.at(x, y)[0] + image.at(x, y)[1] + image.at(x, y)[2]) / 3.0; };
  for (int y = 0; y < image.height; ++y) {
    int right = -1;
    for (int x = image.width - 1; x >= 0 && right < 0; --x)
      if (std::abs(image.at(x, y)[1] - empty.at(x, y)[1]) > 24) right = x;
    if (right < 12) continue;
    edge += (brightness(right, y) + brightness(right - 1, y)) / 2.0;
    inside += (brightness(right - 6, y) + brightness(right - 7, y) + brightness(right - 8, y)) / 3.0;
    ++rows;
  }
  return {rows ? edge / rows : 0.0, rows ? inside / rows : 0.0};
}

TEST_F(SceneViewTest, RimLightBrightensTheSilhouette) {
  show(test::makeTestFigure());
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage empty = background(renderer, 1);
  render::SurfaceLook look = render::SurfaceLook::mannequin();
  const auto [edgeWithRim, insideWithRim] = rightEdgeBrightness(renderer.capture(), empty);
  look.rim = 0.0f;
  view.setSurfaceLook(look);
  const auto [edgeWithout, insideWithout] = rightEdgeBrightness(renderer.capture(), empty);
  // The rim lights the outline and leaves the inside nearly alone.
  EXPECT_GT(edgeWithRim - edgeWithout, 15.0);
  EXPECT_LT(insideWithRim - insideWithout, 0.5 * (edgeWithRim - edgeWithout));
  EXPECT_GT(edgeWithRim, insideWithRim);
}

TEST_F(SceneViewTest, AmbientOcclusionDarkensWhereSurfacesMeet) {
  const LoadedScene scene = openScene("default");
  show(scene.character);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const render::RgbImage empty = background(renderer, scene.character.meshes.size());
  const render::RgbImage plain = renderer.capture();
  view.setAmbientOcclusion(true);
  const render::RgbImage occluded = renderer.capture();
  view.setAmbientOcclusion(false);
  EXPECT_EQ(test::compareImages(renderer.capture(), plain).rms, 0.0);  // switches back off
  // Over the figure: darker overall, never brighter, but most of it open to the sky.
  size_t figure = 0, darker = 0;
  double change = 0.0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      if (std::abs(plain.at(x, y)[1] - empty.at(x, y)[1]) <= 24) continue;
      ++figure;
      const int d = int(occluded.at(x, y)[1]) - int(plain.at(x, y)[1]);
      change += d;
      if (d < -8) ++darker;
    }
  ASSERT_GT(figure, 0u);
  EXPECT_LT(change / figure, -0.5);
  EXPECT_GT(darker, figure / 100);
  EXPECT_LT(darker, figure / 2);
  render::writePng(occluded, MANNEQUIN_BINARY_DIR "/Testing/Temporary/ambient_occlusion.png");
}

TEST_F(SceneViewTest, SkeletonOverlayShowsThroughTheBody) {
  show(test::makeTestFigure());
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  const size_t withoutSkeleton = bluePixels(renderer.capture());
  view.setSkeletonVisible(true);
  const render::RgbImage withSkeleton = renderer.capture();
  // The spine runs inside the torso: it can only show if drawn on top.
  EXPECT_GT(bluePixels(withSkeleton), withoutSkeleton + 150);
  EXPECT_EQ(orangePixels(withSkeleton), 0u);

  view.setHighlightedBone(test::makeTestFigure().skeleton.findBone("thigh_l"));
  EXPECT_GT(orangePixels(renderer.capture()), 30u);
}

TEST_F(SceneViewTest, SkeletonOnlyCharacterIsFramedByItsJoints) {
  Character motionOnly = test::makeTestFigure();
  motionOnly.meshes.clear();  // what a BVH file gives
  view.setCharacter(motionOnly);
  ASSERT_TRUE(view.characterBounds().valid());
  EXPECT_NEAR(view.characterBounds().max.y, 1.57f, 1e-4f);  // the head joint
  view.setSkeletonVisible(true);
  view.frameAll(double(kWidth) / kHeight);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  EXPECT_GT(bluePixels(renderer.capture()), 300u);
}

TEST_F(SceneViewTest, PickBoneFindsTheBoneUnderTheCursor) {
  const Character figure = test::makeTestFigure();
  show(figure);
  render::OffscreenRenderer renderer(view, kWidth, kHeight);
  renderer.capture();
  auto displayOf = [&](glm::vec3 p) {
    view.renderer()->SetWorldPoint(p.x, p.y, p.z, 1.0);
    view.renderer()->WorldToDisplay();
    const double* d = view.renderer()->GetDisplayPoint();
    return glm::ivec2(int(d[0] + 0.5), int(d[1] + 0.5));
  };
  // Middle of the left shin, on the surface (the figure faces +z), and the
  // middle of the chest.
  const glm::ivec2 shin = displayOf({0.1f, 0.28f, 0.05f});
  EXPECT_EQ(view.pickBone(shin.x, shin.y), figure.skeleton.findBone("shin_l"));
  const glm::ivec2 head = displayOf({0.0f, 1.68f, 0.1f});
  EXPECT_EQ(view.pickBone(head.x, head.y), figure.skeleton.findBone("head"));
  EXPECT_EQ(view.pickBone(2, kHeight - 3), -1);  // the backdrop

  view.setSkeletonVisible(true);  // joints win when drawn
  const glm::ivec2 elbow = displayOf({0.22f, 1.14f, 0.0f});
  EXPECT_EQ(view.pickBone(elbow.x, elbow.y), figure.skeleton.findBone("forearm_l"));
}

TEST_F(SceneViewTest, FrameAllKeepsTheCharacterInsideAnyAspect) {
  const Character figure = test::makeTestFigure();
  for (const auto& [w, h] : {std::pair{320, 240}, std::pair{160, 320}, std::pair{400, 120}}) {
    render::SceneView local;
    local.setCharacter(figure);
    local.frameAll(double(w) / h);
    render::OffscreenRenderer renderer(local, w, h);
    const render::RgbImage image = renderer.capture();
    local.meshActor(0)->VisibilityOff();
    const test::Foreground f = test::foregroundOf(image, renderer.capture());
    EXPECT_GT(f.min.x, 0.0) << w << "x" << h;
    EXPECT_LT(f.max.x, 1.0) << w << "x" << h;
    EXPECT_GT(f.min.y, 0.0) << w << "x" << h;
    EXPECT_LT(f.max.y, 1.0) << w << "x" << h;
    EXPECT_GT(std::max(f.max.x - f.min.x, f.max.y - f.min.y), 0.6) << w << "x" << h;
  }
}

}  // namespace
}  // namespace mq
