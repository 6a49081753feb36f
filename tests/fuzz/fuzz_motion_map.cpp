// A bone name map (lines "bvh_joint target_bone") matching a BVH skeleton
// to the built-in mannequin.
#include "core/character/default_mannequin.h"
#include "core/io/bone_match.h"
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
  static const mq::Character walk = mq::importCharacter(std::string(MANNEQUIN_SHARED_DIR) + "/assets/motion/cmu_01_01.bvh");
  const std::string path = mq::fuzz::inputFile(data, size, "map");
  mq::fuzz::expectOnlyErrors([&] { mq::matchBones(walk.skeleton, mannequin().skeleton, path); });
  return 0;
}
