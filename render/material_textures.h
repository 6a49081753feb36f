#pragma once
// The VTK textures of a character's materials, each image decoded once
// (PNG or JPEG, by stb_image). A missing or unreadable image is a warning
// naming it; its slot then has no texture and the material keeps its factors.

#include <map>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "core/material/material.h"

class vtkImageData;
class vtkTexture;

namespace mq::render {

class MaterialTextures {
 public:
  explicit MaterialTextures(const std::vector<ImageSource>& images);

  // The texture of `ref` (sRGB for colour maps, linear for data maps), or
  // null when the reference is empty or its image did not decode.
  vtkTexture* colour(const TextureRef& ref);
  vtkTexture* data(const TextureRef& ref);
  // VTK's packed occlusion-roughness-metallic map for a glTF material (its
  // metallic-roughness map holds roughness in G and metallic in B; occlusion
  // comes in R from its own map when the sizes agree). Null without either
  // map; `withOcclusion` says whether R holds the material's occlusion.
  vtkTexture* occlusionRoughnessMetallic(const Material& material, bool& withOcclusion);

  // One line per image that could not be used, naming it and the problem.
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  vtkImageData* decoded(int image);
  vtkTexture* texture(const TextureRef& ref, bool srgb);

  const std::vector<ImageSource>& images_;
  std::map<int, vtkSmartPointer<vtkImageData>> decoded_;  // null: failed
  std::map<std::string, vtkSmartPointer<vtkTexture>> textures_;
  std::vector<std::string> warnings_;
};

}  // namespace mq::render
