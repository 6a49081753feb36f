// BVH as a skeleton of its own, and retargeted onto the built-in mannequin.
#include "core/io/bvh_import.h"
#include "core/io/character_import.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  mq::fuzz::mannequin();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = mq::fuzz::inputFile(data, size, "bvh");
  mq::fuzz::expectOnlyErrors([&] { mq::importCharacter(path).validate(); });
  mq::fuzz::expectOnlyErrors([&] {
    const mq::RetargetedMotion motion = mq::retargetBvhMotion(path, mq::fuzz::mannequin());
    motion.clip.validate();
  });
  return 0;
}
