// Point caches as Blender or another tool may hand them back: the same bytes
// read as Point Cache 2 and as MDD.
#include "fuzz_input.h"
#include "sim/cloth/point_cache.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string pc2 = mq::fuzz::inputFile(data, size, "pc2");
  mq::fuzz::expectOnlyErrors([&] { mq::cloth::readPointCache(pc2); });
  const std::string mdd = mq::fuzz::inputFile(data, size, "mdd");
  mq::fuzz::expectOnlyErrors([&] { mq::cloth::readMdd(mdd); });
  return 0;
}
