#pragma once
// The renderer's switched-on lights as shader inputs: the direction towards
// each light in view coordinates and its colour times intensity. Shader
// replacements that do their own lighting read these every frame, so they
// follow whatever lights the view has (camera, head or scene lights).

#include <glm/glm.hpp>

class vtkRenderer;

namespace mq::render {

struct ViewLights {
  static constexpr int kMax = 6;
  int count = 0;
  float towardLightVC[kMax][3] = {};
  float colour[kMax][3] = {};
  float upVC[3] = {0.0f, 1.0f, 0.0f};  // world +y in view coordinates
};

ViewLights gatherViewLights(vtkRenderer* renderer);

}  // namespace mq::render
