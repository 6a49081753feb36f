// BVH as a skeleton of its own, and retargeted onto the built-in mannequin.
#include "core/character/default_mannequin.h"
#include "core/io/bvh_import.h"
#include "core/io/character_import.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const mq::Character mannequin = mq::makeDefaultMannequin();
  const std::string path = mq::fuzz::inputFile(data, size, "bvh");
  mq::fuzz::expectOnlyErrors([&] { mq::importCharacter(path).validate(); });
  mq::fuzz::expectOnlyErrors([&] {
    const mq::RetargetedMotion motion = mq::retargetBvhMotion(path, mannequin);
    motion.clip.validate();
  });
  return 0;
}
