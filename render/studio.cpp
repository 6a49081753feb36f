#include "render/studio.h"

#include <glm/glm.hpp>

#include <cmath>

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderer.h>
#include <vtkPBRIrradianceTexture.h>
#include <vtkPBRLUTTexture.h>
#include <vtkPBRPrefilterTexture.h>
#include <vtkPointData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

namespace mq::render {
namespace {

// Positions are in the camera frame of vtkLight camera lights: the camera sits
// at (0, 0, 1) looking at the origin, +x to its right, +y up; the lights are
// directional (from the position towards the origin).
void addCameraLight(vtkRenderer* renderer, double x, double y, double z, double r, double g, double b,
                    double intensity) {
  vtkNew<vtkLight> light;
  light->SetLightTypeToCameraLight();
  light->SetPositional(false);
  light->SetPosition(x, y, z);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->SetColor(r, g, b);
  light->SetIntensity(intensity);
  renderer->AddLight(light);
}

// Linear radiance of the studio in world direction d (y up, the character
// faces +z): a sky graded from horizon to zenith, a dim floor, and a soft
// rectangular light high at the front left, like the key light.
glm::vec3 studioRadiance(const glm::vec3& d) {
  const glm::vec3 zenith(0.55f, 0.60f, 0.68f), horizon(0.42f, 0.42f, 0.42f), floor(0.10f, 0.09f, 0.085f);
  glm::vec3 colour = d.y >= 0.0f ? glm::mix(horizon, zenith, std::sqrt(d.y))
                                 : glm::mix(horizon * 0.5f, floor, std::min(1.0f, -d.y * 4.0f));
  const glm::vec3 keyDirection = glm::normalize(glm::vec3(-0.6f, 0.6f, 0.55f));
  const float key = glm::dot(d, keyDirection);
  colour += glm::vec3(1.6f, 1.5f, 1.35f) * glm::smoothstep(0.88f, 0.95f, key);
  return colour;
}

vtkSmartPointer<vtkTexture> makeStudioEnvironment() {
  constexpr int kWidth = 128, kHeight = 64;
  vtkNew<vtkImageData> image;
  image->SetDimensions(kWidth, kHeight, 1);
  vtkNew<vtkFloatArray> radiance;
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(kWidth * kHeight);
  for (int row = 0; row < kHeight; ++row) {
    // VTK's equirectangular images: row 0 at the bottom (down), u around +y.
    const float latitude =
        (static_cast<float>(row) + 0.5f) / kHeight * static_cast<float>(M_PI) - static_cast<float>(M_PI_2);
    for (int column = 0; column < kWidth; ++column) {
      const float longitude = (static_cast<float>(column) + 0.5f) / kWidth * 2.0f * static_cast<float>(M_PI);
      const glm::vec3 d(std::cos(latitude) * std::sin(longitude), std::sin(latitude),
                        -std::cos(latitude) * std::cos(longitude));
      const glm::vec3 c = studioRadiance(d);
      radiance->SetTuple3(row * kWidth + column, c.x, c.y, c.z);
    }
  }
  image->GetPointData()->SetScalars(radiance);
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
  texture->MipmapOn();
  texture->SetColorModeToDirectScalars();
  return texture;
}

}  // namespace

void useStudioEnvironment(vtkRenderer* renderer, bool enabled) {
  if (renderer->GetUseImageBasedLighting() == enabled) return;
  renderer->SetUseImageBasedLighting(enabled);
  if (!enabled) return;
  static vtkSmartPointer<vtkTexture> studio = makeStudioEnvironment();
  renderer->SetEnvironmentTexture(studio, false);
  // VTK's defaults (a 1024^2 BRDF table, 512-sample prefiltering) take
  // seconds in software GL; these are enough for a soft studio.
  if (auto* gl = vtkOpenGLRenderer::SafeDownCast(renderer)) {
    gl->GetEnvMapLookupTable()->SetLUTSize(128);
    gl->GetEnvMapLookupTable()->SetLUTSamples(256);
    gl->GetEnvMapPrefiltered()->SetPrefilterMaxSamples(64);
    gl->GetEnvMapPrefiltered()->SetPrefilterLevels(5);
  }
}

void addThreePointLights(vtkRenderer* renderer) {
  renderer->AutomaticLightCreationOff();
  renderer->RemoveAllLights();
  addCameraLight(renderer, -0.9, 0.8, 0.8, 1.00, 0.95, 0.88, 1.00);   // key: warm, upper left
  addCameraLight(renderer, 1.0, 0.0, 0.7, 0.80, 0.88, 1.00, 0.22);    // fill: cool, right, low
  addCameraLight(renderer, 1.0, 0.5, -0.6, 1.00, 1.00, 1.00, 1.00);   // rim: behind, upper right
  addCameraLight(renderer, -1.0, 0.3, -0.6, 0.85, 0.90, 1.00, 0.60);  // second rim, left
}

void setStudioBackground(vtkRenderer* renderer) {
  renderer->GradientBackgroundOn();
  renderer->SetBackground(0.10, 0.11, 0.13);   // bottom
  renderer->SetBackground2(0.36, 0.40, 0.46);  // top
}

}  // namespace mq::render
