// BVH as a skeleton of its own, and retargeted onto the built-in mannequin.
#include "core/character/default_mannequin.h"
#include "core/io/bvh_import.h"
#include "core/io/character_import.h"
#include "fuzz_input.h"

namespace {

// Built once before fuzzing starts (it takes seconds under ASan, longer than
// libFuzzer's time limit for one input).
const mq::Character& mannequin() {
  static const mq::Character character = mq::makeDefaultMannequin();
  return character;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  mannequin();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = mq::fuzz::inputFile(data, size, "bvh");
  mq::fuzz::expectOnlyErrors([&] { mq::importCharacter(path).validate(); });
  mq::fuzz::expectOnlyErrors([&] {
    const mq::RetargetedMotion motion = mq::retargetBvhMotion(path, mannequin());
    motion.clip.validate();
  });
  return 0;
}
