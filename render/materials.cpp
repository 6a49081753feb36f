#include "render/materials.h"

#include <vtkActor.h>
#include <vtkProperty.h>

namespace mq::render {
namespace {

bool isDefaultGrey(const glm::vec3& c) { return c.x == 0.8f && c.y == 0.8f && c.z == 0.8f; }

}  // namespace

void applyMannequinMaterial(vtkActor* actor, const glm::vec3& baseColor) {
  const glm::vec3 colour = isDefaultGrey(baseColor) ? glm::vec3(0.80f, 0.70f, 0.58f) : baseColor;
  vtkProperty* p = actor->GetProperty();
  p->SetInterpolationToPhong();
  p->SetColor(colour.x, colour.y, colour.z);
  p->SetAmbient(0.18);
  p->SetDiffuse(0.85);
  p->SetSpecular(0.28);
  p->SetSpecularPower(24.0);
  p->SetSpecularColor(1.0, 0.96, 0.9);
}

}  // namespace mq::render
