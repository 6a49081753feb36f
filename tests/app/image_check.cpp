// mannequin_image_check IMAGE NAME: compares a PNG another program wrote
// (mannequin-cli render) with tests/render/baselines/NAME.png at the render
// tests' tolerance (tests/render/image_checks.h). Exit 0 when it matches;
// otherwise 1 and the reason (the image is kept under the build tree).
#include <exception>
#include <iostream>
#include <string>

#include "render/image_checks.h"
#include "render/offscreen.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: mannequin_image_check IMAGE BASELINE_NAME\n";
    return 2;
  }
  try {
    const std::string why = mq::test::checkAgainstBaseline(mq::render::readPng(argv[1]), argv[2]);
    if (!why.empty()) {
      std::cerr << argv[1] << ": " << why << "\n";
      return 1;
    }
    std::cout << argv[1] << " matches the baseline " << argv[2] << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << argv[1] << ": " << e.what() << "\n";
    return 1;
  }
}
