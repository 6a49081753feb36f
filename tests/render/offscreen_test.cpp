// PNG files and the private X display behind offscreen rendering.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "core/util/error.h"
#include "render/image_checks.h"
#include "render/offscreen.h"
#include "render/private_display.h"
#include "render/scene_view.h"
#include "render/test_figure.h"

namespace mq {
namespace {

std::filesystem::path scratchDir() {
  const auto dir = std::filesystem::path(MANNEQUIN_BINARY_DIR) / "Testing" / "Temporary" / "offscreen_test";
  std::filesystem::create_directories(dir);
  return dir;
}

render::RgbImage gradient(int w, int h) {
  render::RgbImage image{w, h, std::vector<uint8_t>(3 * size_t(w) * h)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t* p = &image.pixels[3 * (size_t(y) * w + x)];
      p[0] = uint8_t(x * 255 / (w - 1)), p[1] = uint8_t(y * 255 / (h - 1)), p[2] = uint8_t((x * y) % 256);
    }
  return image;
}

TEST(Png, RoundTripKeepsPixelsAndRowOrder) {
  const render::RgbImage image = gradient(37, 21);
  const std::string path = (scratchDir() / "roundtrip.png").string();
  render::writePng(image, path);
  const render::RgbImage back = render::readPng(path);
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 21);
  EXPECT_EQ(back.pixels, image.pixels);
  // No temporary file is left beside it.
  for (const auto& entry : std::filesystem::directory_iterator(scratchDir()))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST(Png, ErrorsNameTheFile) {
  const std::string missingDir = (scratchDir() / "no-such-dir" / "x.png").string();
  try {
    render::writePng(gradient(4, 4), missingDir);
    FAIL() << "expected a FileError";
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), missingDir);
  }
  EXPECT_THROW(render::readPng((scratchDir() / "absent.png").string()), FileError);
}

TEST(ImageChecks, DifferenceMeasuresWhatChanged) {
  render::RgbImage a = gradient(10, 10), b = a;
  EXPECT_EQ(test::compareImages(a, b).rms, 0.0);
  for (int c = 0; c < 3; ++c) b.pixels[c] = uint8_t(a.pixels[c] ^ 0x80);  // one pixel very different
  const test::ImageDifference d = test::compareImages(a, b);
  EXPECT_NEAR(d.changedFraction, 0.01, 1e-12);
  EXPECT_GT(d.rms, 5.0);
}

// Without DISPLAY, rendering starts its own Xvfb (in a child process so this
// test's environment stays as it was).
TEST(PrivateDisplay, RendersWithoutADisplay) {
  const std::string path = (scratchDir() / "no_display.png").string();
  std::filesystem::remove(path);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    unsetenv("DISPLAY");
    int code = 1;
    try {
      test::useSoftwareRendering();
      render::SceneView view;
      view.setCharacter(test::makeTestFigure());
      view.frameAll(1.0);
      render::renderToPng(view, path, 64, 64);
      code = render::usingPrivateDisplay() ? 0 : 2;
    } catch (const std::exception&) {
      code = 3;
    }
    std::_Exit(code);  // skip static destructors shared with the parent
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(render::readPng(path).width, 64);
}

}  // namespace
}  // namespace mq
