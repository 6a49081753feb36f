#include "render/studio.h"

#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

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

}  // namespace

void addThreePointLights(vtkRenderer* renderer) {
  renderer->AutomaticLightCreationOff();
  renderer->RemoveAllLights();
  addCameraLight(renderer, -0.9, 0.8, 0.8, 1.00, 0.95, 0.88, 1.00);  // key: warm, upper left
  addCameraLight(renderer, 1.0, 0.0, 0.7, 0.80, 0.88, 1.00, 0.22);   // fill: cool, right, low
  addCameraLight(renderer, 1.0, 0.5, -0.6, 1.00, 1.00, 1.00, 1.00);  // rim: behind, upper right
  addCameraLight(renderer, -1.0, 0.3, -0.6, 0.85, 0.90, 1.00, 0.60); // second rim, left
}

void setStudioBackground(vtkRenderer* renderer) {
  renderer->GradientBackgroundOn();
  renderer->SetBackground(0.10, 0.11, 0.13);   // bottom
  renderer->SetBackground2(0.36, 0.40, 0.46);  // top
}

}  // namespace mq::render
