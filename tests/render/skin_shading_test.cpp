// The physically based skin look (render/skin_shader.cpp): pre-integrated
// scattering reddens the light past the terminator on small, curved skin and
// not on large skin; Volino wrinkles appear where the posed skin is
// compressed and nowhere in the rest pose. Needs X (a private Xvfb starts
// when none answers).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

#include "core/character/posed_character.h"
#include "core/scene/open_scene.h"
#include "render/image_checks.h"
#include "render/offscreen.h"
#include "render/scene_view.h"
#include "render/view_lights.h"

#include "../core/icosphere_util.h"

namespace mq {
namespace {

constexpr int kSize = 200;

// Writes `image` to Testing/Temporary/<name>.png for a person to look at.
void keep(const render::RgbImage& image, const std::string& name) {
  const std::filesystem::path folder = MANNEQUIN_BINARY_DIR "/Testing/Temporary";
  std::filesystem::create_directories(folder);
  render::writePng(image, (folder / (name + ".png")).string());
}

Character sphereCharacter(float radius) {
  const test::FlatMesh sphere = test::makeIcosphere(radius, 5);
  Character c;
  Mesh mesh;
  mesh.name = "sphere";
  mesh.positions = sphere.positions;
  mesh.normals = sphere.normals;
  mesh.triangles = sphere.triangles;
  c.meshes.push_back(mesh);
  return c;
}

struct TerminatorBand {
  double redOverGreen = 0.0;
  size_t pixels = 0;
};

// Mean R / mean G over the sphere's pixels whose normal is 80 to 100 degrees
// from the light, the camera on +z looking at the sphere's centre (so view
// and world axes agree) and one light in the horizontal plane.
TerminatorBand renderTerminatorBand(float radius) {
  render::SceneView view;
  const Character c = sphereCharacter(radius);
  view.setCharacter(c);
  view.setGridVisible(false);
  render::SurfaceLook look = render::SurfaceLook::skinPresetLook("skin1");
  look.microStrength = 0.0f;  // the relief would only add noise here
  view.setSurfaceLook(look);
  vtkRenderer* renderer = view.renderer();
  renderer->RemoveAllLights();
  vtkNew<vtkLight> key;
  key->SetLightTypeToCameraLight();
  key->SetPosition(-1.0, 0.0, 0.6);  // to the left, in front
  key->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(key);
  const float distance = radius / std::sin(12.0f * float(M_PI) / 180.0f);
  view.setCamera({0.0f, 0.0f, distance}, {0.0f, 0.0f, 0.0f});
  render::OffscreenRenderer offscreen(view, kSize, kSize);
  const render::RgbImage image = offscreen.capture();
  keep(image, radius < 0.1f ? "skin_sphere_small" : "skin_sphere_large");
  const render::ViewLights lights = render::gatherViewLights(renderer);
  EXPECT_EQ(lights.count, 1);
  const glm::vec3 toLight =
      glm::normalize(glm::vec3(lights.towardLightVC[0][0], lights.towardLightVC[0][1], lights.towardLightVC[0][2]));
  EXPECT_NEAR(toLight.y, 0.0f, 1e-4f);                   // horizontal: a flipped row order changes nothing
  const double tanHalf = std::tan(15.0 * M_PI / 180.0);  // VTK's default view angle, 30 degrees
  const glm::dvec3 eye(0.0, 0.0, distance);
  double red = 0.0, green = 0.0;
  TerminatorBand band;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::dvec3 ray = glm::normalize(
          glm::dvec3((2.0 * (x + 0.5) / kSize - 1.0) * tanHalf, (1.0 - 2.0 * (y + 0.5) / kSize) * tanHalf, -1.0));
      const double b = glm::dot(eye, ray), disc = b * b - (glm::dot(eye, eye) - double(radius) * radius);
      if (disc <= 0.0) continue;
      const glm::dvec3 normal = (eye + (-b - std::sqrt(disc)) * ray) / double(radius);
      if (normal.z < 0.3) continue;  // near the silhouette, pixels mix with the background
      const double cosine = glm::dot(normal, glm::dvec3(toLight));
      if (std::abs(cosine) > std::cos(80.0 * M_PI / 180.0)) continue;
      red += image.at(x, y)[0];
      green += image.at(x, y)[1];
      ++band.pixels;
    }
  band.redOverGreen = green > 0.0 ? red / green : 0.0;
  return band;
}

TEST(SkinShading, SmallSphereShowsMoreRedPastTheTerminator) {
  test::useSoftwareRendering();
  const TerminatorBand small = renderTerminatorBand(0.01f), large = renderTerminatorBand(1.0f);
  ASSERT_GT(small.pixels, 500u);
  ASSERT_GT(large.pixels, 500u);
  std::printf("R/G in the 80-100 degree band: radius 10 mm %.3f, 1 m %.3f\n", small.redOverGreen, large.redOverGreen);
  // First run (Mesa llvmpipe, skin1): 1.544 against 1.328, 16 % more red.
  EXPECT_GT(small.redOverGreen, 1.10 * large.redOverGreen);
}

// The default mannequin, close on its left elbow from above, in the rest
// pose or bent by the scene's pose edits.
class SkinWrinkleTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { test::useSoftwareRendering(); }

  render::RgbImage render(const LoadedScene& scene, bool bent, float wrinkleDepth, glm::vec2* elbowPixel = nullptr) {
    render::SceneView view;
    view.setCharacter(scene.character);
    PosedCharacter posed;
    posed.evaluate(scene.character, -1, 0.0f, bent ? &scene.edits : nullptr, nullptr);
    view.updatePose(posed);
    render::SurfaceLook look = render::SurfaceLook::skinPresetLook("skin1");
    look.wrinkleDepth = wrinkleDepth;
    view.setSkinLook(look);
    view.setLookMode(render::LookMode::Skin);
    const glm::vec3 elbow = glm::vec3(posed.worldFromBone()[scene.character.skeleton.findBone("forearm_l")][3]);
    view.setCamera(elbow + glm::vec3(0.0f, 0.35f, 0.12f), elbow);  // from above: the inner side
    render::OffscreenRenderer offscreen(view, kSize, kSize);
    const render::RgbImage image = offscreen.capture();
    if (elbowPixel) {
      view.renderer()->SetWorldPoint(elbow.x, elbow.y, elbow.z, 1.0);
      view.renderer()->WorldToDisplay();
      const double* d = view.renderer()->GetDisplayPoint();
      *elbowPixel = {float(d[0]), float(kSize - 1 - d[1])};  // image rows from the top
    }
    return image;
  }
};

TEST_F(SkinWrinkleTest, BendingTheElbowWrinklesItsInnerSideOnly) {
  const LoadedScene scene = openScene(MANNEQUIN_SOURCE_DIR "/docs/skinning_bend.mqscene");
  // Rest pose: no compression, so the wrinkle depth changes nothing.
  const test::ImageDifference rest = test::compareImages(render(scene, false, 0.0f), render(scene, false, 3.0f));
  EXPECT_LT(rest.rms, 0.05);
  // Bent: the wrinkles change the shading, near the elbow.
  glm::vec2 elbow;
  const render::RgbImage smooth = render(scene, true, 0.0f, &elbow);
  const render::RgbImage wrinkled = render(scene, true, 3.0f);
  keep(smooth, "skin_elbow_smooth");
  keep(wrinkled, "skin_elbow_wrinkles");
  size_t changed = 0, nearElbow = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      int d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(smooth.at(x, y)[c]) - int(wrinkled.at(x, y)[c])));
      if (d <= 6) continue;
      ++changed;
      if (glm::length(glm::vec2(x, y) - elbow) < 0.3f * kSize) ++nearElbow;
    }
  std::printf("bent elbow: %zu pixels changed by the wrinkles, %zu near the elbow\n", changed, nearElbow);
  EXPECT_GT(changed, 100u);
  // Most of it at the elbow; the rest where linear blend skinning also
  // squashes the top of the upper arm.
  EXPECT_GT(nearElbow, changed * 2 / 3);
}

}  // namespace
}  // namespace mq
