#pragma once
// The polydata mapper of the character's surfaces and the cloth: feeds the
// view's lights (view_lights.h) to their shaders each frame, and binds extra
// textures (the skin's pre-integrated table, its albedo map) to sampler
// uniforms the shader replacements declare themselves. VTK 9.1 binds only the property's own
// textures; these ride along through RenderPiece (activate, draw,
// deactivate) and SetMapperShaderParameters (the sampler's texture unit).
// With samplers bound it also sets mqPixelAngle (pixelAngle below).

#include <string>
#include <utility>
#include <vector>

#include <vtkOpenGLPolyDataMapper.h>
#include <vtkSmartPointer.h>
#include <glm/glm.hpp>

#include "render/view_lights.h"

class vtkRenderer;
class vtkTexture;
class vtkUniforms;

namespace mq::render {

// Radians per pixel at the image's centre (vertical), for shaders that fade
// detail by its size on screen; 0 under a parallel projection.
float pixelAngle(vtkRenderer* renderer);

// Shared by the surface shaders (the mannequin's wood, the skin).
void setUniform3(vtkUniforms* u, const char* name, const glm::vec3& v);
// GLSL ending a surface shader's light replacement: the survey's rim term,
// (1 - N.V)^k times the light from behind (rimLight), then exposure and
// sRGB encoding of `colour`. Reads mqRim, mqRimPower, mqExposure, NdV,
// albedo, rimLight and colour; closes the replacement's block.
extern const char* const kRimLightAndOutputGlsl;

class SurfaceMapper : public vtkOpenGLPolyDataMapper {
 public:
  static SurfaceMapper* New();
  vtkTypeMacro(SurfaceMapper, vtkOpenGLPolyDataMapper);

  // Textures to bind, each to `uniform sampler2D <name>`; replaces the last set.
  void setSamplers(std::vector<std::pair<std::string, vtkSmartPointer<vtkTexture>>> samplers);

  void RenderPiece(vtkRenderer* renderer, vtkActor* actor) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

 protected:
  SurfaceMapper() = default;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* renderer, vtkActor* actor) override;

 private:
  std::vector<std::pair<std::string, vtkSmartPointer<vtkTexture>>> samplers_;
};

}  // namespace mq::render
