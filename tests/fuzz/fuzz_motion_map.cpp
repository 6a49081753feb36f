// A bone name map (lines "bvh_joint target_bone") matching a BVH skeleton
// to the built-in mannequin.
#include "core/io/bone_match.h"
#include "core/io/character_import.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  mq::fuzz::mannequin();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const mq::Character walk =
      mq::importCharacter(std::string(MANNEQUIN_SHARED_DIR) + "/assets/motion/cmu_01_01.bvh");
  const std::string path = mq::fuzz::inputFile(data, size, "map");
  mq::fuzz::expectOnlyErrors([&] { mq::matchBones(walk.skeleton, mq::fuzz::mannequin().skeleton, path); });
  return 0;
}
