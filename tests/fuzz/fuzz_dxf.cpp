// A DXF sewing pattern read (dxflib, then chaining, fitting and validation),
// and what it gives written as DXF and read back.
#include <filesystem>

#include "core/garment/pattern_dxf.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  mq::fuzz::expectOnlyErrors([&] {
    const mq::Garment garment = mq::patternFromDxf(text);
    const std::string path = mq::fuzz::inputFile(nullptr, 0, "out.dxf");
    mq::writePatternDxf(path, garment);
    mq::readPatternDxf(path);
  });
  return 0;
}
