#pragma once
// The renderer's switched-on lights as shader inputs: the direction towards
// each light in view coordinates and its colour times intensity. Shader
// replacements that do their own lighting (surfaces, skin, cloth, hair) read
// these every frame as the uniforms mqLightCount, mqLightDirVC[kMax],
// mqLightColour[kMax] and mqUpVC, so they follow whatever lights the view has
// (camera, head or scene lights).

#include <glm/glm.hpp>

class vtkRenderer;
class vtkUniforms;

namespace mq::render {

struct ViewLights {
  static constexpr int kMax = 6;
  int count = 0;
  float towardLightVC[kMax][3] = {};
  float colour[kMax][3] = {};
  float upVC[3] = {0.0f, 1.0f, 0.0f};  // world +y in view coordinates
  // The key light for shadows (world): strong and from the viewer's side (a
  // rim light behind the hair would put everything the viewer sees in shadow).
  glm::vec3 keyTowardLightWorld{0.0f, 1.0f, 0.0f};
};

ViewLights gatherViewLights(vtkRenderer* renderer);

// Writes `lights` into a shader's custom uniforms (the names above).
void setViewLightUniforms(vtkUniforms* u, const ViewLights& lights);
// Declares them with no light, so that the first shader compiles with them
// before a frame has gathered the view's lights.
inline void declareViewLightUniforms(vtkUniforms* u) { setViewLightUniforms(u, ViewLights{}); }

}  // namespace mq::render
