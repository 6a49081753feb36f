#include "render/image_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace mq::test {
namespace {

constexpr int kVisibleLevels = 24;

int maxChannelDifference(const uint8_t* a, const uint8_t* b) {
  int d = 0;
  for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
  return d;
}

render::RgbImage differenceImage(const render::RgbImage& a, const render::RgbImage& b) {
  render::RgbImage diff = a;
  for (size_t i = 0; i < diff.pixels.size(); ++i)
    diff.pixels[i] = static_cast<uint8_t>(std::min(255, 4 * std::abs(int(a.pixels[i]) - int(b.pixels[i]))));
  return diff;
}

std::filesystem::path temporaryDir() {
  const std::filesystem::path dir = std::filesystem::path(MANNEQUIN_BINARY_DIR) / "Testing" / "Temporary";
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

ImageDifference compareImages(const render::RgbImage& a, const render::RgbImage& b) {
  ImageDifference d;
  if (a.width != b.width || a.height != b.height) return {255.0, 1.0};
  double sum = 0.0;
  size_t changed = 0;
  const size_t pixels = static_cast<size_t>(a.width) * a.height;
  for (size_t p = 0; p < pixels; ++p) {
    const uint8_t *pa = &a.pixels[3 * p], *pb = &b.pixels[3 * p];
    for (int c = 0; c < 3; ++c) sum += double(pa[c] - pb[c]) * double(pa[c] - pb[c]);
    if (maxChannelDifference(pa, pb) > kVisibleLevels) ++changed;
  }
  d.rms = std::sqrt(sum / (3.0 * static_cast<double>(pixels)));
  d.changedFraction = static_cast<double>(changed) / static_cast<double>(pixels);
  return d;
}

Foreground foregroundOf(const render::RgbImage& image, const render::RgbImage& background) {
  Foreground f;
  size_t count = 0;
  glm::dvec2 sum(0.0);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      if (maxChannelDifference(image.at(x, y), background.at(x, y)) <= kVisibleLevels) continue;
      const glm::dvec2 p((x + 0.5) / image.width, (y + 0.5) / image.height);
      ++count;
      sum += p;
      f.min = glm::min(f.min, p);
      f.max = glm::max(f.max, p);
    }
  f.fraction = static_cast<double>(count) / (static_cast<double>(image.width) * image.height);
  if (count) f.centre = sum / static_cast<double>(count);
  return f;
}

std::string checkAgainstBaseline(const render::RgbImage& image, const std::string& name,
                                 const BaselineTolerance& tolerance) {
  const std::filesystem::path baseline =
      std::filesystem::path(MANNEQUIN_SOURCE_DIR) / "tests" / "render" / "baselines" / (name + ".png");
  const std::filesystem::path actual = temporaryDir() / (name + ".png");
  if (!std::filesystem::exists(baseline)) {
    render::writePng(image, actual.string());
    return "no baseline " + baseline.string() + "; the image was written to " + actual.string() +
           ": look at it and copy it there if it is right";
  }
  const render::RgbImage expected = render::readPng(baseline.string());
  const ImageDifference d = compareImages(image, expected);
  if (d.rms <= tolerance.maxRms && d.changedFraction <= tolerance.maxChangedFraction) return "";
  render::writePng(image, actual.string());
  std::ostringstream why;
  why << "differs from " << baseline.string() << ": rms " << d.rms << " levels (max " << tolerance.maxRms << "), "
      << 100.0 * d.changedFraction << "% of pixels changed (max " << 100.0 * tolerance.maxChangedFraction
      << "%); the image is " << actual.string();
  if (expected.width == image.width && expected.height == image.height) {
    const auto diffPath = temporaryDir() / (name + ".diff.png");
    render::writePng(differenceImage(image, expected), diffPath.string());
    why << ", the difference (x4) " << diffPath.string();
  }
  return why.str();
}

void useSoftwareRendering() { setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1); }

}  // namespace mq::test
