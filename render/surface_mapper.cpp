#include "render/surface_mapper.h"

#include <cmath>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLHelper.h>
#include <vtkOpenGLTexture.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkShaderProperty.h>
#include <vtkTexture.h>
#include <vtkUniforms.h>

#include "render/view_lights.h"

namespace mq::render {

const char* const kRimLightAndOutputGlsl = R"(
    float rimShape = pow(1.0 - NdV, mqRimPower);
    colour += mqRim * rimShape * rimLight * mix(vec3(1.0), albedo / max(albedo.r, 1e-3), 0.35);
    gl_FragData[0] = vec4(pow(mqExposure * colour, vec3(1.0 / 2.2)), opacity);
  }
)";

void setUniform3(vtkUniforms* u, const char* name, const glm::vec3& v) {
  const float values[3] = {v.x, v.y, v.z};
  u->SetUniform3f(name, values);
}

vtkStandardNewMacro(SurfaceMapper);

float pixelAngle(vtkRenderer* renderer) {
  const int* size = renderer->GetSize();
  const double height = size && size[1] > 0 ? size[1] : 1.0;
  vtkCamera* camera = renderer->GetActiveCamera();
  if (camera->GetParallelProjection()) return 0.0f;  // no perspective: see the shader's fallback
  return static_cast<float>(2.0 * std::tan(0.5 * camera->GetViewAngle() * M_PI / 180.0) / height);
}

void SurfaceMapper::setSamplers(std::vector<std::pair<std::string, vtkSmartPointer<vtkTexture>>> samplers) {
  samplers_ = std::move(samplers);
  Modified();
}

void SurfaceMapper::RenderPiece(vtkRenderer* renderer, vtkActor* actor) {
  vtkUniforms* u = actor->GetShaderProperty()->GetFragmentCustomUniforms();
  setViewLightUniforms(u, gatherViewLights(renderer));
  if (!samplers_.empty()) u->SetUniformf("mqPixelAngle", pixelAngle(renderer));
  for (auto& [name, texture] : samplers_) texture->Render(renderer);  // loads once, then activates a unit
  vtkOpenGLPolyDataMapper::RenderPiece(renderer, actor);
  for (auto& [name, texture] : samplers_) texture->PostRender(renderer);
}

void SurfaceMapper::SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* renderer, vtkActor* actor) {
  vtkOpenGLPolyDataMapper::SetMapperShaderParameters(cellBO, renderer, actor);
  for (auto& [name, texture] : samplers_)
    if (auto* gl = vtkOpenGLTexture::SafeDownCast(texture); gl && cellBO.Program->IsUniformUsed(name.c_str()))
      cellBO.Program->SetUniformi(name.c_str(), gl->GetTextureUnit());
}

void SurfaceMapper::ReleaseGraphicsResources(vtkWindow* window) {
  for (auto& [name, texture] : samplers_) texture->ReleaseGraphicsResources(window);
  vtkOpenGLPolyDataMapper::ReleaseGraphicsResources(window);
}

}  // namespace mq::render
