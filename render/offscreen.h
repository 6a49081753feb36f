#pragma once
// Images of a SceneView without a window on screen. Deterministic: no MSAA,
// a fixed size; under Xvfb (software Mesa) the same scene gives the same bytes.
// Needs an X server: a private Xvfb is started when none answers
// (render/private_display.h).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mq::render {

class SceneView;

// 8-bit RGB pixels, rows top to bottom.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> pixels;  // 3 per pixel
  const uint8_t* at(int x, int y) const { return &pixels[3 * (static_cast<size_t>(y) * width + x)]; }
};

// An offscreen render window showing `view`'s renderer for as long as it lives.
// The view must not be shown in another window meanwhile.
class OffscreenRenderer {
 public:
  OffscreenRenderer(SceneView& view, int width, int height);
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  int width() const;
  int height() const;
  // Renders the view and returns its pixels.
  RgbImage capture();
  // Renders the view and writes a PNG atomically (a temporary file renamed
  // into place); throws mq::FileError when it cannot be written.
  void writePng(const std::string& path);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One image of `view` as it stands (camera included) to `path`.
void renderToPng(SceneView& view, const std::string& path, int width, int height);

// Writes `image` as a PNG atomically; throws mq::FileError.
void writePng(const RgbImage& image, const std::string& path);
// Reads an 8-bit PNG (alpha dropped); throws mq::FileError.
RgbImage readPng(const std::string& path);

}  // namespace mq::render
