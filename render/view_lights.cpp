#include "render/view_lights.h"

#include <algorithm>

#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>
#include <vtkUniforms.h>

namespace mq::render {
namespace {

glm::vec3 toGlm(const double v[3]) { return {float(v[0]), float(v[1]), float(v[2])}; }

void store(const glm::vec3& v, float out[3]) {
  for (int k = 0; k < 3; ++k) out[k] = v[k];
}

}  // namespace

ViewLights gatherViewLights(vtkRenderer* renderer) {
  ViewLights set;
  vtkMatrix4x4* view = renderer->GetActiveCamera()->GetViewTransformMatrix();
  glm::mat3 viewFromWorld(1.0f);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) viewFromWorld[c][r] = float(view->GetElement(r, c));
  const glm::mat3 worldFromView = glm::transpose(viewFromWorld);
  store(glm::normalize(viewFromWorld * glm::vec3(0.0f, 1.0f, 0.0f)), set.upVC);

  float strongestKey = -1.0f;
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem()) {
    if (!light->GetSwitch() || set.count >= ViewLights::kMax) continue;
    glm::vec3 toward;
    if (light->LightTypeIsHeadlight())
      toward = {0.0f, 0.0f, 1.0f};
    else if (light->LightTypeIsCameraLight())  // camera-light axes are the view axes
      toward = toGlm(light->GetPosition()) - toGlm(light->GetFocalPoint());
    else
      toward = viewFromWorld * (toGlm(light->GetPosition()) - toGlm(light->GetFocalPoint()));
    if (glm::length(toward) < 1e-9f) continue;
    toward = glm::normalize(toward);
    const float intensity = float(light->GetIntensity());
    store(toward, set.towardLightVC[set.count]);
    store(toGlm(light->GetDiffuseColor()) * intensity, set.colour[set.count]);
    ++set.count;
    const float keyScore = intensity * (0.2f + std::max(toward.z, 0.0f));
    if (keyScore > strongestKey) {
      strongestKey = keyScore;
      set.keyTowardLightWorld = glm::normalize(worldFromView * toward);
    }
  }
  return set;
}

void setViewLightUniforms(vtkUniforms* u, const ViewLights& lights) {
  u->SetUniformi("mqLightCount", lights.count);
  u->SetUniform3fv("mqLightDirVC", ViewLights::kMax, lights.towardLightVC);
  u->SetUniform3fv("mqLightColour", ViewLights::kMax, lights.colour);
  u->SetUniform3f("mqUpVC", lights.upVC);
}

}  // namespace mq::render
