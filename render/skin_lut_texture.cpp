#include "render/skin_lut_texture.h"

#include <algorithm>
#include <map>

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include "core/optics/skin_tone.h"

namespace mq::render {

const optics::PreintegratedLutSettings& skinLutSettings() {
  static const optics::PreintegratedLutSettings settings;
  return settings;
}

vtkTexture* preintegratedSkinTexture(const std::string& key, const optics::SkinOptics& skin) {
  // Never destroyed: textures outlive the last render window at exit.
  static auto* cache = new std::map<std::string, vtkSmartPointer<vtkTexture>>;
  if (auto found = cache->find(key); found != cache->end()) return found->second;
  const optics::PreintegratedLut lut = optics::buildPreintegratedLut(optics::skinKernels(skin), skinLutSettings());
  vtkNew<vtkFloatArray> texels;
  texels->SetNumberOfComponents(3);
  texels->SetNumberOfTuples(vtkIdType(lut.width) * lut.height);
  std::copy(lut.rgb.begin(), lut.rgb.end(), texels->GetPointer(0));  // row 0 (flat skin) at v = 0
  vtkNew<vtkImageData> image;
  image->SetDimensions(lut.width, lut.height, 1);
  image->GetPointData()->SetScalars(texels);
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->SetColorModeToDirectScalars();  // floats as they are, not through a colour map
  texture->InterpolateOn();
  texture->MipmapOff();
  texture->RepeatOff();
  texture->EdgeClampOn();
  (*cache)[key] = texture;
  return texture;
}

}  // namespace mq::render
