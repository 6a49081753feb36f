#include "render/material_textures.h"

#include <climits>
#include <cstring>
#include <memory>

#include <stb_image.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>

#include "core/io/file_bytes.h"
#include "core/util/error.h"

namespace mq::render {
namespace {

// Decodes PNG or JPEG bytes into an image whose row 0 is the bottom one (as
// VTK's images are); null with `problem` set when they do not decode.
vtkSmartPointer<vtkImageData> decode(const std::vector<uint8_t>& bytes, std::string& problem) {
  constexpr int kMaxSide = 16384;  // refuse before allocating what a hostile header claims
  const int length = static_cast<int>(std::min<size_t>(bytes.size(), INT_MAX));
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(bytes.data(), length, &width, &height, &channels)) {
    problem = std::string("could not be decoded (") + stbi_failure_reason() + ")";
    return nullptr;
  }
  if (width > kMaxSide || height > kMaxSide) {
    problem = "is " + std::to_string(width) + "x" + std::to_string(height) + " pixels, more than " +
              std::to_string(kMaxSide) + " a side";
    return nullptr;
  }
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(bytes.data(), length, &width, &height, &channels, 0), stbi_image_free);
  if (!pixels) {
    problem = std::string("could not be decoded (") + stbi_failure_reason() + ")";
    return nullptr;
  }
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, channels);
  const size_t rowBytes = size_t(width) * channels;
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int row = 0; row < height; ++row)
    std::memcpy(out + size_t(height - 1 - row) * rowBytes, pixels.get() + size_t(row) * rowBytes, rowBytes);
  return image;
}

int vtkWrap(TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::ClampToEdge:
      return vtkTexture::ClampToEdge;
    case TextureWrap::MirroredRepeat:
      return vtkTexture::MirroredRepeat;
    case TextureWrap::Repeat:
      break;
  }
  return vtkTexture::Repeat;
}

vtkSmartPointer<vtkTexture> makeTexture(vtkImageData* image, const TextureSampler& sampler, bool srgb) {
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->SetUseSRGBColorSpace(srgb);
  texture->SetInterpolate(sampler.linear);
  texture->SetMipmap(sampler.mipmaps);
  // VTK has one wrap mode for both axes: the u axis decides.
  texture->SetWrap(vtkWrap(sampler.wrapS));
  texture->SetColorModeToDirectScalars();
  return texture;
}

std::string keyOf(const TextureRef& ref, bool srgb) {
  const TextureSampler& s = ref.sampler;
  return std::to_string(ref.image) + (srgb ? "s" : "l") + std::to_string(static_cast<int>(s.wrapS)) +
         (s.linear ? "L" : "N") + (s.mipmaps ? "M" : "-");
}

// The value of component `c` of pixel `i`, or `fallback` when the image has
// fewer components (a grey map read as RGB).
unsigned char component(vtkDataArray* scalars, vtkIdType i, int c, unsigned char fallback) {
  const int n = scalars->GetNumberOfComponents();
  if (n >= 3) return static_cast<unsigned char>(scalars->GetComponent(i, c));
  return n >= 1 ? static_cast<unsigned char>(scalars->GetComponent(i, 0)) : fallback;
}

}  // namespace

MaterialTextures::MaterialTextures(const std::vector<ImageSource>& images) : images_(images) {}

vtkImageData* MaterialTextures::decoded(int index) {
  if (index < 0 || index >= static_cast<int>(images_.size())) return nullptr;
  if (auto found = decoded_.find(index); found != decoded_.end()) return found->second;
  const ImageSource& source = images_[index];
  std::string problem;
  vtkSmartPointer<vtkImageData> image;
  try {
    image = decode(source.path.empty() ? source.encoded : readFileBytes(source.path), problem);
  } catch (const FileError& e) {
    problem = e.problem();
  }
  if (!image)
    warnings_.push_back("image '" + source.name + "'" + (source.path.empty() ? "" : " (" + source.path + ")") + " " +
                        problem + "; its material uses its factors instead");
  decoded_[index] = image;
  return image;
}

vtkTexture* MaterialTextures::texture(const TextureRef& ref, bool srgb) {
  if (!ref.present()) return nullptr;
  vtkImageData* image = decoded(ref.image);
  if (!image) return nullptr;
  const std::string key = keyOf(ref, srgb);
  if (auto found = textures_.find(key); found != textures_.end()) return found->second;
  return textures_[key] = makeTexture(image, ref.sampler, srgb);
}

vtkTexture* MaterialTextures::colour(const TextureRef& ref) { return texture(ref, true); }
vtkTexture* MaterialTextures::data(const TextureRef& ref) { return texture(ref, false); }

vtkTexture* MaterialTextures::occlusionRoughnessMetallic(const Material& material, bool& withOcclusion) {
  const TextureRef& mr = material.metallicRoughnessTexture;
  const TextureRef& ao = material.occlusionTexture;
  vtkImageData* mrImage = mr.present() ? decoded(mr.image) : nullptr;
  vtkImageData* aoImage = ao.present() ? decoded(ao.image) : nullptr;
  withOcclusion = false;
  if (!mrImage && !aoImage) return nullptr;
  if (mrImage && (!aoImage || ao.image == mr.image)) {  // packed already, or no occlusion
    withOcclusion = aoImage != nullptr;
    return data(mr);
  }
  const TextureRef& base = mrImage ? mr : ao;
  vtkImageData* shape = mrImage ? mrImage : aoImage;
  int dims[3];
  shape->GetDimensions(dims);
  int aoDims[3] = {0, 0, 0};
  if (aoImage) aoImage->GetDimensions(aoDims);
  withOcclusion = aoImage && aoDims[0] == dims[0] && aoDims[1] == dims[1];
  const std::string key = "orm" + std::to_string(mr.image) + "_" + std::to_string(ao.image);
  if (auto found = textures_.find(key); found != textures_.end()) return found->second;

  vtkNew<vtkImageData> packed;
  packed->SetDimensions(dims[0], dims[1], 1);
  packed->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(packed->GetScalarPointer());
  vtkDataArray* mrScalars = mrImage ? mrImage->GetPointData()->GetScalars() : nullptr;
  vtkDataArray* aoScalars = withOcclusion ? aoImage->GetPointData()->GetScalars() : nullptr;
  for (vtkIdType i = 0; i < vtkIdType(dims[0]) * dims[1]; ++i) {
    out[3 * i] = aoScalars ? component(aoScalars, i, 0, 255) : 255;
    out[3 * i + 1] = mrScalars ? component(mrScalars, i, 1, 255) : 255;  // factors scale these
    out[3 * i + 2] = mrScalars ? component(mrScalars, i, 2, 255) : 255;
  }
  return textures_[key] = makeTexture(packed, base.sampler, false);
}

}  // namespace mq::render
