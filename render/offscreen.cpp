#include "render/offscreen.h"

#include <unistd.h>

#include <cstring>
#include <filesystem>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include "core/util/error.h"
#include "render/private_display.h"
#include "render/scene_view.h"

namespace mq::render {
namespace {

// vtkImageData (rows bottom to top, 3 or 4 components) -> RgbImage.
RgbImage toRgbImage(vtkImageData* data) {
  RgbImage image;
  int dims[3];
  data->GetDimensions(dims);
  image.width = dims[0];
  image.height = dims[1];
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(data->GetPointData()->GetScalars());
  if (!scalars) return image;
  const int components = scalars->GetNumberOfComponents();
  image.pixels.resize(3 * static_cast<size_t>(image.width) * image.height);
  const uint8_t* source = scalars->GetPointer(0);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* s = source + components * (static_cast<size_t>(y) * image.width + x);
      uint8_t* d = &image.pixels[3 * (static_cast<size_t>(image.height - 1 - y) * image.width + x)];
      for (int c = 0; c < 3; ++c) d[c] = components >= 3 ? s[c] : s[0];
    }
  return image;
}

vtkSmartPointer<vtkImageData> toImageData(const RgbImage& image) {
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(image.width, image.height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* target = static_cast<uint8_t*>(data->GetScalarPointer());
  const size_t row = 3 * static_cast<size_t>(image.width);
  for (int y = 0; y < image.height; ++y)
    std::memcpy(target + (image.height - 1 - y) * row, &image.pixels[y * row], row);
  return data;
}

void writeImageDataAtomically(vtkImageData* data, const std::string& path) {
  const std::filesystem::path target(path);
  const std::filesystem::path directory = target.has_parent_path() ? target.parent_path() : ".";
  if (!std::filesystem::is_directory(directory)) throw FileError(path, "the folder does not exist");
  const std::string temporary = path + ".tmp" + std::to_string(getpid());
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(temporary.c_str());
  writer->SetInputData(data);
  writer->Write();
  std::error_code error;
  if (writer->GetErrorCode() != 0 || !std::filesystem::exists(temporary)) {
    std::filesystem::remove(temporary, error);
    throw FileError(path, "cannot write the PNG");
  }
  std::filesystem::rename(temporary, target, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw FileError(path, "cannot replace the file: " + error.message());
  }
}

}  // namespace

struct OffscreenRenderer::Impl {
  vtkRenderer* renderer = nullptr;
  vtkSmartPointer<vtkRenderWindow> window;

  vtkSmartPointer<vtkImageData> grab() {
    window->Render();
    vtkNew<vtkWindowToImageFilter> grabber;
    grabber->SetInput(window);
    grabber->SetInputBufferTypeToRGB();
    grabber->ReadFrontBufferOff();
    grabber->ShouldRerenderOff();
    grabber->Update();
    auto copy = vtkSmartPointer<vtkImageData>::New();
    copy->DeepCopy(grabber->GetOutput());
    return copy;
  }
};

OffscreenRenderer::OffscreenRenderer(SceneView& view, int width, int height) : impl_(std::make_unique<Impl>()) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) + " is out of range");
  impl_->renderer = view.renderer();
  if (impl_->renderer->GetRenderWindow()) throw Error("the scene view is already shown in a window; render it there");
  ensureDisplay();
  // Multisampling varies between drivers; without it images are reproducible.
  // The global is read when a window is made: restore it for the editor's windows.
  const int previousSamples = vtkOpenGLRenderWindow::GetGlobalMaximumNumberOfMultiSamples();
  vtkOpenGLRenderWindow::SetGlobalMaximumNumberOfMultiSamples(0);
  impl_->window = vtkSmartPointer<vtkRenderWindow>::New();
  vtkOpenGLRenderWindow::SetGlobalMaximumNumberOfMultiSamples(previousSamples);
  impl_->window->SetMultiSamples(0);
  impl_->window->SetOffScreenRendering(1);
  impl_->window->SetSize(width, height);
  impl_->window->AddRenderer(impl_->renderer);
}

OffscreenRenderer::~OffscreenRenderer() {
  impl_->window->RemoveRenderer(impl_->renderer);  // releases the view's GL resources
  impl_->window->Finalize();
}

int OffscreenRenderer::width() const { return impl_->window->GetSize()[0]; }
int OffscreenRenderer::height() const { return impl_->window->GetSize()[1]; }

RgbImage OffscreenRenderer::capture() { return toRgbImage(impl_->grab()); }

void OffscreenRenderer::writePng(const std::string& path) { writeImageDataAtomically(impl_->grab(), path); }

void renderToPng(SceneView& view, const std::string& path, int width, int height) {
  OffscreenRenderer(view, width, height).writePng(path);
}

void writePng(const RgbImage& image, const std::string& path) { writeImageDataAtomically(toImageData(image), path); }

RgbImage readPng(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw FileError(path, "no such file");
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str())) throw FileError(path, "not a PNG file");
  reader->SetFileName(path.c_str());
  reader->Update();
  if (reader->GetErrorCode() != 0) throw FileError(path, "cannot read the PNG");
  return toRgbImage(reader->GetOutput());
}

}  // namespace mq::render
